#include "core/calib/calibration_report.h"

#include <cmath>
#include <cstdarg>
#include <cstdio>

namespace sightline {
namespace {

std::string Printf(const char* format, ...) {
  char text[512];
  va_list args;
  va_start(args, format);
  std::vsnprintf(text, sizeof(text), format, args);
  va_end(args);
  return text;
}

std::string CameraLine(const char* label, const PinholeCamera& c) {
  return Printf(
      "%s: %dx%d fx %.2f fy %.2f cx %.2f cy %.2f k1 %.4f k2 %.4f p1 %.5f p2 %.5f "
      "k3 %.4f\n",
      label, c.width, c.height, c.fx, c.fy, c.cx, c.cy, c.distortion[0], c.distortion[1],
      c.distortion[2], c.distortion[3], c.distortion[4]);
}

std::string CoverageLines(const Coverage& coverage) {
  std::string text = "coverage: " + coverage.Summary() + "\n";
  for (const std::string& hint : coverage.Hints()) text += "  hint: " + hint + "\n";
  return text;
}

std::string WithoutBoard(const Detections& detections) {
  std::string text;
  for (const std::string& name : detections.without_board) text += "  no board: " + name + "\n";
  return text;
}

}  // namespace

Status CalibrationSettings::Declare(OptionSet* options) {
  SIGHTLINE_RETURN_IF_ERROR(options->Declare(ChessboardOptions::Describe()));
  SIGHTLINE_RETURN_IF_ERROR(options->Declare(CoverageOptions::Describe()));
  SIGHTLINE_RETURN_IF_ERROR(options->Declare(MonoCalibrationOptions::Describe()));
  SIGHTLINE_RETURN_IF_ERROR(options->Declare(StereoCalibrationOptions::Describe()));
  return options->Declare(HandEyeOptions::Describe());
}

CalibrationSettings CalibrationSettings::Extract(const OptionSet& options) {
  CalibrationSettings s;
  s.board = options.Extract(ChessboardOptions::Describe());
  s.coverage = options.Extract(CoverageOptions::Describe());
  s.mono = options.Extract(MonoCalibrationOptions::Describe());
  s.stereo = options.Extract(StereoCalibrationOptions::Describe());
  s.hand_eye = options.Extract(HandEyeOptions::Describe());
  return s;
}

std::string CalibrationSettings::Check() const {
  std::string error;
  if (!board.IsValid(&error) || !coverage.IsValid(&error) || !mono.IsValid(&error) ||
      !stereo.IsValid(&error) || !hand_eye.IsValid(&error)) {
    return error;
  }
  return "";
}

std::string MonoReport(const MonoCalibration& c, const Detections& detections) {
  std::string text =
      Printf("board found in %zu of %d images\n", detections.views.size(), detections.inputs);
  text += WithoutBoard(detections);
  text += "per-view RMS reprojection error (px):\n";
  for (const ViewError& v : c.views) {
    text += Printf("  %-24s %.4f%s\n", v.name.c_str(), v.rms_px, v.rejected ? "  rejected" : "");
  }
  text += Printf("views used %zu, rejected %d\n", c.used.size(), c.rejected());
  text += Printf("RMS %.4f px\n", c.rms_px);
  text += CameraLine("camera", c.camera);
  return text + CoverageLines(c.coverage);
}

std::string StereoReport(const StereoCalibration& c, const Detections& detections) {
  std::string text = Printf("board found in both images of %zu of %d pairs\n",
                            detections.views.size(), detections.inputs);
  text += WithoutBoard(detections);
  text += "per-pair RMS reprojection error, left / right (px):\n";
  for (const PairError& p : c.pairs) {
    text += Printf("  %-28s %.4f  %.4f%s\n", p.name.c_str(), p.left_rms_px, p.right_rms_px,
                   p.rejected ? "  rejected" : "");
  }
  text += Printf("RMS left %.4f px, right %.4f px, stereo %.4f px (%d pairs used)\n", c.left.rms_px,
                 c.right.rms_px, c.rms_px, c.used_pairs());
  const Eigen::Vector3d t = c.rig.right_from_left.translation();
  const double angle = Eigen::AngleAxisd(c.rig.right_from_left.linear()).angle() * 180 / M_PI;
  text += Printf("baseline %.2f mm (T = %.2f %.2f %.2f mm, rotation %.3f deg)\n",
                 1000 * c.BaselineM(), 1000 * t.x(), 1000 * t.y(), 1000 * t.z(), angle);
  text += CameraLine("left", c.rig.left) + CameraLine("right", c.rig.right);
  text += "left " + CoverageLines(c.left.coverage);
  return text + "right " + CoverageLines(c.right.coverage);
}

std::string HandEyeReport(const HandEyeResult& r) {
  const Eigen::Isometry3d& x = r.end_effector_from_camera;
  const Eigen::AngleAxisd aa(x.linear());
  const Eigen::Quaterniond q(x.linear());
  std::string text = Printf("hand-eye (%s) from %d pairs; arm rotation up to %.1f deg\n",
                            r.method.c_str(), r.pairs, r.max_rotation_deg);
  text += Printf(
      "end_effector_from_camera: translation %.4f %.4f %.4f m, quaternion_xyzw "
      "%.6f %.6f %.6f %.6f (%.2f deg)\n",
      x.translation().x(), x.translation().y(), x.translation().z(), q.x(), q.y(), q.z(), q.w(),
      aa.angle() * 180 / M_PI);
  text += Printf("board in the base frame: spread %.2f mm, %.3f deg RMS\n",
                 1000 * r.board_translation_rms_m, r.board_rotation_rms_deg);
  return text;
}

}  // namespace sightline
