#include "app/cli/program_pipelines.h"

namespace sightline::cli {

PipelineRegistry ProgramPipelines() { return BuiltinPipelines(); }

}  // namespace sightline::cli
