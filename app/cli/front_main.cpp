// sightline-cli: the front binary. It answers --help, --version and `info` of recorded datasets
// (TUM RGB-D, EuRoC, KITTI, image folders, recordings of them) with only core/io's readers
// linked, so these start in a few milliseconds. `run stereo-vo` on a recorded stereo dataset is
// handed with execv to sightline-cli-stereo (stereo_main.cpp: the stereo pipeline and the
// readers), every other command line to sightline-cli-full (main.cpp), which links every module
// (PCL, ROS, the sensor drivers).
#include <cctype>
#include <cstring>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "app/cli/cli_args.h"
#include "app/cli/commands.h"
#include "app/cli/full_program.h"
#include "app/cli/info_output.h"
#include "app/cli/stereo_program.h"
#include "app/cli/top_level.h"
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

// True when `info` of `args` describes a recorded dataset this binary reads: one PATH, no --set
// or --help, no sensor URI (scheme://), .bag or .oni, and a dataset, or a recording with a
// sensor, other than PCD clouds (OpenDataset prefers RGB-D, stereo and mono to clouds). All
// else, errors included, is answered by the full program, so the messages are its own.
bool InfoReadsHere(const CliArgs& args) {
  if (args.Has("--help") || args.Has("--set") || args.positionals().size() != 1) return false;
  const std::string& path = args.positionals()[0];
  if (path.find("://") != std::string::npos || EndsWithNoCase(path, ".bag") ||
      EndsWithNoCase(path, ".oni")) {
    return false;
  }
  if (std::optional<DetectedDataset> dataset = DetectDataset(path)) {
    return dataset->format != DatasetFormat::kPcd;
  }
  for (const DetectedDataset& sensor : FindRecordingSensors(path)) {
    if (sensor.format != DatasetFormat::kPcd) return true;
  }
  return false;
}

}  // namespace
}  // namespace sightline::cli

int main(int argc, char** argv) {
  using namespace sightline;
  using namespace sightline::cli;
  if (std::optional<int> code = RunTopLevel(argc, argv)) return *code;
  if (std::strcmp(argv[1], "info") == 0) {
    // The same flags as InfoCommand (command_info.cpp).
    const std::vector<std::string> args(argv + 2, argv + argc);
    StatusOr<CliArgs> parsed = CliArgs::Parse(args, {"--set"}, {"--json", "--help"});
    if (parsed.ok() && InfoReadsHere(*parsed)) {
      StatusOr<std::unique_ptr<Source>> source = OpenDataset(parsed->positionals()[0]);
      if (!source.ok()) return Fail(source.status().ToString());
      return PrintSourceInfo(**source, parsed->Has("--json"));
    }
  }
  if (std::strcmp(argv[1], "run") == 0 &&
      RunsInStereoProgram(std::vector<std::string>(argv + 2, argv + argc))) {
    return HandOverToStereoProgram(argv);
  }
  return HandOverToFullProgram(argv);
}
