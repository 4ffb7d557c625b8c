#include "core/sim/planar_path.h"

#include <gtest/gtest.h>

#include <cmath>

namespace sightline::sim {
namespace {

TEST(PlanarPath, StraightLineIsParametrisedByArcLength) {
  auto path = PlanarPath::Through({{0, 0}, {4, 0}}, 0.5, PlanarPath::End::kStop);
  ASSERT_TRUE(path.ok()) << path.status().ToString();
  EXPECT_DOUBLE_EQ(path->LengthM(), 4.0);
  const PathPose p = path->At(1.5);
  EXPECT_NEAR(p.position.x(), 1.5, 1e-12);
  EXPECT_NEAR(p.position.y(), 0.0, 1e-12);
  EXPECT_NEAR(p.heading_rad, 0.0, 1e-12);
  EXPECT_NEAR(path->At(10).position.x(), 4.0, 1e-12);  // Stops at the end.
}

TEST(PlanarPath, RightAngleTurnIsAQuarterCircle) {
  const double r = 0.5;
  auto path = PlanarPath::Through({{0, 0}, {4, 0}, {4, 3}}, r, PlanarPath::End::kStop);
  ASSERT_TRUE(path.ok());
  // Two straights shortened by r each, plus a quarter circle.
  EXPECT_NEAR(path->LengthM(), 4 - r + 3 - r + M_PI / 2 * r, 1e-12);
  // Half way round the turn: on the circle around (4 - r, r), heading 45 deg.
  const PathPose mid = path->At(4 - r + M_PI / 4 * r);
  EXPECT_NEAR((mid.position - Eigen::Vector2d(4 - r, r)).norm(), r, 1e-12);
  EXPECT_NEAR(mid.heading_rad, M_PI / 4, 1e-12);
  const PathPose end = path->At(path->LengthM());
  EXPECT_NEAR(end.position.x(), 4, 1e-12);
  EXPECT_NEAR(end.position.y(), 3, 1e-12);
  EXPECT_NEAR(end.heading_rad, M_PI / 2, 1e-12);
}

TEST(PlanarPath, LoopWrapsAndPingPongWalksBack) {
  auto loop =
      PlanarPath::Through({{1, 0}, {4, 0}, {4, 4}, {0, 4}, {0, 0}}, 0.5, PlanarPath::End::kLoop);
  ASSERT_TRUE(loop.ok());
  const PathPose a = loop->At(0.3), b = loop->At(0.3 + loop->LengthM());
  EXPECT_NEAR((a.position - b.position).norm(), 0, 1e-9);
  EXPECT_NEAR(loop->At(0).position.x(), 1, 1e-12);

  auto pingpong = PlanarPath::Through({{0, 0}, {2, 0}}, 0, PlanarPath::End::kPingPong);
  ASSERT_TRUE(pingpong.ok());
  const PathPose back = pingpong->At(3);
  EXPECT_NEAR(back.position.x(), 1, 1e-12);
  EXPECT_NEAR(std::cos(back.heading_rad), -1, 1e-12);
}

TEST(PlanarPath, RejectsTurnsThatDoNotFit) {
  auto path = PlanarPath::Through({{0, 0}, {1, 0}, {1, 1}, {3, 1}}, 0.8, PlanarPath::End::kStop);
  ASSERT_FALSE(path.ok());
  EXPECT_NE(path.status().message().find("does not fit"), std::string::npos)
      << path.status().message();
  EXPECT_FALSE(PlanarPath::Through({{0, 0}}, 0.1, PlanarPath::End::kStop).ok());
}

}  // namespace
}  // namespace sightline::sim
