#include "core/calib/calibration_file.h"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <opencv2/core/persistence.hpp>
#include <sstream>

namespace sightline {
namespace {

using calib_internal::CameraMatrix;
using calib_internal::DistortionVector;

std::string Format(const char* format, double value) {
  char text[64];
  std::snprintf(text, sizeof(text), format, value);
  return text;
}

// The camera.yaml keys (core/io/camera_yaml.h) of one camera.
void WriteCameraKeys(cv::FileStorage& fs, const PinholeCamera& c) {
  fs << "model"
     << "pinhole";
  fs << "width" << c.width << "height" << c.height;
  fs << "fx" << c.fx << "fy" << c.fy << "cx" << c.cx << "cy" << c.cy;
  fs << "distortion" << std::vector<double>(c.distortion.begin(), c.distortion.end());
}

Status Open(cv::FileStorage* fs, const std::string& path) {
  try {
    if (!fs->open(path, cv::FileStorage::WRITE | cv::FileStorage::FORMAT_YAML)) {
      return Unavailable("cannot write " + path);
    }
  } catch (const cv::Exception& e) {
    return Unavailable("cannot write " + path + ": " + e.what());
  }
  return Status::Ok();
}

void WriteViewComments(cv::FileStorage& fs, const MonoCalibration& c) {
  fs.writeComment("per-view RMS reprojection error (px):");
  for (const ViewError& v : c.views) {
    fs.writeComment("  " + v.name + " " + Format("%.4f", v.rms_px) +
                    (v.rejected ? " rejected" : ""));
  }
}

Status WriteCameraFile(const PinholeCamera& camera, const std::string& comment,
                       const std::string& path) {
  cv::FileStorage fs;
  SIGHTLINE_RETURN_IF_ERROR(Open(&fs, path));
  fs.writeComment(comment);
  WriteCameraKeys(fs, camera);
  fs.release();
  return Status::Ok();
}

}  // namespace

Status WriteMonoCalibration(const MonoCalibration& c, const ChessboardOptions& board,
                            const std::string& path) {
  cv::FileStorage fs;
  SIGHTLINE_RETURN_IF_ERROR(Open(&fs, path));
  fs.writeComment("Sightline camera calibration (camera.yaml format, see core/io/camera_yaml.h)");
  fs.writeComment("board " + board.SizeText() + ", squares " + Format("%.4f", board.square_size_m) +
                  " m; " + std::to_string(c.used.size()) + " views used, " +
                  std::to_string(c.rejected()) + " rejected; RMS " + Format("%.4f", c.rms_px) +
                  " px");
  fs.writeComment("coverage: " + c.coverage.Summary());
  WriteCameraKeys(fs, c.camera);
  WriteViewComments(fs, c);
  fs.release();
  return Status::Ok();
}

std::string StereoCameraFilePath(const std::string& stereo_path, const std::string& side) {
  std::filesystem::path p(stereo_path);
  const std::string ext = p.has_extension() ? p.extension().string() : ".yaml";
  return (p.parent_path() / (p.stem().string() + "_" + side + ext)).string();
}

Status WriteStereoCalibration(const StereoCalibration& c, const ChessboardOptions& board,
                              const std::string& path) {
  cv::FileStorage fs;
  SIGHTLINE_RETURN_IF_ERROR(Open(&fs, path));
  fs.writeComment("Sightline stereo calibration (OpenCV stereo layout); x_right = R x_left + T");
  fs.writeComment("per-camera files: " + StereoCameraFilePath(path, "left") + ", " +
                  StereoCameraFilePath(path, "right"));
  const StereoRig& rig = c.rig;
  fs << "image_width" << rig.left.width << "image_height" << rig.left.height;
  fs << "M1" << CameraMatrix(rig.left) << "D1" << DistortionVector(rig.left);
  fs << "M2" << CameraMatrix(rig.right) << "D2" << DistortionVector(rig.right);
  cv::Mat r(3, 3, CV_64F), t(3, 1, CV_64F);
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) r.at<double>(i, j) = rig.right_from_left.linear()(i, j);
    t.at<double>(i) = rig.right_from_left.translation()(i);
  }
  fs << "R" << r << "T" << t;
  fs << "E" << cv::Mat(c.essential) << "F" << cv::Mat(c.fundamental);
  fs << "R1" << cv::Mat(c.rect_left) << "R2" << cv::Mat(c.rect_right);
  fs << "P1" << cv::Mat(c.proj_left) << "P2" << cv::Mat(c.proj_right);
  fs << "Q" << cv::Mat(c.disparity_to_depth);
  fs << "rms_left" << c.left.rms_px << "rms_right" << c.right.rms_px << "rms_stereo" << c.rms_px;
  fs << "baseline_m" << c.BaselineM();
  fs << "board_width" << board.columns << "board_height" << board.rows;
  fs << "square_size_m" << board.square_size_m;
  fs.writeComment("per-pair RMS reprojection error, left and right (px):");
  for (const PairError& p : c.pairs) {
    fs.writeComment("  " + p.name + " " + Format("%.4f", p.left_rms_px) + " " +
                    Format("%.4f", p.right_rms_px) + (p.rejected ? " rejected" : ""));
  }
  fs.release();
  const std::string note = "Sightline camera file written with the stereo calibration " + path;
  SIGHTLINE_RETURN_IF_ERROR(
      WriteCameraFile(rig.left, note + " (left)", StereoCameraFilePath(path, "left")));
  return WriteCameraFile(rig.right, note + " (right)", StereoCameraFilePath(path, "right"));
}

namespace {

Status ReadMatrix(const cv::FileStorage& fs, const std::string& key, int rows, int cols,
                  const std::string& path, cv::Mat* out) {
  cv::FileNode node = fs[key];
  if (node.empty()) return ParseError(path + ": key '" + key + "' is missing");
  cv::Mat m;
  try {
    node >> m;
  } catch (const cv::Exception&) {
    return ParseError(path + ": key '" + key + "' is not an OpenCV matrix");
  }
  if (m.total() != static_cast<size_t>(rows) * cols) {
    return ParseError(path + ": key '" + key + "' must hold " + std::to_string(rows * cols) +
                      " numbers, found " + std::to_string(m.total()));
  }
  m.convertTo(*out, CV_64F);
  *out = out->reshape(1, rows);
  return Status::Ok();
}

Status ReadCamera(const cv::FileStorage& fs, const std::string& k_key, const std::string& d_key,
                  cv::Size size, const std::string& path, PinholeCamera* camera) {
  cv::Mat k, d;
  SIGHTLINE_RETURN_IF_ERROR(ReadMatrix(fs, k_key, 3, 3, path, &k));
  cv::FileNode node = fs[d_key];
  if (node.empty()) return ParseError(path + ": key '" + d_key + "' is missing");
  cv::Mat raw;
  try {
    node >> raw;
  } catch (const cv::Exception&) {
    return ParseError(path + ": key '" + d_key + "' is not an OpenCV matrix");
  }
  if (raw.total() < 4 || raw.total() > 5) {
    return ParseError(path + ": key '" + d_key + "' must hold 4 or 5 distortion coefficients");
  }
  raw.convertTo(d, CV_64F);
  *camera = calib_internal::ToCamera(k, d.reshape(1, 1), size);
  Status valid = camera->Validate();
  if (!valid.ok()) return ParseError(path + ": " + k_key + ": " + valid.message());
  return Status::Ok();
}

}  // namespace

StatusOr<StereoRig> ReadStereoCalibration(const std::string& path) {
  if (!std::filesystem::is_regular_file(path)) return NotFound(path + " does not exist");
  cv::FileStorage fs;
  try {
    if (!fs.open(path, cv::FileStorage::READ))
      return ParseError(path + ": not an OpenCV YAML/XML file");
  } catch (const cv::Exception& e) {
    return ParseError(path + ": not an OpenCV YAML/XML file (" + e.err + ")");
  }
  const cv::FileNode w = fs["image_width"], h = fs["image_height"];
  if (w.empty() || h.empty() || !w.isInt() || !h.isInt()) {
    return ParseError(path + ": keys 'image_width' and 'image_height' (whole pixels) are required");
  }
  const cv::Size size(static_cast<int>(w), static_cast<int>(h));
  StereoRig rig;
  SIGHTLINE_RETURN_IF_ERROR(ReadCamera(fs, "M1", "D1", size, path, &rig.left));
  SIGHTLINE_RETURN_IF_ERROR(ReadCamera(fs, "M2", "D2", size, path, &rig.right));
  cv::Mat r, t;
  SIGHTLINE_RETURN_IF_ERROR(ReadMatrix(fs, "R", 3, 3, path, &r));
  SIGHTLINE_RETURN_IF_ERROR(ReadMatrix(fs, "T", 3, 1, path, &t));
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) rig.right_from_left.linear()(i, j) = r.at<double>(i, j);
    rig.right_from_left.translation()(i) = t.at<double>(i);
  }
  const Eigen::Matrix3d rot = rig.right_from_left.linear();
  if (!((rot.transpose() * rot - Eigen::Matrix3d::Identity()).norm() < 1e-3)) {
    return ParseError(path + ": key 'R' is not a rotation matrix");
  }
  Status valid = rig.Validate();
  if (!valid.ok()) return ParseError(path + ": key 'T': " + valid.message());
  return rig;
}

}  // namespace sightline

namespace sightline {

Status WriteHandEyeCalibration(const HandEyeResult& result, const std::string& path) {
  cv::FileStorage fs;
  SIGHTLINE_RETURN_IF_ERROR(Open(&fs, path));
  fs.writeComment("Sightline hand-eye calibration (" + result.method + ", " +
                  std::to_string(result.pairs) +
                  " pairs): end_effector_from_camera is the "
                  "camera's optical frame in the end-effector frame, metres");
  const Eigen::Isometry3d& t = result.end_effector_from_camera;
  const Eigen::Quaterniond q(t.linear());
  fs << "end_effector_from_camera"
     << "{";
  fs << "translation"
     << std::vector<double>{t.translation().x(), t.translation().y(), t.translation().z()};
  fs << "quaternion_xyzw" << std::vector<double>{q.x(), q.y(), q.z(), q.w()};
  fs << "}";
  cv::Mat r(3, 3, CV_64F);
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) r.at<double>(i, j) = t.linear()(i, j);
  }
  fs << "rotation" << r;
  fs << "method" << result.method << "pairs" << result.pairs;
  fs << "max_rotation_deg" << result.max_rotation_deg;
  fs << "board_rotation_rms_deg" << result.board_rotation_rms_deg;
  fs << "board_translation_rms_m" << result.board_translation_rms_m;
  fs.release();
  return Status::Ok();
}

StatusOr<Eigen::Isometry3d> ReadEndEffectorFromCamera(const std::string& path) {
  if (!std::filesystem::is_regular_file(path)) return NotFound(path + " does not exist");
  // The simulator writes plain YAML without OpenCV's "%YAML:1.0" line, which FileStorage needs.
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  std::string content = text.str();
  if (content.rfind("%YAML", 0) != 0) content = "%YAML:1.0\n---\n" + content;
  cv::FileStorage fs;
  try {
    if (!fs.open(content,
                 cv::FileStorage::READ | cv::FileStorage::MEMORY | cv::FileStorage::FORMAT_YAML)) {
      return ParseError(path + ": not a YAML file");
    }
  } catch (const cv::Exception& e) {
    return ParseError(path + ": not a YAML file (" + e.err + ")");
  }
  const cv::FileNode node = fs["end_effector_from_camera"];
  if (node.empty() || !node.isMap()) {
    return ParseError(path + ": key 'end_effector_from_camera' is missing");
  }
  std::vector<double> t, q;
  try {
    node["translation"] >> t;
    node["quaternion_xyzw"] >> q;
  } catch (const cv::Exception&) {
    t.clear();
  }
  if (t.size() != 3 || q.size() != 4) {
    return ParseError(path +
                      ": end_effector_from_camera needs 'translation' (3 numbers) and "
                      "'quaternion_xyzw' (4 numbers)");
  }
  const Eigen::Quaterniond quaternion(q[3], q[0], q[1], q[2]);
  if (!(std::abs(quaternion.norm() - 1) < 1e-3)) {
    return ParseError(path + ": end_effector_from_camera.quaternion_xyzw is not a unit quaternion");
  }
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.linear() = quaternion.normalized().toRotationMatrix();
  pose.translation() = Eigen::Vector3d(t[0], t[1], t[2]);
  return pose;
}

}  // namespace sightline
