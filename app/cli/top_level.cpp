#include "app/cli/top_level.h"

#include <cstdio>
#include <cstring>

#include "sightline_version.h"

namespace sightline::cli {

const char kUsage[] =
    "usage: sightline-cli COMMAND [ARGS...]\n"
    "\n"
    "Commands:\n"
    "  info PATH [--json]         describe a dataset or recording (format, frames, calibration)\n"
    "  run PIPELINE PATH --out DIR [--profile F] [--set key=value]...\n"
    "                             run a pipeline headless; writes DIR/metrics.json\n"
    "  options [PIPELINE] [--yaml]\n"
    "                             list the pipelines, or the options of one with their ranges\n"
    "  eval EST GT [--align se3|sim3|none] [--json] [--plot DIR]\n"
    "                             accuracy of a trajectory against ground truth (ATE, RPE, KITTI)\n"
    "  simulate SCENE --out DIR [--frames N] [--seed S] [--noise PROFILE]\n"
    "                             write a simulated recording (corridor, terrain, panel)\n"
    "  sweep stereo-vo PATH --subsample A..B [--out DIR]\n"
    "                             path-length error per subsampling factor (table + plot)\n"
    "  floor PATH --out FILE [--frames N]\n"
    "                             calibrate the floor plane for indoor mapping\n"
    "  calibrate mono|stereo|handeye|floor ... --out FILE\n"
    "                             chessboard calibration of a camera, a stereo rig, an arm camera\n"
    "  arm-listen HOST:PORT [--token T]\n"
    "                             print the arm targets Sightline serves (JSON lines)\n"
    "  arm-sim HOST:PORT [--token T] [--seed N]\n"
    "                             a simulated arm that presses the button Sightline targets\n"
    "  record SOURCE --out DIR [--seconds S] [--frames N]\n"
    "                             record a sensor or replayed recording (TUM, EuRoC, images)\n"
    "  train-button-classifier LABELS.csv PHOTO_DIR --out FILE\n"
    "                             train the button-or-label model on labelled panel photos\n"
    "\n"
    "Run 'sightline-cli COMMAND --help' for a command's details;\n"
    "'sightline-cli --version' prints the version and the git commit it was built from.\n";

std::optional<int> RunTopLevel(int argc, char** argv) {
  if (argc < 2 || std::strcmp(argv[1], "--help") == 0 || std::strcmp(argv[1], "-h") == 0) {
    std::fputs(kUsage, argc < 2 ? stderr : stdout);
    return argc < 2 ? 2 : 0;
  }
  if (std::strcmp(argv[1], "--version") == 0 || std::strcmp(argv[1], "-v") == 0) {
    std::printf("sightline-cli %s (commit %s)\n", SIGHTLINE_VERSION, SIGHTLINE_GIT_COMMIT);
    return 0;
  }
  return std::nullopt;
}

}  // namespace sightline::cli
