#include "core/calib/hand_eye.h"

#include <Eigen/SVD>
#include <algorithm>
#include <cmath>
#include <opencv2/calib3d.hpp>

#include "core/calib/mono_calibration.h"

namespace sightline {
namespace {

constexpr double kDeg = 180.0 / M_PI;

cv::HandEyeCalibrationMethod MethodOf(const std::string& name) {
  if (name == "park") return cv::CALIB_HAND_EYE_PARK;
  if (name == "horaud") return cv::CALIB_HAND_EYE_HORAUD;
  if (name == "andreff") return cv::CALIB_HAND_EYE_ANDREFF;
  if (name == "daniilidis") return cv::CALIB_HAND_EYE_DANIILIDIS;
  return cv::CALIB_HAND_EYE_TSAI;
}

cv::Mat ToCvRotation(const Eigen::Isometry3d& t) {
  cv::Mat r(3, 3, CV_64F);
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) r.at<double>(i, j) = t.linear()(i, j);
  }
  return r;
}

cv::Mat ToCvTranslation(const Eigen::Isometry3d& t) {
  return (cv::Mat_<double>(3, 1) << t.translation().x(), t.translation().y(), t.translation().z());
}

// Checks that the arm rotates enough about two non-parallel axes; returns the largest rotation.
StatusOr<double> CheckRotations(const std::vector<Eigen::Isometry3d>& poses, double min_deg) {
  double max_angle = 0;
  std::vector<Eigen::Vector3d> axes;
  for (size_t i = 0; i < poses.size(); ++i) {
    for (size_t j = i + 1; j < poses.size(); ++j) {
      const Eigen::AngleAxisd relative(poses[i].linear().transpose() * poses[j].linear());
      const double angle = std::abs(relative.angle()) * kDeg;
      max_angle = std::max(max_angle, angle);
      if (angle >= min_deg) axes.push_back(relative.axis());
    }
  }
  const double cos_limit = std::cos(15.0 / kDeg);
  for (size_t i = 0; i < axes.size(); ++i) {
    for (size_t j = i + 1; j < axes.size(); ++j) {
      if (std::abs(axes[i].dot(axes[j])) < cos_limit) return max_angle;
    }
  }
  char text[256];
  std::snprintf(text, sizeof(text),
                "hand-eye calibration: the arm poses rotate by at most %.2f deg%s; the camera "
                "mount is only determined by rotations of at least %.1f deg "
                "(calib.handeye.min_rotation_deg) about two axes 15 deg or more apart",
                max_angle, axes.empty() ? "" : " (about one axis only)", min_deg);
  return InvalidArgument(text);
}

// Chordal mean of rotations.
Eigen::Matrix3d MeanRotation(const std::vector<Eigen::Matrix3d>& rotations) {
  Eigen::Matrix3d sum = Eigen::Matrix3d::Zero();
  for (const auto& r : rotations) sum += r;
  Eigen::JacobiSVD<Eigen::Matrix3d> svd(sum, Eigen::ComputeFullU | Eigen::ComputeFullV);
  Eigen::Matrix3d mean = svd.matrixU() * svd.matrixV().transpose();
  if (mean.determinant() < 0) {
    Eigen::Matrix3d u = svd.matrixU();
    u.col(2) *= -1;
    mean = u * svd.matrixV().transpose();
  }
  return mean;
}

void SetBoardSpread(const std::vector<Eigen::Isometry3d>& base_from_board, HandEyeResult* r) {
  std::vector<Eigen::Matrix3d> rotations;
  Eigen::Vector3d mean_t = Eigen::Vector3d::Zero();
  for (const auto& t : base_from_board) {
    rotations.push_back(t.linear());
    mean_t += t.translation();
  }
  mean_t /= static_cast<double>(base_from_board.size());
  r->base_from_board.linear() = MeanRotation(rotations);
  r->base_from_board.translation() = mean_t;
  double sum_angle = 0, sum_t = 0;
  for (const auto& t : base_from_board) {
    const double a = RotationAngleDeg(r->base_from_board.linear().transpose() * t.linear());
    sum_angle += a * a;
    sum_t += (t.translation() - mean_t).squaredNorm();
  }
  const double n = static_cast<double>(base_from_board.size());
  r->board_rotation_rms_deg = std::sqrt(sum_angle / n);
  r->board_translation_rms_m = std::sqrt(sum_t / n);
}

}  // namespace

const std::vector<std::string>& HandEyeMethodNames() {
  static const std::vector<std::string> kNames = {"tsai", "park", "horaud", "andreff",
                                                  "daniilidis"};
  return kNames;
}

bool HandEyeOptions::IsValid(std::string* error) const {
  auto fail = [&](const std::string& m) {
    if (error) *error = "calib.handeye." + m;
    return false;
  };
  const auto& names = HandEyeMethodNames();
  if (std::find(names.begin(), names.end(), method) == names.end()) {
    return fail("method = '" + method + "': must be tsai, park, horaud, andreff or daniilidis");
  }
  if (min_pairs < 3 || min_pairs > 10000) return fail("min_pairs must lie in [3, 10000]");
  if (!(min_rotation_deg >= 0 && min_rotation_deg <= 90)) {
    return fail("min_rotation_deg must lie in [0, 90] deg");
  }
  if (!(max_time_offset_s > 0 && max_time_offset_s <= 10)) {
    return fail("max_time_offset_s must lie in (0, 10] s");
  }
  return true;
}

OptionTable<HandEyeOptions> HandEyeOptions::Describe() {
  using O = HandEyeOptions;
  return OptionTable<O>("calib.handeye")
      .Choice("method", &O::method, HandEyeMethodNames(), "OpenCV's hand-eye solver.")
      .Int("min_pairs", &O::min_pairs, "", 3, 10000, 1, "Fewer arm pose / view pairs is an error.")
      .Double("min_rotation_deg", &O::min_rotation_deg, "deg", 0, 90, 0.5,
              "The arm must rotate at least this much about two different axes.")
      .Double("max_time_offset_s", &O::max_time_offset_s, "s", 0.0001, 10, 0.001,
              "Largest time difference when pairing arm poses with views.");
}

double RotationAngleDeg(const Eigen::Matrix3d& rotation) {
  const double c = std::clamp((rotation.trace() - 1) / 2, -1.0, 1.0);
  return std::acos(c) * kDeg;
}

StatusOr<HandEyeResult> CalibrateHandEye(const std::vector<Eigen::Isometry3d>& base_from_ee,
                                         const std::vector<Eigen::Isometry3d>& camera_from_board,
                                         const HandEyeOptions& options) {
  std::string error;
  if (!options.IsValid(&error)) return InvalidArgument(error);
  if (base_from_ee.size() != camera_from_board.size()) {
    return InvalidArgument("hand-eye calibration: " + std::to_string(base_from_ee.size()) +
                           " arm poses but " + std::to_string(camera_from_board.size()) +
                           " board poses; they must pair up one to one");
  }
  if (static_cast<int>(base_from_ee.size()) < options.min_pairs) {
    return InvalidArgument("hand-eye calibration: " + std::to_string(base_from_ee.size()) +
                           " pose/view pairs, at least " + std::to_string(options.min_pairs) +
                           " needed (calib.handeye.min_pairs)");
  }
  StatusOr<double> max_rotation = CheckRotations(base_from_ee, options.min_rotation_deg);
  if (!max_rotation.ok()) return max_rotation.status();
  std::vector<cv::Mat> r_ee, t_ee, r_board, t_board;
  for (size_t i = 0; i < base_from_ee.size(); ++i) {
    r_ee.push_back(ToCvRotation(base_from_ee[i]));
    t_ee.push_back(ToCvTranslation(base_from_ee[i]));
    r_board.push_back(ToCvRotation(camera_from_board[i]));
    t_board.push_back(ToCvTranslation(camera_from_board[i]));
  }
  cv::Mat r, t;
  try {
    cv::calibrateHandEye(r_ee, t_ee, r_board, t_board, r, t, MethodOf(options.method));
  } catch (const cv::Exception& e) {
    return InvalidArgument("hand-eye calibration failed: " + std::string(e.what()));
  }
  HandEyeResult result;
  result.method = options.method;
  result.pairs = static_cast<int>(base_from_ee.size());
  result.max_rotation_deg = *max_rotation;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) result.end_effector_from_camera.linear()(i, j) = r.at<double>(i, j);
    result.end_effector_from_camera.translation()(i) = t.at<double>(i);
  }
  if (!result.end_effector_from_camera.matrix().allFinite()) {
    return InvalidArgument("hand-eye calibration: the solver returned no finite transform");
  }
  std::vector<Eigen::Isometry3d> base_from_board;
  for (size_t i = 0; i < base_from_ee.size(); ++i) {
    base_from_board.push_back(base_from_ee[i] * result.end_effector_from_camera *
                              camera_from_board[i]);
  }
  SetBoardSpread(base_from_board, &result);
  return result;
}

StatusOr<std::vector<Eigen::Isometry3d>> BoardPoses(const std::vector<BoardView>& views,
                                                    const PinholeCamera& camera,
                                                    const ChessboardOptions& board,
                                                    std::vector<double>* rms_px) {
  SIGHTLINE_RETURN_IF_ERROR(calib_internal::CheckViews(views, board, 1, "board poses", "one view"));
  const std::vector<cv::Point3f> object = board.ObjectPoints();
  const cv::Mat k = calib_internal::CameraMatrix(camera);
  const cv::Mat d = calib_internal::DistortionVector(camera);
  std::vector<Eigen::Isometry3d> poses;
  if (rms_px) rms_px->clear();
  for (const BoardView& view : views) {
    cv::Mat rvec, tvec;
    if (!cv::solvePnP(object, view.corners, k, d, rvec, tvec, false, cv::SOLVEPNP_ITERATIVE)) {
      return InvalidArgument("board poses: PnP failed for view '" + view.name + "'");
    }
    std::vector<cv::Point2f> projected;
    cv::projectPoints(object, rvec, tvec, k, d, projected);
    double sum = 0;
    for (size_t i = 0; i < projected.size(); ++i) {
      const cv::Point2f e = projected[i] - view.corners[i];
      sum += e.dot(e);
    }
    if (rms_px) rms_px->push_back(std::sqrt(sum / projected.size()));
    cv::Mat r;
    cv::Rodrigues(rvec, r);
    Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) pose.linear()(i, j) = r.at<double>(i, j);
      pose.translation()(i) = tvec.at<double>(i);
    }
    poses.push_back(pose);
  }
  return poses;
}

std::vector<Eigen::Isometry3d> ArmPosesForViews(const Trajectory& base_from_ee,
                                                const std::vector<BoardView>& views,
                                                double max_offset_s,
                                                std::vector<int>* view_indices) {
  std::vector<Eigen::Isometry3d> poses;
  view_indices->clear();
  for (size_t i = 0; i < views.size(); ++i) {
    if (views[i].time_s < 0) continue;
    const auto nearest = base_from_ee.Nearest(views[i].time_s, max_offset_s);
    if (!nearest) continue;
    poses.push_back(base_from_ee.poses()[*nearest].world_from_sensor);
    view_indices->push_back(static_cast<int>(i));
  }
  return poses;
}

}  // namespace sightline
