// Occupancy image (seed 000, section 4.3.2): a bird's-eye view of one depth frame, built with
// the calibrated floor plane. Each depth pixel becomes a 3D point; points within epsilon_floor of
// the floor are free, points above it (up to a height limit) occupied; pixels inside a person's
// box mark their cells as person instead, so walls are never fitted to people.
//
// Geometry (seed: 400 x 400, robot at (width / 2, height)): column = width / 2 - y / cell,
// row = height - x / cell, with x forward and y left in the base frame (pose2d.h). Row 0 is the
// far edge; the robot sits at the middle of the bottom edge.
#pragma once

#include <Eigen/Core>
#include <opencv2/core.hpp>
#include <string>
#include <vector>

#include "core/common/camera.h"
#include "core/common/status.h"
#include "core/mapping/floor_plane.h"
#include "core/mapping/mapping_types.h"
#include "core/mapping/person_boxes.h"
#include "core/options/option_table.h"

namespace sightline {

// Options of the occupancy image. Keys "mapping.occupancy.*".
struct OccupancyImageOptions {
  int width_cells = 400;        // Seed: 400.
  int height_cells = 400;       // Seed: 400.
  double cell_size_m = 0.02;    // Cell edge [m]; 400 cells x 2 cm = 8 m, the Kinect's range.
  double max_height_m = 1.8;    // Points higher above the floor (ceiling, lamps) are ignored [m].
  int min_occupied_points = 1;  // Points a cell needs to be occupied (1 = seed: any point).
  int target_columns = 320;     // Depth is sampled to about this many columns (seed: 320x240).
  double person_depth_margin_m = 0.4;  // Pixels in a person box within this depth of the box's
                                       // median depth belong to the person [m].

  bool IsValid(std::string* error) const;
  static OptionTable<OccupancyImageOptions> Describe();
};

// Builds occupancy images. Configure() once per floor plane and camera (it precomputes a table
// of per-pixel ray coefficients), then Build() per frame without allocating.
//
//   OccupancyImageBuilder builder(options);
//   SIGHTLINE_RETURN_IF_ERROR(builder.Configure(floor, camera));
//   StatusOr<OccupancyImage> image = builder.Build(frame.depth_m, people);
class OccupancyImageBuilder {
 public:
  explicit OccupancyImageBuilder(OccupancyImageOptions options = {});

  // Sets the floor plane and the depth camera (intrinsics at any resolution; they are scaled to
  // the depth image on the first Build). Fails on an invalid plane, camera or options.
  Status Configure(const FloorPlane& floor, const PinholeCamera& camera);

  // The occupancy image of one metric depth image (CV_32FC1, NaN = invalid). `people` are boxes
  // in image pixels (any resolution; scaled by their image_size). An empty or all-invalid
  // depth gives an all-unknown image (not an error); a wrong type is InvalidArgument.
  StatusOr<OccupancyImage> Build(const cv::Mat& depth_m, const std::vector<PersonBox>& people);

  // Bearing range of the camera's field of view on the floor [rad], from the ray table
  // (counter-clockwise from forward; min < 0 < max for a forward-looking camera). Valid after
  // Configure().
  double fov_min_rad() const { return fov_min_rad_; }
  double fov_max_rad() const { return fov_max_rad_; }
  const OccupancyImageOptions& options() const { return options_; }
  const FloorPlane& floor() const { return floor_; }

  // base_from_camera rotation rows: forward, left, up (camera-frame unit vectors).
  const Eigen::Matrix3d& base_from_camera_rotation() const { return base_from_camera_; }

 private:
  Status PrepareTable(int depth_cols, int depth_rows);

  OccupancyImageOptions options_;
  FloorPlane floor_;
  PinholeCamera camera_;
  bool configured_ = false;
  Eigen::Matrix3d base_from_camera_ = Eigen::Matrix3d::Identity();
  double fov_min_rad_ = 0, fov_max_rad_ = 0;
  // Per sampled pixel: (up . ray, forward . ray, left . ray) for a ray with z = 1.
  int table_cols_ = 0, table_rows_ = 0, step_ = 1;
  std::vector<Eigen::Vector3f> ray_table_;
  std::vector<uint8_t> occupied_counts_;
  cv::Mat cells_;  // The last image's cells, reused when no result holds them any more.
  std::vector<uint8_t> person_mask_;  // Per sampled pixel, when people are given.
};

}  // namespace sightline
