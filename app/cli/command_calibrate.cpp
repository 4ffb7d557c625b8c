// sightline-cli calibrate: chessboard calibration of one camera or a stereo rig from an image
// folder or a live camera, hand-eye calibration of an arm camera, and (as an alias of
// `sightline-cli floor`) the floor plane of the depth camera.
#include <cstdio>
#include <cstdlib>
#include <filesystem>

#include "app/cli/cli_args.h"
#include "app/cli/commands.h"
#include "core/calib/calibration_file.h"
#include "core/calib/calibration_job.h"
#include "core/calib/calibration_report.h"
#include "core/common/trajectory.h"
#include "core/io/camera_yaml.h"
#include "core/sensors/driver_registry.h"

namespace sightline::cli {
namespace {

const char kHelp[] =
    "usage: sightline-cli calibrate mono DIR_OR_SOURCE --out FILE.yaml [--images PATTERN]\n"
    "       sightline-cli calibrate stereo DIR | LEFT_DIR RIGHT_DIR --out FILE.yaml\n"
    "       sightline-cli calibrate handeye POSES VIEWS --out FILE.yaml [--camera FILE]\n"
    "       sightline-cli calibrate floor PATH --out FILE   (same as 'sightline-cli floor')\n"
    "\n"
    "Chessboard calibration with OpenCV. Prints the per-view reprojection errors, the RMS, the\n"
    "coverage of the image by the views (with hints) and, for stereo, the baseline.\n"
    "\n"
    "  mono     DIR: the images of DIR matching --images (default '*'); a recording or a live\n"
    "           camera URI (v4l2://0, aravis://ID): its frames, keeping views that differ.\n"
    "           Writes a camera.yaml that the dataset readers accept.\n"
    "  stereo   DIR with left/ and right/ (or image_0/ image_1/, cam0/ cam1/) or files named\n"
    "           left*/right*; or two folders; or a stereo recording or camera. Writes OpenCV's\n"
    "           stereo file (M1 D1 M2 D2 R T E F R1 R2 P1 P2 Q) and FILE_left.yaml, "
    "FILE_right.yaml.\n"
    "  handeye  POSES: TUM file of base_from_end_effector (the simulator's arm_poses.txt);\n"
    "           VIEWS: image folder with times.txt and camera.yaml (or --camera FILE). Views are\n"
    "           paired with poses by timestamp. Writes end_effector_from_camera.\n"
    "\n"
    "  --board CxR       inner corners, e.g. 9x6 (default)\n"
    "  --square M        square size in metres (default 0.025)\n"
    "  --images PATTERN  file name pattern inside DIR (mono), e.g. 'left*.jpg'\n"
    "  --method NAME     hand-eye solver: tsai park horaud andreff daniilidis\n"
    "  --frames N        frames to examine from a recording or camera (default 2000)\n"
    "  --set K=V         any calib.* option (sightline-cli calibrate --options lists them)\n";

struct Context {
  CalibrationSettings settings;
  std::string out;
  int frames = 2000;
};

// Mono and stereo: folders, recordings and cameras through RunCalibration (as the GUI does).
int MonoOrStereo(bool stereo, const std::vector<std::string>& in, const std::string& pattern,
                 const Context& c) {
  const char* what = stereo ? "calibrate stereo: " : "calibrate mono: ";
  CalibrationRequest request;
  request.stereo = stereo;
  request.pattern = pattern;
  request.settings = c.settings;
  request.max_frames = c.frames;
  if (stereo && in.size() == 2) {
    // Two folders: pair their images by position.
    auto left = ListCalibrationImages(in[0]);
    if (!left.ok()) return Fail(what + left.status().ToString());
    auto right = ListCalibrationImages(in[1]);
    if (!right.ok()) return Fail(what + right.status().ToString());
    auto files = PairImageLists(*left, *right);
    if (!files.ok()) return Fail(what + files.status().ToString());
    request.input = in[0] + " + " + in[1];
    request.files = std::move(*files);
  } else if (in.size() == 1) {
    request.input = in[0];
  } else {
    return Fail(std::string(what) + "expected " +
                (stereo ? "DIR or LEFT_DIR RIGHT_DIR" : "one DIR_OR_SOURCE") + " (see --help)");
  }
  const SourceOpener open = [](const std::string& uri) {
    std::fprintf(stderr, "reading frames of %s\n", uri.c_str());
    return OpenSource(uri);
  };
  auto outcome = RunCalibration(request, open);
  if (!outcome.ok()) return Fail(what + outcome.status().ToString());
  std::fputs(outcome->report.c_str(), stdout);
  Status written = SaveCalibration(*outcome, c.out);
  if (!written.ok()) return Fail(what + written.ToString());
  if (stereo) {
    std::printf("wrote %s, %s, %s\n", c.out.c_str(), StereoCameraFilePath(c.out, "left").c_str(),
                StereoCameraFilePath(c.out, "right").c_str());
  } else {
    std::printf("wrote %s\n", c.out.c_str());
  }
  return 0;
}

int HandEye(const std::vector<std::string>& in, const std::optional<std::string>& camera_file,
            const Context& c) {
  if (in.size() != 2) return Fail("calibrate handeye: expected POSES VIEWS (see --help)");
  auto poses = ReadTumTrajectory(in[0]);
  if (!poses.ok()) return Fail("calibrate handeye: " + poses.status().ToString());
  auto source = OpenSource(in[1]);
  if (!source.ok()) return Fail("calibrate handeye: " + source.status().ToString());
  std::optional<PinholeCamera> camera = (*source)->info().camera;
  if (camera_file) {
    auto file = ReadCameraYaml(*camera_file);
    if (!file.ok()) return Fail("calibrate handeye: " + file.status().ToString());
    camera = file->camera;
  }
  if (!camera) {
    return Fail("calibrate handeye: " + in[1] +
                " has no camera intrinsics: add camera.yaml or pass --camera FILE");
  }
  SourceDetectionOptions options;
  options.max_frames = c.frames;
  options.max_views = c.frames;
  auto detections = DetectBoardsInSource(source->get(), c.settings.board, options);
  if (!detections.ok()) return Fail("calibrate handeye: " + detections.status().ToString());
  std::vector<int> kept;
  const std::vector<Eigen::Isometry3d> arm =
      ArmPosesForViews(*poses, detections->views, c.settings.hand_eye.max_time_offset_s, &kept);
  std::vector<BoardView> views;
  views.reserve(kept.size());
  for (int i : kept) views.push_back(detections->views[i]);
  std::printf("board found in %zu of %d views, %zu paired with an arm pose within %.3f s\n",
              detections->views.size(), detections->inputs, views.size(),
              c.settings.hand_eye.max_time_offset_s);
  std::vector<double> rms;
  auto boards = BoardPoses(views, *camera, c.settings.board, &rms);
  if (!boards.ok()) return Fail("calibrate handeye: " + boards.status().ToString());
  std::printf("per-view RMS reprojection error of the board pose (px):\n");
  for (size_t i = 0; i < views.size(); ++i) {
    std::printf("  %-24s %.4f\n", views[i].name.c_str(), rms[i]);
  }
  auto result = CalibrateHandEye(arm, *boards, c.settings.hand_eye);
  if (!result.ok()) return Fail("calibrate handeye: " + result.status().ToString());
  std::fputs(HandEyeReport(*result).c_str(), stdout);
  Status written = SaveHandEyeCalibration(*result, c.out);
  if (!written.ok()) return Fail("calibrate handeye: " + written.ToString());
  std::printf("wrote %s\n", c.out.c_str());
  return 0;
}

}  // namespace

int CalibrateCommand(const std::vector<std::string>& args) {
  if (!args.empty() && args[0] == "floor") {
    return FloorCommand(std::vector<std::string>(args.begin() + 1, args.end()));
  }
  StatusOr<CliArgs> parsed = CliArgs::Parse(
      args,
      {"--out", "--board", "--square", "--images", "--method", "--frames", "--camera", "--set"},
      {"--help", "--options"});
  if (!parsed.ok()) return Fail("calibrate: " + parsed.status().message());
  OptionSet options;
  Status declared = CalibrationSettings::Declare(&options);
  if (!declared.ok()) return Fail("calibrate: " + declared.ToString());
  if (parsed->Has("--help")) {
    std::fputs(kHelp, stdout);
    return 0;
  }
  if (parsed->Has("--options")) {
    std::fputs(options.ToYaml().c_str(), stdout);
    return 0;
  }
  const std::vector<std::string>& positionals = parsed->positionals();
  if (positionals.empty())
    return Fail("calibrate: expected mono, stereo, handeye or floor (see --help)");
  for (const std::string& assignment : parsed->Values("--set")) {
    Status s = options.ApplyOverride(assignment);
    if (!s.ok()) return Fail("calibrate: " + s.ToString());
  }
  Context c;
  c.settings = CalibrationSettings::Extract(options);
  if (auto board = parsed->Value("--board")) {
    Status s = ParseBoardSize(*board, &c.settings.board);
    if (!s.ok()) return Fail("calibrate: --board: " + s.message());
  }
  if (auto square = parsed->Value("--square")) {
    char* end = nullptr;
    c.settings.board.square_size_m = std::strtod(square->c_str(), &end);
    if (end == square->c_str() || *end != '\0') {
      return Fail("calibrate: --square must be a number of metres, got '" + *square + "'");
    }
  }
  if (auto method = parsed->Value("--method")) c.settings.hand_eye.method = *method;
  if (auto frames = parsed->Value("--frames")) {
    c.frames = std::atoi(frames->c_str());
    if (c.frames < 1) return Fail("calibrate: --frames must be a positive whole number");
  }
  if (const std::string error = c.settings.Check(); !error.empty()) {
    return Fail("calibrate: " + error);
  }
  if (!parsed->Value("--out")) return Fail("calibrate: --out FILE is required");
  c.out = *parsed->Value("--out");
  const std::string mode = positionals[0];
  const std::vector<std::string> inputs(positionals.begin() + 1, positionals.end());
  const std::string pattern = parsed->Value("--images").value_or("*");
  if (mode == "mono" || mode == "stereo") return MonoOrStereo(mode == "stereo", inputs, pattern, c);
  if (mode == "handeye") return HandEye(inputs, parsed->Value("--camera"), c);
  return Fail("calibrate: unknown mode '" + mode + "' (mono, stereo, handeye, floor)");
}

}  // namespace sightline::cli
