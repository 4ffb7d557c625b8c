#include "core/mapping/line_extractor.h"

#include <cmath>
#include <limits>

#include "core/mapping/pose2d.h"

namespace sightline {

bool FitLineTotalLeastSquares(const std::vector<Eigen::Vector2d>& points,
                              const std::vector<int>& indices, Eigen::Vector2d* normal,
                              double* offset) {
  if (indices.size() < 2) return false;
  Eigen::Vector2d mean = Eigen::Vector2d::Zero();
  for (int i : indices) mean += points[i];
  mean /= static_cast<double>(indices.size());
  double sxx = 0, sxy = 0, syy = 0;
  for (int i : indices) {
    const Eigen::Vector2d q = points[i] - mean;
    sxx += q.x() * q.x();
    sxy += q.x() * q.y();
    syy += q.y() * q.y();
  }
  if (sxx + syy < 1e-18) return false;
  // Direction of largest spread: angle 0.5 atan2(2 sxy, sxx - syy); the normal is perpendicular.
  const double theta = 0.5 * std::atan2(2 * sxy, sxx - syy);
  *normal = Eigen::Vector2d(-std::sin(theta), std::cos(theta));
  *offset = normal->dot(mean);
  return true;
}

WallSegment MakeWallSegment(const Eigen::Vector2d& normal, double offset,
                            const std::vector<Eigen::Vector2d>& points,
                            const std::vector<int>& inliers) {
  WallSegment line;
  line.normal = normal;
  line.offset_m = offset;
  const Eigen::Vector2d direction(-normal.y(), normal.x());
  double t_min = std::numeric_limits<double>::max(), t_max = -t_min, sum_sq = 0;
  for (int i : inliers) {
    const double t = direction.dot(points[i]);
    t_min = std::min(t_min, t);
    t_max = std::max(t_max, t);
    const double e = normal.dot(points[i]) - offset;
    sum_sq += e * e;
  }
  if (inliers.empty()) t_min = t_max = 0;
  line.start = offset * normal + t_min * direction;
  line.end = offset * normal + t_max * direction;
  line.length_m = t_max - t_min;
  line.angle_rad = WrapHalfTurn(std::atan2(direction.y(), direction.x()));
  line.inliers = static_cast<int>(inliers.size());
  line.rms_error_m = inliers.empty() ? 0 : std::sqrt(sum_sq / inliers.size());
  return line;
}

}  // namespace sightline
