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
#include "core/mapping/mapping_types.h"
#include "core/mapping/polar_scan.h"

namespace sightline {

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
