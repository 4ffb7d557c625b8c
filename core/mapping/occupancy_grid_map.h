// Map stitching: occupancy images placed with the estimated pose into one global occupancy grid
// (log-odds, Moravec and Elfes), exported as map.pgm + map.yaml in the ROS map_server convention
// and as PNG.
#pragma once

#include <Eigen/Core>
#include <opencv2/core.hpp>
#include <string>
#include <vector>

#include "core/common/status.h"
#include "core/mapping/occupancy_image.h"
#include "core/mapping/polar_scan.h"
#include "core/mapping/pose2d.h"
#include "core/options/option_table.h"

namespace sightline {

// Options of the global map. Keys "mapping.stitch.*".
struct OccupancyGridMapOptions {
  double resolution_m = 0.05;   // Global cell edge [m].
  double hit_log_odds = 0.85;   // Added when a frame sees a cell occupied (log(0.7/0.3)).
  double miss_log_odds = -0.4;  // Added when a frame sees a cell free.
  double min_log_odds = -2.0;   // Clamp, so that the map can change its mind.
  double max_log_odds = 3.5;
  double occupied_threshold = 0.65;    // ROS map_server occupied_thresh (probability).
  double free_threshold = 0.196;       // ROS map_server free_thresh (probability).
  bool clear_on_reset = true;          // Start a new map when the reset rule fires (seed).
  std::string occupied_from = "scan";  // Occupied evidence: "scan" (the polar scan's nearest
                                       // hits: visible surfaces) or "image" (every occupied
                                       // cell of the occupancy image, as the seed stitches).
  double grow_margin_m = 4.0;          // The grid grows by at least this much when it must [m].
  int render_every_n = 0;  // Frame results carry a rendered map every n frames (0: never;
                           // the GUI sets it).

  bool IsValid(std::string* error) const;
  static OptionTable<OccupancyGridMapOptions> Describe();
};

// The global log-odds grid. Cell (ix, iy) covers world x in origin.x + [ix, ix + 1) * resolution
// and y likewise; it grows as the robot explores.
//
//   OccupancyGridMap map(options);
//   map.Insert(image, world_from_base);
//   map.SaveRos(out_dir, "map");  // map.pgm + map.yaml
class OccupancyGridMap {
 public:
  explicit OccupancyGridMap(OccupancyGridMapOptions options = {});

  // Adds one occupancy image seen from `world_from_base`. Occupied evidence is forward-mapped
  // (no thin wall is missed): with occupied_from = "scan" and a `surface` scan, only the scan's
  // hits (the first occupied cell along each ray), else every occupied cell of the image. The
  // image's occupied cells include depth noise behind each surface that no later frame can see
  // free, which thickens walls by a cell or two; the scan's hits do not. Free cells are sampled
  // at each global cell's centre; person and unknown cells leave the map unchanged.
  Status Insert(const OccupancyImage& image, const Pose2d& world_from_base,
                const PolarScan* surface = nullptr);
  // Forgets everything (after a reset).
  void Clear();

  bool empty() const { return log_odds_.empty(); }
  int width() const { return log_odds_.cols; }
  int height() const { return log_odds_.rows; }
  double resolution_m() const { return options_.resolution_m; }
  // World position of the lower-left corner of cell (0, 0) [m].
  Eigen::Vector2d origin() const { return origin_; }
  // Log-odds per cell, CV_32FC1, row = iy (world y grows with the row index).
  const cv::Mat& log_odds() const { return log_odds_; }
  // Frames inserted since the last Clear().
  int frames() const { return frames_; }

  // Cell of a world point (may lie outside the grid).
  Eigen::Vector2i CellOf(const Eigen::Vector2d& p_in_world) const;
  Eigen::Vector2d CellCenter(int ix, int iy) const;
  // Occupancy probability of a cell's log-odds.
  static double Probability(float log_odds);
  bool IsOccupied(int ix, int iy) const;
  bool IsFree(int ix, int iy) const;
  bool IsKnown(int ix, int iy) const;  // Observed at least once.

  // The map as the ROS map_server image: 0 occupied, 254 free, 205 unknown; row 0 is the top
  // (largest world y), as map_server expects.
  cv::Mat RenderGray() const;
  // A BGR picture for people and the GUI: the gray map with the trajectory drawn in red.
  cv::Mat RenderBgr(const std::vector<Pose2d>& trajectory) const;
  // Writes DIR/NAME.pgm and DIR/NAME.yaml (image, resolution, origin, negate, occupied_thresh,
  // free_thresh). Fails on an empty map or a write error, naming the file.
  Status SaveRos(const std::string& dir, const std::string& name = "map") const;
  // Writes RenderBgr(trajectory) as a PNG.
  Status SavePng(const std::string& path, const std::vector<Pose2d>& trajectory = {}) const;

  const OccupancyGridMapOptions& options() const { return options_; }

 private:
  // Makes sure the world box [lo, hi] lies inside the grid.
  void Cover(const Eigen::Vector2d& lo, const Eigen::Vector2d& hi);

  OccupancyGridMapOptions options_;
  cv::Mat log_odds_;  // CV_32FC1.
  cv::Mat stamps_;    // CV_32SC1: the frame that last marked the cell occupied.
  cv::Mat observed_;  // CV_8UC1: 1 once observed.
  Eigen::Vector2d origin_ = Eigen::Vector2d::Zero();
  int frames_ = 0;
  int stamp_ = 0;
};

}  // namespace sightline
