#include <cstdio>

#include "app/cli/cli_args.h"
#include "app/cli/commands.h"
#include "core/io/dataset.h"
#include "core/sensors/driver_registry.h"

namespace sightline::cli {

int Fail(const std::string& message) {
  std::fprintf(stderr, "sightline-cli: %s\n", message.c_str());
  return 1;
}

int InfoCommand(const std::vector<std::string>& args) {
  static const char kHelp[] =
      "usage: sightline-cli info PATH [--json]\n"
      "\n"
      "Detects the format of PATH (TUM RGB-D, EuRoC MAV, KITTI odometry, image folder, PCD file\n"
      "or folder, an OpenNI2 .oni file, a recording with one sub-folder per sensor, or a sensor\n"
      "URI: openni2://, aravis://ID, v4l2://0) and prints its frames,\n"
      "resolution, calibration, ground truth and duration. --json prints the same as JSON.\n";
  StatusOr<CliArgs> parsed = CliArgs::Parse(args, {}, {"--json", "--help"});
  if (!parsed.ok()) return Fail("info: " + parsed.status().message());
  if (parsed->Has("--help")) {
    std::fputs(kHelp, stdout);
    return 0;
  }
  if (parsed->positionals().size() != 1) return Fail("info: expected one PATH (see --help)");
  StatusOr<std::unique_ptr<Source>> source = OpenSource(parsed->positionals()[0]);
  if (!source.ok()) return Fail(source.status().ToString());
  const std::string text =
      parsed->Has("--json") ? DescribeSourceJson(**source) : DescribeSourceText(**source);
  std::fputs(text.c_str(), stdout);
  if (!text.empty() && text.back() != '\n') std::fputc('\n', stdout);
  return 0;
}

}  // namespace sightline::cli
