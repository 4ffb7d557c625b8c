// The mobility map's outputs: the top-view grid on the ground, the scores projected onto the
// colour image (seed eq. 13), the score colours, and intrinsics recovered from an organized
// cloud when the source gives none (PCD files).
#pragma once

#include <Eigen/Geometry>
#include <opencv2/core.hpp>
#include <vector>

#include "core/common/camera.h"
#include "core/common/frame.h"
#include "core/common/status.h"
#include "core/mobility/mobility_types.h"

namespace sightline {

// Score colour, BGR: red at 0, yellow at 0.5, green at 1; grey for NaN (unscored).
cv::Vec3b ScoreColorBgr(float score);

// The ground frame: origin on the ground under the camera, z = the ground's up normal, x = the
// camera's optical axis projected onto the ground, y = z x x (left).
Eigen::Isometry3d GroundFromCamera(const GroundPlane& ground);

// A top-view grid of cell_m cells over x in [0, range_m], y in [-range_m, range_m] holding the
// lowest score of the points falling into each cell (NaN where none).
TopViewMap BuildTopView(const std::vector<Eigen::Vector3f>& points,
                        const std::vector<float>& scores, const GroundPlane& ground, double cell_m,
                        double range_m);

// The top view as a BGR image (camera at the bottom centre, forward up), one pixel per cell.
cv::Mat RenderTopView(const TopViewMap& map);

// Published eq. 13: u = fx (x + tx) / z + cx, v = fy (y + ty) / z + cy. Draws each scored point's
// colour as a dot of dot_px pixels half-blended into a copy of `color_bgr` (a grey canvas of
// the camera's size when empty).
cv::Mat ProjectScores(const std::vector<Eigen::Vector3f>& points, const std::vector<float>& scores,
                      const PinholeCamera& camera, const cv::Mat& color_bgr, double offset_x_m,
                      double offset_y_m, int dot_px);

// Pinhole intrinsics (no distortion) of an organized cloud, by least squares on
// u = fx x / z + cx and v = fy y / z + cy over its valid points. FailedPrecondition for an
// unorganized cloud or too few valid points.
StatusOr<PinholeCamera> EstimateIntrinsics(const PointCloud& cloud);

// The organized cloud's colours as a BGR image (empty when it has none or is unorganized).
cv::Mat CloudColorImage(const PointCloud& cloud);

}  // namespace sightline
