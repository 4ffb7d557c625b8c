#include "core/sim/planar_path.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace sightline::sim {
namespace {

double Cross(const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  return a.x() * b.y() - a.y() * b.x();
}

}  // namespace

StatusOr<PlanarPath> PlanarPath::Through(const std::vector<Eigen::Vector2d>& input,
                                         double turn_radius_m, End end) {
  std::vector<Eigen::Vector2d> points;
  for (const Eigen::Vector2d& p : input) {
    if (points.empty() || (p - points.back()).norm() > 1e-9) points.push_back(p);
  }
  const bool closed = end == End::kLoop;
  if (closed && points.size() > 1 && (points.front() - points.back()).norm() < 1e-9) {
    points.pop_back();
  }
  if (points.size() < 2) return InvalidArgument("a path needs at least two distinct points");
  if (!(turn_radius_m >= 0)) return InvalidArgument("path turn radius must be >= 0");
  const size_t n = points.size();
  const size_t segments = closed ? n : n - 1;
  // Per corner: the tangent distance cut from both neighbouring segments.
  std::vector<double> cut(n, 0.0), turn(n, 0.0);
  for (size_t i = 0; i < n; ++i) {
    if (!closed && (i == 0 || i == n - 1)) continue;
    const Eigen::Vector2d in = (points[i] - points[(i + n - 1) % n]).normalized();
    const Eigen::Vector2d out = (points[(i + 1) % n] - points[i]).normalized();
    turn[i] = std::atan2(Cross(in, out), in.dot(out));
    cut[i] = turn_radius_m * std::tan(std::abs(turn[i]) / 2);
  }
  PlanarPath path;
  path.end_ = end;
  double s = 0;
  for (size_t k = 0; k < segments; ++k) {
    const size_t a = k, b = (k + 1) % n;
    const Eigen::Vector2d d = points[b] - points[a];
    const double length = d.norm() - cut[a] - cut[b];
    if (length < -1e-9) {
      return InvalidArgument("path turn of radius " + std::to_string(turn_radius_m) +
                             " m does not fit on the segment from point " + std::to_string(a) +
                             " to point " + std::to_string(b));
    }
    const Eigen::Vector2d dir = d / d.norm();
    Piece line;
    line.start_s = s;
    line.length = std::max(0.0, length);
    line.start = points[a] + cut[a] * dir;
    line.heading = std::atan2(dir.y(), dir.x());
    path.pieces_.push_back(line);
    s += line.length;
    if (cut[b] > 0 && (closed || b != 0)) {
      Piece arc;
      arc.arc = true;
      arc.start_s = s;
      arc.radius = turn_radius_m;
      arc.turn = turn[b];
      arc.length = turn_radius_m * std::abs(turn[b]);
      arc.heading = line.heading;
      const Eigen::Vector2d start = points[b] - cut[b] * dir;
      const Eigen::Vector2d left(-dir.y(), dir.x());
      arc.start = start;
      arc.center = start + (turn[b] > 0 ? 1.0 : -1.0) * turn_radius_m * left;
      path.pieces_.push_back(arc);
      s += arc.length;
    }
  }
  path.length_m_ = s;
  if (!(s > 0)) return InvalidArgument("path has zero length");
  return path;
}

PathPose PlanarPath::AtWithin(double s) const {
  auto it = std::upper_bound(pieces_.begin(), pieces_.end(), s,
                             [](double v, const Piece& p) { return v < p.start_s; });
  const Piece& p = *(it == pieces_.begin() ? it : std::prev(it));
  const double u = std::clamp(s - p.start_s, 0.0, p.length);
  PathPose pose;
  if (!p.arc) {
    pose.heading_rad = p.heading;
    pose.position = p.start + u * Eigen::Vector2d(std::cos(p.heading), std::sin(p.heading));
    return pose;
  }
  const double sign = p.turn > 0 ? 1.0 : -1.0;
  const double angle = u / p.radius;
  pose.heading_rad = p.heading + sign * angle;
  // The start point rotated about the centre by the travelled angle.
  const Eigen::Vector2d r0 = p.start - p.center;
  const double c = std::cos(sign * angle), sn = std::sin(sign * angle);
  pose.position = p.center + Eigen::Vector2d(c * r0.x() - sn * r0.y(), sn * r0.x() + c * r0.y());
  return pose;
}

PathPose PlanarPath::At(double s) const {
  if (pieces_.empty()) return {};
  const double length = length_m_;
  switch (end_) {
    case End::kStop:
      return AtWithin(std::clamp(s, 0.0, length));
    case End::kLoop: {
      double u = std::fmod(s, length);
      if (u < 0) u += length;
      return AtWithin(u);
    }
    case End::kPingPong: {
      double u = std::fmod(s, 2 * length);
      if (u < 0) u += 2 * length;
      if (u <= length) return AtWithin(u);
      PathPose back = AtWithin(2 * length - u);
      back.heading_rad += M_PI;
      return back;
    }
  }
  return {};
}

}  // namespace sightline::sim
