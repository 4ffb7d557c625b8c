#include "core/mapping/mapping_accuracy.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <opencv2/imgproc.hpp>

#include "core/common/text_file.h"

namespace sightline {

double TrueWall::AngleRad() const {
  const Eigen::Vector2d d = end - start;
  return WrapHalfTurn(std::atan2(d.y(), d.x()));
}

StatusOr<std::vector<TrueWall>> ReadWallsCsv(const std::string& path) {
  StatusOr<std::vector<DataLine>> lines = ReadDataLines(path);
  if (!lines.ok()) return lines.status();
  std::vector<TrueWall> walls;
  for (const DataLine& line : *lines) {
    StatusOr<std::vector<double>> v = ParseNumbers(line, 5, path);
    if (!v.ok()) return v.status();
    TrueWall wall;
    wall.id = static_cast<int>((*v)[0]);
    wall.start = Eigen::Vector2d((*v)[1], (*v)[2]);
    wall.end = Eigen::Vector2d((*v)[3], (*v)[4]);
    if (wall.LengthM() <= 0) {
      return ParseError(path + " line " + std::to_string(line.number) + ": wall has zero length");
    }
    walls.push_back(wall);
  }
  return walls;
}

HeadingErrors ComputeHeadingErrors(const std::vector<double>& estimate_rad,
                                   const std::vector<double>& truth_rad) {
  HeadingErrors errors;
  const size_t n = std::min(estimate_rad.size(), truth_rad.size());
  if (n == 0) return errors;
  double sum = 0;
  for (size_t k = 0; k < n; ++k) {
    const double e = std::abs(
        RadToDeg(WrapAngle((estimate_rad[k] - estimate_rad[0]) - (truth_rad[k] - truth_rad[0]))));
    errors.error_deg.push_back(e);
    sum += e;
    errors.max_deg = std::max(errors.max_deg, e);
  }
  errors.mean_deg = sum / n;
  errors.final_deg = errors.error_deg.back();
  return errors;
}

std::optional<WallMatch> MatchSegmentToWalls(const Eigen::Vector2d& start_in_world,
                                             const Eigen::Vector2d& end_in_world,
                                             const std::vector<TrueWall>& walls,
                                             double max_angle_deg, double max_distance_m) {
  const Eigen::Vector2d d = end_in_world - start_in_world;
  if (d.norm() < 1e-9) return std::nullopt;
  const double angle = std::atan2(d.y(), d.x());
  const Eigen::Vector2d mid = 0.5 * (start_in_world + end_in_world);
  std::optional<WallMatch> best;
  for (size_t i = 0; i < walls.size(); ++i) {
    const TrueWall& wall = walls[i];
    const double angle_error = std::abs(RadToDeg(WrapHalfTurn(angle - wall.AngleRad())));
    if (angle_error > max_angle_deg) continue;
    const Eigen::Vector2d dir = (wall.end - wall.start).normalized();
    const Eigen::Vector2d normal(-dir.y(), dir.x());
    const double distance = std::abs(normal.dot(mid - wall.start));
    if (distance > max_distance_m) continue;
    const double s = dir.dot(mid - wall.start);
    if (s < -max_distance_m || s > wall.LengthM() + max_distance_m) continue;
    // Prefer the nearest wall, then the best-aligned one.
    if (!best || distance + 0.01 * angle_error < best->distance_m + 0.01 * best->angle_error_deg) {
      best = WallMatch{static_cast<int>(i), angle_error, distance};
    }
  }
  return best;
}

std::vector<WallVisibility> VisibleWalls(const Pose2d& world_from_base, double fov_min_rad,
                                         double fov_max_rad, double resolution_rad,
                                         double max_range_m, const std::vector<TrueWall>& walls,
                                         const std::vector<TrueWall>& occluders) {
  std::vector<WallVisibility> result(walls.size());
  std::vector<double> s_min(walls.size(), 1e9), s_max(walls.size(), -1e9);
  const Eigen::Vector2d origin = world_from_base.position();
  for (double b = fov_min_rad; b <= fov_max_rad + 1e-12; b += resolution_rad) {
    const double a = world_from_base.heading_rad + b;
    const Eigen::Vector2d ray(std::cos(a), std::sin(a));
    double best_t = max_range_m;
    int best_wall = -1;
    double best_s = 0;
    for (size_t i = 0; i < walls.size(); ++i) {
      const Eigen::Vector2d e = walls[i].end - walls[i].start;
      const double det = ray.x() * (-e.y()) + ray.y() * e.x();
      if (std::abs(det) < 1e-12) continue;
      const Eigen::Vector2d q = walls[i].start - origin;
      const double t = (q.x() * (-e.y()) + q.y() * e.x()) / det;
      const double s = (ray.x() * q.y() - ray.y() * q.x()) / det;
      if (t <= 1e-6 || t >= best_t || s < 0 || s > 1) continue;
      best_t = t;
      best_wall = static_cast<int>(i);
      best_s = s;
    }
    for (const TrueWall& o : occluders) {
      const Eigen::Vector2d e = o.end - o.start;
      const double det = ray.x() * (-e.y()) + ray.y() * e.x();
      if (std::abs(det) < 1e-12) continue;
      const Eigen::Vector2d q = o.start - origin;
      const double t = (q.x() * (-e.y()) + q.y() * e.x()) / det;
      const double s = (ray.x() * q.y() - ray.y() * q.x()) / det;
      // An occluder lying on the wall itself (a poster) does not hide it.
      if (t > 1e-6 && t < best_t - 0.03 && s >= 0 && s <= 1) {
        best_wall = -1;
        break;
      }
    }
    if (best_wall < 0) continue;
    ++result[best_wall].rays;
    s_min[best_wall] = std::min(s_min[best_wall], best_s);
    s_max[best_wall] = std::max(s_max[best_wall], best_s);
  }
  std::vector<WallVisibility> seen;
  for (size_t i = 0; i < walls.size(); ++i) {
    if (result[i].rays == 0) continue;
    result[i].wall_index = static_cast<int>(i);
    result[i].visible_length_m = (s_max[i] - s_min[i]) * walls[i].LengthM();
    seen.push_back(result[i]);
  }
  return seen;
}

Pose2d AlignSe2(const std::vector<Eigen::Vector2d>& estimate,
                const std::vector<Eigen::Vector2d>& truth) {
  const size_t n = std::min(estimate.size(), truth.size());
  if (n < 2) return Pose2d();
  Eigen::Vector2d me = Eigen::Vector2d::Zero(), mt = Eigen::Vector2d::Zero();
  for (size_t i = 0; i < n; ++i) {
    me += estimate[i];
    mt += truth[i];
  }
  me /= n;
  mt /= n;
  double sxx = 0, sxy = 0, syx = 0, syy = 0;
  for (size_t i = 0; i < n; ++i) {
    const Eigen::Vector2d a = estimate[i] - me, b = truth[i] - mt;
    sxx += a.x() * b.x();
    sxy += a.x() * b.y();
    syx += a.y() * b.x();
    syy += a.y() * b.y();
  }
  const double angle = std::atan2(sxy - syx, sxx + syy);
  const double c = std::cos(angle), s = std::sin(angle);
  const Eigen::Vector2d t = mt - Eigen::Vector2d(c * me.x() - s * me.y(), s * me.x() + c * me.y());
  return Pose2d{t.x(), t.y(), angle};
}

MapAgreement CompareMapWithWalls(const OccupancyGridMap& map, const std::vector<TrueWall>& walls,
                                 const Pose2d& truth_from_estimate, int tolerance_cells) {
  MapAgreement agreement;
  if (map.empty()) return agreement;
  const int w = map.width(), h = map.height();
  cv::Mat truth(h, w, CV_8UC1, cv::Scalar(0)), occupied(h, w, CV_8UC1, cv::Scalar(0)),
      known(h, w, CV_8UC1, cv::Scalar(0));
  for (int iy = 0; iy < h; ++iy) {
    for (int ix = 0; ix < w; ++ix) {
      if (map.IsOccupied(ix, iy)) occupied.at<uint8_t>(iy, ix) = 255;
      if (map.IsKnown(ix, iy)) known.at<uint8_t>(iy, ix) = 255;
    }
  }
  // Walls into the map's frame: estimate_from_truth = inverse(truth_from_estimate).
  const double c = std::cos(truth_from_estimate.heading_rad);
  const double s = std::sin(truth_from_estimate.heading_rad);
  auto to_estimate = [&](const Eigen::Vector2d& p) {
    const Eigen::Vector2d q = p - truth_from_estimate.position();
    return Eigen::Vector2d(c * q.x() + s * q.y(), -s * q.x() + c * q.y());
  };
  const double step = 0.25 * map.resolution_m();
  for (const TrueWall& wall : walls) {
    const Eigen::Vector2d a = to_estimate(wall.start), b = to_estimate(wall.end);
    const int samples = static_cast<int>(std::ceil((b - a).norm() / step)) + 1;
    for (int k = 0; k <= samples; ++k) {
      const Eigen::Vector2i cell = map.CellOf(a + (b - a) * (static_cast<double>(k) / samples));
      if (cell.x() >= 0 && cell.y() >= 0 && cell.x() < w && cell.y() < h) {
        truth.at<uint8_t>(cell.y(), cell.x()) = 255;
      }
    }
  }
  const cv::Mat kernel = cv::getStructuringElement(
      cv::MORPH_RECT, cv::Size(2 * tolerance_cells + 1, 2 * tolerance_cells + 1));
  cv::Mat truth_near, occupied_near, known_near;
  cv::dilate(truth, truth_near, kernel);
  cv::dilate(occupied, occupied_near, kernel);
  cv::dilate(known, known_near, kernel);
  const cv::Mat observed_truth = truth & known_near;
  agreement.occupied_cells = cv::countNonZero(occupied);
  agreement.wall_cells = cv::countNonZero(observed_truth);
  if (agreement.occupied_cells == 0 || agreement.wall_cells == 0) return agreement;
  agreement.precision =
      static_cast<double>(cv::countNonZero(occupied & truth_near)) / agreement.occupied_cells;
  agreement.recall =
      static_cast<double>(cv::countNonZero(observed_truth & occupied_near)) / agreement.wall_cells;
  if (agreement.precision > 0 && agreement.recall > 0) {
    agreement.iou = 1.0 / (1.0 / agreement.precision + 1.0 / agreement.recall - 1.0);
  }
  return agreement;
}

}  // namespace sightline
