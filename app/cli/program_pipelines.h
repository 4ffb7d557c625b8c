// The pipelines of the program a command runs in: sightline-cli-full has every pipeline
// (program_pipelines_full.cpp: BuiltinPipelines()), sightline-cli-stereo only stereo-vo
// (program_pipelines_stereo.cpp). command_run.cpp and command_options.cpp take them from here.
#pragma once

#include "core/pipeline/pipeline_registry.h"

namespace sightline::cli {

PipelineRegistry ProgramPipelines();

}  // namespace sightline::cli
