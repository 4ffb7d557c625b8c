#include "app/cli/program_pipelines.h"
#include "core/pipeline/stereo_vo_pipeline.h"

namespace sightline::cli {

PipelineRegistry ProgramPipelines() {
  PipelineRegistry registry;
  (void)registry.Register(StereoVoPipelineInfo());  // The only name: it cannot clash.
  return registry;
}

}  // namespace sightline::cli
