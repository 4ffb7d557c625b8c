#include "core/pipeline/button_pipeline.h"
#include "core/pipeline/inspect_pipeline.h"
#include "core/pipeline/mapping_pipeline.h"
#include "core/pipeline/mobility_pipeline.h"
#include "core/pipeline/mono_slam_pipeline.h"
#include "core/pipeline/pipeline_registry.h"
#include "core/pipeline/stereo_vo_pipeline.h"

namespace sightline {

PipelineRegistry BuiltinPipelines() {
  PipelineRegistry registry;
  Status s = registry.Register(InspectPipelineInfo());
  s = registry.Register(MappingPipelineInfo());
  s = registry.Register(StereoVoPipelineInfo());
  s = registry.Register(MobilityPipelineInfo());
  s = registry.Register(MonoSlamPipelineInfo());
  s = registry.Register(ButtonPipelineInfo());
  (void)s;  // Built-in names are distinct; a clash is a programming error caught by tests.
  return registry;
}

}  // namespace sightline
