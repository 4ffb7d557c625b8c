// What the indoor mapping chain produces, as plain data for views, writers and tests: the
// occupancy image, the polar scan, wall lines, the rotation estimate, person boxes and one frame's
// MappingFrameResult. The stages that make them live in their own headers
// (mapping_frame_processor.h and the stage headers it includes).
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cstdint>
#include <memory>
#include <opencv2/core.hpp>
#include <string>
#include <vector>

#include "core/common/frame.h"
#include "core/mapping/pose2d.h"

namespace sightline {

// A person's box in one image.
struct PersonBox {
  int id = -1;          // Ground-truth person id, or -1 for a detection.
  cv::Rect2d box;       // Pixels of the image it was found in.
  cv::Size image_size;  // Size of that image (boxes are scaled to the depth image).
  double score = 1;     // Detector confidence (1 for ground truth).
  // The whole body from the floor to the top of the head, in the same pixels, where a detector
  // in 3D knows it and it lies wholly in the image's rows; empty otherwise.
  cv::Rect2d body;

  // Factors (x, y) that take `box` into an image of `size`; 1 along an axis of unknown size.
  cv::Point2d ScaleTo(const cv::Size& size) const {
    return {image_size.width > 0 ? static_cast<double>(size.width) / image_size.width : 1.0,
            image_size.height > 0 ? static_cast<double>(size.height) / image_size.height : 1.0};
  }
};

// The label of one occupancy cell (the values stored in OccupancyImage::cells).
enum class OccupancyCell : uint8_t {
  kUnknown = 0,   // No depth reading fell into the cell.
  kFree = 1,      // Floor seen, nothing above it.
  kOccupied = 2,  // Something between epsilon_floor and max_height_m above the floor.
  kPerson = 3,    // Occupied by a person (excluded from scans and from the map's obstacles).
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

// One scan point: the nearest occupied cell along a ray.
struct ScanPoint {
  int ray = 0;                                   // Ray index (0 = rightmost).
  double bearing_rad = 0;                        // Counter-clockwise from forward.
  double range_m = 0;                            // Robot to cell centre [m].
  Eigen::Vector2d xy = Eigen::Vector2d::Zero();  // Cell centre in the base frame [m].
  cv::Point cell;                                // (column, row) in the occupancy image.
};

// One frame's scan. Points are ordered by bearing (right to left).
struct PolarScan {
  std::vector<ScanPoint> points;
  int rays_cast = 0;               // Rays inside the field of view.
  int rays_blocked_by_people = 0;  // Rays that passed a person's cells or footprint.
  double fov_min_rad = 0;          // Bearing range actually scanned.
  double fov_max_rad = 0;
  double resolution_rad = 0;
  double cell_size_m = 0;  // Of the occupancy image scanned.
  // "290 of 900 rays (0.2 deg over 180 deg) lie in the 57.9 deg field of view".
  std::string Describe() const;
};

// One wall line in the base frame (x forward, y left, metres).
struct WallSegment {
  Eigen::Vector2d normal = Eigen::Vector2d::UnitX();  // Unit normal n.
  double offset_m = 0;                                // d in n . x = d.
  Eigen::Vector2d start = Eigen::Vector2d::Zero();    // Extreme inlier projections onto the line.
  Eigen::Vector2d end = Eigen::Vector2d::Zero();
  double length_m = 0;     // |end - start|.
  double angle_rad = 0;    // Direction in [-pi/2, pi/2), counter-clockwise from forward.
  int inliers = 0;         // Scan points assigned to the line.
  double rms_error_m = 0;  // RMS point-to-line distance of the inliers [m].
  // Manhattan direction class, set by the rotation stage: 0 = parallel to the reference's first
  // wall direction, 1 = perpendicular to it, -1 = neither (or not yet classified).
  int direction_class = -1;

  // Signed distance of a point to the line [m].
  double Distance(const Eigen::Vector2d& p) const { return normal.dot(p) - offset_m; }
};

// Everything an extractor found in one scan.
struct LineExtraction {
  std::vector<WallSegment> lines;  // In the order they were found.
  std::vector<int> point_line;     // For each scan point: index into lines, or -1.
  int points = 0;                  // Scan points given.
  int assigned = 0;                // Points on some line.
  int iterations = 0;              // RANSAC hypotheses tried, or split-and-merge splits.
  std::string stop_reason;         // Why the extractor stopped, for people.
};

// The dominant wall direction of one frame.
struct ManhattanMeasurement {
  bool valid = false;
  double angle_rad = 0;      // m in [-pi/4, pi/4), base frame.
  double concentration = 0;  // In [0, 1]; 1 = all voting lines exactly Manhattan.
  double weight_m = 0;       // Summed vote weight (length x fit quality) of the voters [m].
  int voting_lines = 0;
  int rejected_lines = 0;       // Long enough but outside the gate or the trim.
  double trimmed_weight_m = 0;  // Length of the lines inside the gate that the trim dropped:
                                // a second, conflicting direction [m].
};

// One frame's rotation estimate.
struct RotationEstimate {
  double heading_rad = 0;            // The estimate: world_from_base heading.
  double predicted_heading_rad = 0;  // Previous estimate plus the pose source's turn.
  double correction_rad = 0;         // Applied correction (heading - predicted).
  double raw_correction_rad = 0;     // What the walls said, before gating and gain.
  double gate_rad = 0;               // The tracking gate of this frame (see the options).
  ManhattanMeasurement measurement;
  bool corrected = false;          // The walls corrected the heading.
  bool gated = false;              // The walls disagreed too much; not applied.
  bool reference_set = false;      // A reference direction exists (after this frame).
  double reference_angle_rad = 0;  // alpha_ref in [-pi/4, pi/4), world frame.
  bool reset = false;              // The reset rule fired on this frame.
  std::string reset_reason;        // Why, for the log.
  std::string status;              // "corrected", "no walls: dead reckoning", ...
};

// Per-stage durations of one frame [ms]; stages that did not run are 0.
struct MappingStageTimes {
  double people_ms = 0;
  double occupancy_ms = 0;
  double scan_ms = 0;
  double lines_ms = 0;
  double odometry_ms = 0;  // RGB-D odometry (only with mapping.pose.source rgbd).
  double rotation_ms = 0;
  double stitch_ms = 0;
  double total_ms = 0;  // All of the above.
};

// Everything one frame produced, immutable once returned, for the GUI to draw: the occupancy
// image (OccupancyCell values), the scan's rays (robot at occupancy.ToImage({0, 0}), each point's
// cell), the wall lines with their Manhattan direction class (base frame; occupancy.ToImage()
// turns their end points into image coordinates), the pose, and every few frames the global map
// with the trajectory. A busy view can draw the pose alone.
struct MappingFrameResult {
  FrameStamp stamp;
  std::vector<PersonBox> people;  // Boxes used (image pixels).
  std::string people_source;  // Where they came from: ground truth, depth, depth+hog, hog or none.
  OccupancyImage occupancy;
  PolarScan scan;
  LineExtraction lines;  // Base frame; direction_class set.
  RotationEstimate rotation;
  Pose2d pose;                   // world_from_base estimate.
  std::string pose_source;       // What gave the translation: recording, rgbd or none.
  std::string odometry_failure;  // Why the RGB-D odometry failed on this frame ("" = it did
                                 // not, or did not run); the position was then held.
  Eigen::Isometry3d world_from_camera = Eigen::Isometry3d::Identity();
  bool reset = false;        // The reset rule fired (rotation.reset_reason says why).
  bool map_cleared = false;  // ... and the map was started anew.
  std::string status;        // "ok" or what was degenerate ("no valid depth", ...).
  MappingStageTimes times;
  int64_t frame_index = 0;  // Frames processed before this one.
  // Every mapping.stitch.render_every_n frames (else null): the global map as BGR with the
  // trajectory in red; map_origin is the world position of its bottom-left corner.
  std::shared_ptr<const cv::Mat> map_image;
  // With map_image: the same map as the ROS map_server image (OccupancyGridMap::RenderGray: 0
  // occupied, 254 free, 205 unknown, row 0 the largest world y) and its thresholds.
  std::shared_ptr<const cv::Mat> map_gray;
  double map_occupied_threshold = 0.65;
  double map_free_threshold = 0.196;
  Eigen::Vector2d map_origin = Eigen::Vector2d::Zero();
  double map_resolution_m = 0;
  // With map_image: the estimated poses so far (world_from_base), to draw or plot.
  std::shared_ptr<const std::vector<Pose2d>> trajectory;
};

}  // namespace sightline
