#include "app/cli/program_pipelines.h"

namespace sightline::cli {

PipelineRegistry ProgramPipelines() { return StereoPipelines(); }

SourceOpener ProgramSourceOpener(const std::string& path, const std::atomic<bool>* cancel) {
  return {};
}

}  // namespace sightline::cli
