#include "core/calib/calibration_file.h"

#include <cstdio>
#include <filesystem>

#include "core/io/camera_yaml.h"
#include "core/io/hand_eye_file.h"
#include "core/io/stereo_calibration_file.h"

namespace sightline {
namespace {

std::string Format(const char* format, double value) {
  char text[64];
  std::snprintf(text, sizeof(text), format, value);
  return text;
}

std::vector<std::string> ViewComments(const MonoCalibration& c) {
  std::vector<std::string> lines = {"per-view RMS reprojection error (px):"};
  for (const ViewError& v : c.views) {
    lines.push_back("  " + v.name + " " + Format("%.4f", v.rms_px) +
                    (v.rejected ? " rejected" : ""));
  }
  return lines;
}

std::vector<std::string> PairComments(const StereoCalibration& c) {
  std::vector<std::string> lines = {"per-pair RMS reprojection error, left and right (px):"};
  for (const PairError& p : c.pairs) {
    lines.push_back("  " + p.name + " " + Format("%.4f", p.left_rms_px) + " " +
                    Format("%.4f", p.right_rms_px) + (p.rejected ? " rejected" : ""));
  }
  return lines;
}

Eigen::MatrixXd ToEigen(const cv::Mat& m) {
  cv::Mat d;
  m.convertTo(d, CV_64F);
  Eigen::MatrixXd out(d.rows, d.cols);
  for (int r = 0; r < d.rows; ++r) {
    for (int c = 0; c < d.cols; ++c) out(r, c) = d.at<double>(r, c);
  }
  return out;
}

StereoFileExtras ExtrasOf(const StereoCalibration& c, const ChessboardOptions& board,
                          const std::string& path) {
  StereoFileExtras extras;
  extras.comments.header = {
      "Sightline stereo calibration (OpenCV stereo layout); x_right = R x_left + T",
      "per-camera files: " + StereoCameraFilePath(path, "left") + ", " +
          StereoCameraFilePath(path, "right")};
  extras.matrices = {
      {"E", ToEigen(cv::Mat(c.essential))},         {"F", ToEigen(cv::Mat(c.fundamental))},
      {"R1", ToEigen(cv::Mat(c.rect_left))},        {"R2", ToEigen(cv::Mat(c.rect_right))},
      {"P1", ToEigen(cv::Mat(c.proj_left))},        {"P2", ToEigen(cv::Mat(c.proj_right))},
      {"Q", ToEigen(cv::Mat(c.disparity_to_depth))}};
  extras.numbers = {{"rms_left", c.left.rms_px},
                    {"rms_right", c.right.rms_px},
                    {"rms_stereo", c.rms_px},
                    {"baseline_m", c.BaselineM()},
                    {"board_width", board.columns},
                    {"board_height", board.rows},
                    {"square_size_m", board.square_size_m}};
  extras.comments.footer = PairComments(c);
  return extras;
}

}  // namespace

Status SaveMonoCalibration(const MonoCalibration& c, const ChessboardOptions& board,
                           const std::string& path) {
  FileComments comments;
  comments.header = {
      "Sightline camera calibration (camera.yaml format, see core/io/camera_yaml.h)",
      "board " + board.SizeText() + ", squares " + Format("%.4f", board.square_size_m) + " m; " +
          std::to_string(c.used.size()) + " views used, " + std::to_string(c.rejected()) +
          " rejected; RMS " + Format("%.4f", c.rms_px) + " px",
      "coverage: " + c.coverage.Summary()};
  comments.footer = ViewComments(c);
  CameraFile file;
  file.camera = c.camera;
  return WriteCameraYaml(file, path, comments);
}

std::string StereoCameraFilePath(const std::string& stereo_path, const std::string& side) {
  std::filesystem::path p(stereo_path);
  const std::string ext = p.has_extension() ? p.extension().string() : ".yaml";
  return (p.parent_path() / (p.stem().string() + "_" + side + ext)).string();
}

Status SaveStereoCalibration(const StereoCalibration& c, const ChessboardOptions& board,
                             const std::string& path) {
  SIGHTLINE_RETURN_IF_ERROR(WriteStereoCalibration(c.rig, path, ExtrasOf(c, board, path)));
  const std::string note = "Sightline camera file written with the stereo calibration " + path;
  for (const auto& [camera, side] :
       {std::pair<const PinholeCamera*, const char*>{&c.rig.left, "left"},
        {&c.rig.right, "right"}}) {
    CameraFile file;
    file.camera = *camera;
    SIGHTLINE_RETURN_IF_ERROR(WriteCameraYaml(file, StereoCameraFilePath(path, side),
                                              FileComments{{note + " (" + side + ")"}, {}}));
  }
  return Status::Ok();
}

Status SaveHandEyeCalibration(const HandEyeResult& result, const std::string& path) {
  HandEye file;
  file.end_effector_from_camera = result.end_effector_from_camera;
  file.fit = HandEyeFit{result.method, result.pairs, result.max_rotation_deg,
                        result.board_rotation_rms_deg, result.board_translation_rms_m};
  FileComments comments;
  comments.header = {"Sightline hand-eye calibration (" + result.method + ", " +
                     std::to_string(result.pairs) +
                     " pairs): end_effector_from_camera is the camera's optical frame in the "
                     "end-effector frame, metres"};
  return WriteHandEyeFile(file, path, comments);
}

}  // namespace sightline
