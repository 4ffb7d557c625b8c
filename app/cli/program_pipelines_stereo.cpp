#include "app/cli/program_pipelines.h"

namespace sightline::cli {

PipelineRegistry ProgramPipelines() { return StereoPipelines(); }

}  // namespace sightline::cli
