#include "core/pipeline/pipeline_registry.h"
#include "core/pipeline/stereo_vo_pipeline.h"

namespace sightline {

PipelineRegistry StereoPipelines() {
  PipelineRegistry registry;
  (void)registry.Register(StereoVoPipelineInfo());  // The only name: it cannot clash.
  return registry;
}

}  // namespace sightline
