// People found in the depth image alone, standing on the calibrated floor: the idea of PCL's
// ground-based people detection (Munaro and Menegatti: remove the ground, cluster what stands
// on it, split clusters at their heads, keep the ones of a person's height and width), done on
// a floor grid instead of a k-d tree so it costs about a millisecond per frame.
//
//  1. Every sampled depth pixel becomes a point; its height above the floor and its place on
//     the floor (forward, left) put it into a cell of a floor grid (depth_cell_m).
//  2. Occupied cells are joined into clusters (8-neighbours).
//  3. A cluster longer than a person is split at its heads: cells at least depth_min_height_m
//     high whose top is the highest within depth_head_radius_m, with a dip of
//     depth_head_drop_m between any two (a neck, shoulders, the gap between two people; the
//     cut-off top of a wall is flat). Every cell goes to the nearest head. A single head that
//     stands that much above everything one to two head radii around it (a person beside a bin
//     or a wall) keeps the cells within half a person's width.
//  4. A cluster (or part) is a person when its top lies in [depth_min_height_m,
//     depth_max_height_m], its footprint in [depth_min_width_m, depth_max_width_m] and its top
//     depth_min_height_to_length footprint lengths high (a desk is wider than tall), its
//     lowest point within depth_max_foot_m of the floor (it stands there), it has
//     depth_min_points points, and nothing taller stands in its cells (a wall or a pillar that
//     goes on upward).
//  5. Its box is the bounding box of its pixels.
// Clusters touching the image's top rows count too: a person close to the camera has the head
// cut off, and walls stay out by their length or their height where seen. Depth alone cannot
// tell a high-backed chair from a child; MappingFrameProcessor checks each box with HOG on the
// colour image when it has one (mapping.people.depth_hog_check).
#pragma once

#include <Eigen/Core>
#include <opencv2/core.hpp>
#include <vector>

#include "core/common/camera.h"
#include "core/common/floor.h"
#include "core/common/status.h"
#include "core/mapping/mapping_types.h"
#include "core/mapping/person_boxes.h"

namespace sightline {

// Finds people in depth frames of one camera above one floor. Configure() once, then
// Detect() per frame; not thread-safe (it reuses its grids).
//
//   DepthPersonDetector detector(options.people);
//   SIGHTLINE_RETURN_IF_ERROR(detector.Configure(floor, camera));
//   StatusOr<std::vector<PersonBox>> people = detector.Detect(frame.depth_m);
class DepthPersonDetector {
 public:
  explicit DepthPersonDetector(PersonDetectorOptions options = {});

  // Fails on invalid options, plane or camera, or a camera looking straight down.
  Status Configure(const FloorPlane& floor, const PinholeCamera& camera);
  // People in a metric depth image (CV_32FC1, NaN or <= 0 = invalid) of the configured camera
  // (or a scaled copy of it). Boxes are in that image's pixels, id -1, score 1; `body` spans the
  // floor to the top of the head when both are in view (empty otherwise).
  StatusOr<std::vector<PersonBox>> Detect(const cv::Mat& depth_m);

 private:
  struct Cell {
    int points = 0;
    float top = -1e9f, bottom = 1e9f;
    int u0 = 1 << 30, v0 = 1 << 30, u1 = -1, v1 = -1;
  };
  // The image box from the floor under `centre` (forward, left) to height_m above it, over the
  // columns of `box`; empty when it leaves the image's rows.
  cv::Rect2d BodyBox(const PinholeCamera& cam, const Eigen::Vector2d& centre, double height_m,
                     const cv::Rect2d& box) const;

  PersonDetectorOptions options_;
  bool configured_ = false;
  FloorPlane floor_;
  PinholeCamera camera_;
  Eigen::Vector3d forward_, left_, up_;
  int grid_rows_ = 0, grid_cols_ = 0;  // Forward x left cells.
  std::vector<Cell> cells_;
  std::vector<int> used_;  // Cells holding points, in the order they were first hit.
  std::vector<int> label_;
};

}  // namespace sightline
