// The payloads of the mobility map: the working cloud the per-point stages share, the ground
// plane, per-segment surface properties and scores, the maps and the per-stage timing.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cstdint>
#include <limits>
#include <opencv2/core.hpp>
#include <string>
#include <vector>

#include "core/common/frame.h"
#include "core/common/status.h"

namespace sightline {

// The points the per-point stages work on, in the camera frame (x right, y down, z forward).
// Grid mode keeps the layout of the downsampled pixel grid (grid_w x grid_h cells, each with at
// most one point) so that neighbours are found by index; pcl mode leaves it empty.
struct WorkingCloud {
  std::vector<Eigen::Vector3f> points;
  std::vector<Eigen::Vector3f> normals;  // Unit, towards the viewpoint; NaN where unknown.
  std::vector<int> pixel;                // Index into the input cloud (row * width + col), or -1.
  int grid_w = 0, grid_h = 0;            // Grid mode only.
  std::vector<int> cell_point;           // Grid cell -> point index, -1 = none.
  std::vector<int> point_cell;           // Point index -> grid cell.

  size_t size() const { return points.size(); }
  bool gridded() const { return grid_w > 0; }
  // Keeps the points with keep[i] != 0, in order, updating the grid maps.
  void Compact(const std::vector<uint8_t>& keep);
};

// The ground: n . x + d = 0 in the camera frame with n the unit up normal, so n . x + d is the
// height of x above the ground and d the camera's height.
struct GroundPlane {
  bool found = false;
  Eigen::Vector3d normal = Eigen::Vector3d(0, -1, 0);
  double d = 0;
  int inliers = 0;
  int candidates = 0;  // Up-facing planes considered.

  double HeightOf(const Eigen::Vector3f& x) const { return normal.dot(x.cast<double>()) + d; }
};

// One segment's surface properties and scores (a row of segments.csv).
struct SegmentProperties {
  int id = 0;
  bool is_ground = false;
  int points = 0;
  double slope_deg = 0;   // Plane normal against the ground normal, [0, 90].
  double roughness = 1;   // Sum of 3D / projected triangle areas (>= 1, flat = 1).
  double area_m2 = 0;     // Occupied plane cells times the cell area.
  double height_m = 0;    // Raised above the ground (MobilityOptions::height_percentile).
  double score_rule = 0;  // Table I, 0 when raised more than the platform's step.
  double score_gpr = 0;   // Gaussian process on Table I, clamped to [0, 1].
  double foot_m = 0;      // Horizontal distance from its lowest points to where its plane
                          // meets the ground (height / tan slope; infinite when level).
  bool raised = false;    // Scored 0 for its height.
  Eigen::Vector3d normal = Eigen::Vector3d::Zero();
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
};

// Time and input size of one stage, as in the seed's Table II.
struct StageReport {
  std::string name;
  double ms = 0;
  int64_t points = 0;  // Points entering the stage.
};

// The top view: a grid on the ground plane holding the lowest score seen in each cell.
// Ground frame: origin under the camera, z up, x along the camera's view, y left.
struct TopViewMap {
  cv::Mat score;  // CV_32FC1, rows = x (row 0 farthest), cols = y (col 0 leftmost); NaN = unknown.
  double cell_m = 0.02;
  double x_max_m = 0;  // Forward extent; row r covers x in [x_max - (r+1) cell, x_max - r cell).
  double y_max_m = 0;  // Lateral half-width; col c covers y in [y_max - (c+1) cell, ...).
  Eigen::Isometry3d ground_from_camera = Eigen::Isometry3d::Identity();
};

// Everything the mapper made of one frame. Immutable once built; shared with views.
struct MobilityResult {
  FrameStamp stamp;
  Status status;     // Why the frame has no (full) map, if so.
  std::string mode;  // "grid" or "pcl".
  int input_width = 0, input_height = 0;
  Eigen::Vector3d expected_up = Eigen::Vector3d(0, -1, 0);
  GroundPlane ground;
  int ransac_iterations = 0;            // Per candidate, from seed eq. 6.
  std::vector<Eigen::Vector3f> points;  // The scored cloud (after cut, downsampling, denoising).
  std::vector<int> pixel;               // Input index of each point, -1 = none.
  std::vector<int> segment;             // Index into segments, -1 = unsegmented.
  std::vector<cv::Vec3b> rgbn;          // RGB-N colour (R, G, B) of each point.
  std::vector<SegmentProperties> segments;  // The ground first when found.
  TopViewMap map;
  cv::Mat projection;  // BGR colour image with the scores drawn on it.
  std::vector<StageReport> stages;
  bool use_gpr = false;  // Which score the maps show.

  // Score of point i (the chosen one), NaN when unsegmented.
  float PointScore(size_t i) const {
    const int s = segment[i];
    if (s < 0) return std::numeric_limits<float>::quiet_NaN();
    return static_cast<float>(use_gpr ? segments[s].score_gpr : segments[s].score_rule);
  }
  double TotalMs() const {
    double t = 0;
    for (const StageReport& s : stages) t += s.ms;
    return t;
  }
};

}  // namespace sightline
