// sightline-cli floor: calibrates the floor plane for indoor mapping from the first
// frames of an RGB-D dataset or recording, or from PCD clouds, and writes the calibration file
// that `run mapping --set mapping.run.floor_file=FILE` and the GUI read.
#include <cstdio>
#include <cstdlib>

#include "app/cli/cli_args.h"
#include "app/cli/commands.h"
#include "core/io/floor_file.h"
#include "core/options/option_set.h"
#include "core/pipeline/floor_calibration.h"

namespace sightline::cli {

namespace {

const char kHelp[] =
    "usage: sightline-cli floor PATH --out FILE [--frames N] [--set mapping.floor.KEY=VALUE]...\n"
    "\n"
    "Fits the floor plane a x + b y + c z + d = 0 in the camera frame (RANSAC, least-squares\n"
    "refit) to the first N frames (default 5) of the RGB-D dataset or recording at PATH, or to\n"
    "the clouds of a .pcd file or folder, and writes it with epsilon_floor and the camera height\n"
    "to FILE (YAML). Use it for mapping with --set mapping.run.floor_file=FILE.\n"
    "\n"
    "  --frames N      frames to use (default 5)\n"
    "  --set K=V       any mapping.floor.* option, e.g. mapping.floor.epsilon_m=0.05\n";

}  // namespace

int FloorCommand(const std::vector<std::string>& args) {
  StatusOr<CliArgs> parsed = CliArgs::Parse(args, {"--out", "--frames", "--set"}, {"--help"});
  if (!parsed.ok()) return Fail("floor: " + parsed.status().message());
  if (parsed->Has("--help")) {
    std::fputs(kHelp, stdout);
    return 0;
  }
  if (parsed->positionals().size() != 1) return Fail("floor: expected one PATH (see --help)");
  if (!parsed->Value("--out")) return Fail("floor: --out FILE is required");
  int frames = 5;
  if (auto text = parsed->Value("--frames")) {
    char* end = nullptr;
    const long value = std::strtol(text->c_str(), &end, 10);
    if (end == text->c_str() || *end != '\0' || value < 1 || value > 10000) {
      return Fail("floor: --frames must be a whole number in [1, 10000], got '" + *text + "'");
    }
    frames = static_cast<int>(value);
  }
  OptionSet options;
  Status declared = options.Declare(FloorPlaneOptions::Describe());
  if (!declared.ok()) return Fail("floor: " + declared.ToString());
  for (const std::string& assignment : parsed->Values("--set")) {
    Status s = options.ApplyOverride(assignment);
    if (!s.ok()) return Fail("floor: " + s.ToString());
  }
  const FloorPlaneOptions floor_options = options.Extract(FloorPlaneOptions::Describe());
  const std::string path = parsed->positionals()[0];
  int used = 0;
  StatusOr<FloorFitResult> fit = CalibrateFloorFromDataset(path, frames, floor_options, &used);
  if (!fit.ok()) return Fail("floor: " + fit.status().ToString());
  FloorCalibration calibration;
  calibration.plane = fit->plane;
  calibration.inlier_ratio = fit->inlier_ratio;
  calibration.frames = used;
  calibration.source = path;
  const std::string out = *parsed->Value("--out");
  Status written = WriteFloorCalibration(calibration, out);
  if (!written.ok()) return Fail("floor: " + written.ToString());
  const Eigen::Vector3d& n = fit->plane.normal;
  std::printf("floor of %s (%d frames): %.5f x %+.5f y %+.5f z %+.5f = 0\n", path.c_str(), used,
              n.x(), n.y(), n.z(), fit->plane.d);
  std::printf(
      "camera %.3f m above the floor, pitched %.1f deg down; %.1f %% of %d points within "
      "%.3f m (rms %.4f m)\n",
      fit->plane.CameraHeightM(), fit->plane.PitchDownDeg(), 100 * fit->inlier_ratio, fit->points,
      floor_options.fit_threshold_m, fit->rms_m);
  std::printf("wrote %s\n", out.c_str());
  return 0;
}

}  // namespace sightline::cli
