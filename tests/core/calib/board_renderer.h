// Test images of a chessboard seen through a pinhole camera without distortion: a printed board
// (inner corners at (c, r) * square in the board frame, one white square of margin) warped by
// the exact homography, blurred slightly, with pixel noise.
#pragma once

#include <Eigen/Geometry>
#include <opencv2/core.hpp>
#include <vector>

#include "core/calib/chessboard.h"
#include "core/common/camera.h"

namespace sightline::testing {

// A grey image of `board` at camera_from_board. Noise: Gaussian sigma in grey levels.
cv::Mat RenderBoardView(const PinholeCamera& camera, const Eigen::Isometry3d& camera_from_board,
                        const ChessboardOptions& board, double noise_sigma, int seed);

// The board's inner corners projected exactly (no distortion).
std::vector<cv::Point2f> ProjectBoard(const PinholeCamera& camera,
                                      const Eigen::Isometry3d& camera_from_board,
                                      const ChessboardOptions& board);

// A camera pose looking at the board centre from `distance_m`, displaced from the board normal
// by `off_axis_deg` towards direction `azimuth_deg`, rolled by `roll_deg` about its axis.
Eigen::Isometry3d BoardFromCameraLookingAt(const ChessboardOptions& board, double distance_m,
                                           double off_axis_deg, double azimuth_deg,
                                           double roll_deg);

}  // namespace sightline::testing
