// Wall lines from a polar scan: the common result type, the extractor interface (multi-line
// RANSAC as in the seed, split-and-merge to compare) and the line-fitting helpers they share.
//
// Lines use the normal form n . x = d (unit n), which handles every direction alike; the seed's
// switch between y = m x + c and x = m y + c is not needed.
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "core/common/status.h"
#include "core/mapping/polar_scan.h"

namespace sightline {

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

// A line extractor. Not thread-safe (RANSAC keeps its random generator and scratch buffers);
// deterministic for a given seed and input.
class LineExtractor {
 public:
  virtual ~LineExtractor() = default;
  // "multi_line_ransac", "split_and_merge".
  virtual const char* name() const = 0;
  // The wall lines of one scan. A scan with too few points gives no lines, not an error.
  virtual StatusOr<LineExtraction> Extract(const PolarScan& scan) = 0;
};

// Total least-squares line through the points `indices` of `points`: fills normal and offset.
// False with fewer than 2 points or all points coincident.
bool FitLineTotalLeastSquares(const std::vector<Eigen::Vector2d>& points,
                              const std::vector<int>& indices, Eigen::Vector2d* normal,
                              double* offset);

// A WallSegment for a line and its inliers: end points, length, angle, RMS error.
WallSegment MakeWallSegment(const Eigen::Vector2d& normal, double offset,
                            const std::vector<Eigen::Vector2d>& points,
                            const std::vector<int>& inliers);

}  // namespace sightline
