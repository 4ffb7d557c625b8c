#include "app/cli/stereo_program.h"

#include <cctype>
#include <optional>

#include "app/cli/cli_args.h"
#include "app/cli/full_program.h"
#include "core/io/dataset.h"

namespace sightline::cli {
namespace {

bool EndsWithNoCase(const std::string& text, const std::string& suffix) {
  if (text.size() < suffix.size()) return false;
  for (size_t i = 0; i < suffix.size(); ++i) {
    const char c = text[text.size() - suffix.size() + i];
    if (std::tolower(static_cast<unsigned char>(c)) != suffix[i]) return false;
  }
  return true;
}

// Whether core/io's readers open `path` as stereo, as RunHeadless opens it for stereo-vo
// (OpenDataset(path, SourceKind::kStereo)): the dataset itself, or a recording's stereo sensor.
bool IsRecordedStereo(const std::string& path) {
  if (path.find("://") != std::string::npos || EndsWithNoCase(path, ".bag") ||
      EndsWithNoCase(path, ".oni")) {
    return false;
  }
  if (std::optional<DetectedDataset> dataset = DetectDataset(path)) {
    return dataset->kind == SourceKind::kStereo;
  }
  for (const DetectedDataset& sensor : FindRecordingSensors(path)) {
    if (sensor.kind == SourceKind::kStereo) return true;
  }
  return false;
}

}  // namespace

const std::vector<std::string>& RunValueFlags() {
  static const std::vector<std::string> flags = {"--out",    "--profile", "--set",  "--subsample",
                                                 "--format", "--tap",     "--serve"};
  return flags;
}

const std::vector<std::string>& RunSwitches() {
  static const std::vector<std::string> flags = {"--help", "--quiet"};
  return flags;
}

bool RunsInStereoProgram(const std::vector<std::string>& run_args) {
  StatusOr<CliArgs> parsed = CliArgs::Parse(run_args, RunValueFlags(), RunSwitches());
  if (!parsed.ok() || parsed->Has("--help") || parsed->positionals().size() != 2) return false;
  if (parsed->positionals()[0] != "stereo-vo") return false;
  return IsRecordedStereo(parsed->positionals()[1]);
}

int HandOverToStereoProgram(char** argv) {
  HandOverToProgram("sightline-cli-stereo", argv);  // Returns only when it is not there.
  return HandOverToFullProgram(argv);
}

}  // namespace sightline::cli
