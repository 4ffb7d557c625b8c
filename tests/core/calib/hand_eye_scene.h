// A hand-eye calibration session on the simulator's arm: the panel scene's arm base and camera
// mount (core/sim), a chessboard fixed in front of the panel, and arm poses that look at it from
// different directions (the simulator's own approach only translates, on which hand-eye
// calibration is undetermined). Images are rendered through the simulator's mono camera.
#pragma once

#include <Eigen/Geometry>
#include <opencv2/core.hpp>
#include <string>
#include <vector>

#include "core/calib/chessboard.h"
#include "core/common/camera.h"
#include "core/common/status.h"
#include "core/common/trajectory.h"

namespace sightline::testing {

struct HandEyeScene {
  PinholeCamera camera;                              // The simulator's mono camera.
  Eigen::Isometry3d end_effector_from_camera;        // The simulator's mount (the truth).
  Trajectory base_from_end_effector;                 // Arm poses with the simulator's pose noise.
  std::vector<Eigen::Isometry3d> camera_from_board;  // Exact.
  std::vector<cv::Mat> images;                       // Grey, with pixel noise.
  std::vector<double> times_s;
};

// `views` poses at 10 Hz; the board is the default 9x6 board with 25 mm squares.
StatusOr<HandEyeScene> MakeHandEyeScene(int views, const ChessboardOptions& board);

// Writes DIR/views/ (NNNNNN.png, times.txt, camera.yaml) and DIR/arm_poses.txt (TUM).
Status WriteHandEyeScene(const HandEyeScene& scene, const std::string& dir);

}  // namespace sightline::testing
