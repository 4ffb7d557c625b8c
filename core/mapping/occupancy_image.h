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
#include "core/mapping/person_boxes.h"
#include "core/options/option_table.h"

namespace sightline {

// The label of one occupancy cell (the values stored in OccupancyImage::cells).
enum class OccupancyCell : uint8_t {
  kUnknown = 0,   // No depth reading fell into the cell.
  kFree = 1,      // Floor seen, nothing above it.
  kOccupied = 2,  // Something between epsilon_floor and max_height_m above the floor.
  kPerson = 3,    // Occupied by a person (excluded from scans and from the map's obstacles).
};

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

// A person's footprint in the occupancy image.
struct PersonFootprint {
  int id = -1;
  cv::Rect cells;      // Bounding rectangle in cells (x = column, y = row).
  double range_m = 0;  // Median distance from the robot [m].
};

// One frame's occupancy image and what went into it.
struct OccupancyImage {
  cv::Mat cells;  // CV_8UC1 of OccupancyCell, height_cells x width_cells.
  double cell_size_m = 0.02;
  std::vector<PersonFootprint> people;  // Scans skip these rectangles.
  cv::Rect known_cells;                 // Bounding rectangle of the cells that are not unknown.
  int sampled_pixels = 0;               // Depth pixels looked at.
  int invalid_pixels = 0;               // NaN or non-positive depth.
  int floor_pixels = 0;
  int occupied_pixels = 0;
  int person_pixels = 0;
  int outside_pixels = 0;  // Valid but outside the image, below the floor or above max height.

  int width() const { return cells.cols; }
  int height() const { return cells.rows; }
  // The base-frame position (x forward, y left) of a cell's centre [m].
  Eigen::Vector2d CellCenter(int column, int row) const {
    return {(height() - row - 0.5) * cell_size_m, (0.5 * width() - column - 0.5) * cell_size_m};
  }
  // The cell holding a base-frame point, as continuous image coordinates (column, row).
  Eigen::Vector2d ToImage(const Eigen::Vector2d& p_in_base) const {
    return {0.5 * width() - p_in_base.y() / cell_size_m, height() - p_in_base.x() / cell_size_m};
  }
  OccupancyCell At(int column, int row) const {
    return static_cast<OccupancyCell>(cells.at<uint8_t>(row, column));
  }
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
