// Paths on the floor made of straight lines and circular turns, parametrised by arc length:
// the robot's drive through the corridor and the walking people's routes.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "core/common/status.h"

namespace sightline::sim {

// A position and heading on a planar path.
struct PathPose {
  Eigen::Vector2d position = Eigen::Vector2d::Zero();  // Map frame x, y in metres.
  double heading_rad = 0;  // Direction of travel, counter-clockwise from the map's x axis.
};

// Straight segments joined by arcs of a fixed radius at each corner (fillets), so the heading is
// continuous. Positions beyond the end follow End: stop, loop (closed paths) or walk back.
//
//   auto path = PlanarPath::Through({{0, 0}, {6, 0}, {6, 4}}, 0.6, PlanarPath::End::kStop);
//   PathPose p = path->At(0.5 * t);  // 0.5 m/s
class PlanarPath {
 public:
  // What happens past the last point.
  enum class End { kStop, kLoop, kPingPong };

  PlanarPath() = default;

  // A path through `waypoints` with turns of `turn_radius_m` at the corners. For kLoop the path
  // closes back to the first waypoint; the first waypoint must then lie on a straight stretch
  // (collinear with its neighbours) or the loop starts inside a turn. InvalidArgument when
  // fewer than two distinct points are given or a turn does not fit between its neighbours.
  static StatusOr<PlanarPath> Through(const std::vector<Eigen::Vector2d>& waypoints,
                                      double turn_radius_m, End end);

  // Length of one pass in metres.
  double LengthM() const { return length_m_; }
  // The pose at arc length `s_m` from the start (any value; see End).
  PathPose At(double s_m) const;

 private:
  struct Piece {
    double start_s = 0, length = 0;
    bool arc = false;
    Eigen::Vector2d start = Eigen::Vector2d::Zero();   // Lines: start point.
    double heading = 0;                                // Lines: direction; arcs: start heading.
    Eigen::Vector2d center = Eigen::Vector2d::Zero();  // Arcs.
    double radius = 0;
    double turn = 0;  // Arcs: signed heading change (rad), positive = left.
  };
  PathPose AtWithin(double s_m) const;

  std::vector<Piece> pieces_;
  double length_m_ = 0;
  End end_ = End::kStop;
};

}  // namespace sightline::sim
