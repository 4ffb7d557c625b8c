// Hand-eye calibration of an arm camera (cv::calibrateHandEye): from arm poses
// (base_from_end_effector) and the board seen by the camera at the same instants
// (camera_from_board), the camera's mount end_effector_from_camera. Checks that the poses rotate
// about two non-parallel axes (otherwise the problem has no unique answer) and reports how
// consistently the board then lies in the base frame.
#pragma once

#include <Eigen/Geometry>
#include <string>
#include <vector>

#include "core/calib/chessboard.h"
#include "core/common/camera.h"
#include "core/common/status.h"
#include "core/common/trajectory.h"
#include "core/options/option_table.h"

namespace sightline {

// How to solve. Keys "calib.handeye.*".
struct HandEyeOptions {
  std::string method = "tsai";  // tsai, park, horaud, andreff, daniilidis (OpenCV's methods).
  int min_pairs = 3;            // Fewer pose/view pairs is an error.
  // The arm must rotate by at least this much, about at least two axes 15 deg or more apart.
  double min_rotation_deg = 5.0;
  double max_time_offset_s = 0.02;  // Pairing arm poses with views by timestamp, seconds.

  bool IsValid(std::string* error) const;
  static OptionTable<HandEyeOptions> Describe();
};

// The method names HandEyeOptions::method accepts.
const std::vector<std::string>& HandEyeMethodNames();

// The solved mount and how well it explains the data.
struct HandEyeResult {
  Eigen::Isometry3d end_effector_from_camera = Eigen::Isometry3d::Identity();
  Eigen::Isometry3d base_from_board = Eigen::Isometry3d::Identity();  // Mean over the pairs.
  int pairs = 0;
  double max_rotation_deg = 0;  // Largest rotation between two arm poses.
  // Spread of base_from_board over the pairs (RMS about the mean): small when poses, views and
  // the solved mount agree.
  double board_rotation_rms_deg = 0;
  double board_translation_rms_m = 0;
  std::string method;
};

// Solves AX = XB. InvalidArgument for unequal counts, too few pairs, poses without enough
// rotation, or an unknown method.
StatusOr<HandEyeResult> CalibrateHandEye(
    const std::vector<Eigen::Isometry3d>& base_from_end_effector,
    const std::vector<Eigen::Isometry3d>& camera_from_board, const HandEyeOptions& options = {});

// camera_from_board of each view by PnP with known intrinsics; per-view RMS errors in pixels
// into *rms_px when given. InvalidArgument naming the view when PnP fails.
StatusOr<std::vector<Eigen::Isometry3d>> BoardPoses(const std::vector<BoardView>& views,
                                                    const PinholeCamera& camera,
                                                    const ChessboardOptions& board,
                                                    std::vector<double>* rms_px = nullptr);

// For each view with a timestamp, the arm pose nearest in time within max_offset_s. Views
// without such a pose are left out; *view_indices gets the indices of the views kept.
std::vector<Eigen::Isometry3d> ArmPosesForViews(const Trajectory& base_from_end_effector,
                                                const std::vector<BoardView>& views,
                                                double max_offset_s,
                                                std::vector<int>* view_indices);

// Angle of a rotation, degrees.
double RotationAngleDeg(const Eigen::Matrix3d& rotation);

}  // namespace sightline
