#include "core/mapping/multi_line_ransac.h"

#include <gtest/gtest.h>

#include <cmath>

#include "core/mapping/pose2d.h"
#include "tests/core/mapping/scan_fixtures.h"

namespace sightline {
namespace {

using testing::ScanFixtureOptions;
using testing::ScanOfWalls;
using testing::ScanWall;

// Angle between two undirected line directions [deg].
double LineAngleErrorDeg(double a_rad, double b_rad) {
  return std::abs(RadToDeg(WrapHalfTurn(a_rad - b_rad)));
}

// The extracted line closest in direction and offset to a true wall, or nullptr.
const WallSegment* Match(const LineExtraction& lines, const ScanWall& wall) {
  const Eigen::Vector2d n(-std::sin(wall.angle_rad), std::cos(wall.angle_rad));
  const WallSegment* best = nullptr;
  double best_score = 1e9;
  for (const WallSegment& line : lines.lines) {
    const double angle = LineAngleErrorDeg(line.angle_rad, wall.angle_rad);
    const double offset = std::abs(std::abs(line.offset_m) - std::abs(n.dot(wall.point)));
    if (angle > 5 || offset > 0.15) continue;
    if (angle + 10 * offset < best_score) {
      best_score = angle + 10 * offset;
      best = &line;
    }
  }
  return best;
}

// A room corner 3 m ahead (bearing 5.7 deg): one wall at 20 deg, a perpendicular one at 110 deg.
std::vector<ScanWall> Corner() { return {{{3.0, 0.3}, DegToRad(110)}, {{3.0, 0.3}, DegToRad(20)}}; }

TEST(MultiLineRansac, FindsTwoPerpendicularWallsWithOutliers) {
  ScanFixtureOptions fixture;
  fixture.outlier_ratio = 0.15;
  const std::vector<Eigen::Vector2d> points = ScanOfWalls(Corner(), fixture);
  ASSERT_GT(points.size(), 250u);
  MultiLineRansac ransac;
  StatusOr<LineExtraction> lines = ransac.ExtractPoints(points, 0.02);
  ASSERT_TRUE(lines.ok()) << lines.status().ToString();
  for (const ScanWall& wall : Corner()) {
    const WallSegment* line = Match(*lines, wall);
    ASSERT_NE(line, nullptr) << "wall at " << RadToDeg(wall.angle_rad) << " deg not found";
    EXPECT_LT(LineAngleErrorDeg(line->angle_rad, wall.angle_rad), 0.5);
    EXPECT_GT(line->inliers, 30);
    EXPECT_GT(line->length_m, 0.5);
    EXPECT_NEAR(line->normal.norm(), 1.0, 1e-12);
    EXPECT_NEAR((line->end - line->start).norm(), line->length_m, 1e-9);
  }
  EXPECT_EQ(lines->point_line.size(), points.size());
  EXPECT_EQ(lines->points, static_cast<int>(points.size()));
  EXPECT_FALSE(lines->stop_reason.empty());
}

TEST(MultiLineRansac, SeedDefaults) {
  const MultiLineRansacOptions o;
  EXPECT_EQ(o.error_threshold_cells, 5);
  EXPECT_EQ(o.min_inlier_ratio, 0.2);
  EXPECT_EQ(o.early_exit_ratio, 0.5);
  EXPECT_EQ(o.max_iterations, 250);
  EXPECT_EQ(o.stop_assigned_ratio, 0.8);
  EXPECT_EQ(o.max_lines, 100);
  EXPECT_EQ(o.iterations, "fixed");
  EXPECT_EQ(o.best_by, "total_error");
}

TEST(MultiLineRansac, LineStraightAheadAndAlongTheRobot) {
  // A wall across the view (normal along x, the case y = m x + c cannot represent) and one
  // along the robot's direction of travel.
  const std::vector<ScanWall> walls = {{{4.0, 0.0}, DegToRad(90)}, {{0.0, -0.9}, 0.0}};
  const std::vector<Eigen::Vector2d> points = ScanOfWalls(walls, ScanFixtureOptions());
  MultiLineRansac ransac;
  StatusOr<LineExtraction> lines = ransac.ExtractPoints(points, 0.02);
  ASSERT_TRUE(lines.ok());
  for (const ScanWall& wall : walls) {
    const WallSegment* line = Match(*lines, wall);
    ASSERT_NE(line, nullptr) << RadToDeg(wall.angle_rad);
    EXPECT_LT(LineAngleErrorDeg(line->angle_rad, wall.angle_rad), 0.5);
  }
}

TEST(MultiLineRansac, StopsAtEightyPercentAssigned) {
  // One clean wall: its line takes > 80 % of the points, so step E ends after one line.
  const std::vector<Eigen::Vector2d> points =
      ScanOfWalls({{{3.0, 0.0}, DegToRad(95)}}, ScanFixtureOptions());
  MultiLineRansac ransac;
  StatusOr<LineExtraction> lines = ransac.ExtractPoints(points, 0.02);
  ASSERT_TRUE(lines.ok());
  ASSERT_EQ(lines->lines.size(), 1u);
  EXPECT_GT(lines->assigned, 0.8 * points.size());
  EXPECT_NE(lines->stop_reason.find("step E"), std::string::npos) << lines->stop_reason;
  // Early exit (> 50 % inliers) on the first good hypothesis: far fewer than 250 tried.
  EXPECT_LT(lines->iterations, 50);
}

TEST(MultiLineRansac, FixedCountRunsTwoHundredFiftyHypotheses) {
  // A corridor: the end wall 4 m ahead holds about 47 % of the points and each side wall about
  // 26 %, so the first line never exceeds ratio_max = 0.5 and all 250 hypotheses run.
  const std::vector<ScanWall> walls = {
      {{4.0, 0.0}, DegToRad(90)}, {{0.0, 1.0}, 0.0}, {{0.0, -1.0}, 0.0}};
  const std::vector<Eigen::Vector2d> points = ScanOfWalls(walls, ScanFixtureOptions());
  MultiLineRansac ransac;
  StatusOr<LineExtraction> lines = ransac.ExtractPoints(points, 0.02);
  ASSERT_TRUE(lines.ok());
  for (const ScanWall& wall : walls) EXPECT_NE(Match(*lines, wall), nullptr);
  EXPECT_GE(lines->iterations, 250);
}

TEST(MultiLineRansac, AdaptiveIterationCountFormula) {
  // k = ceil(log(1 - p) / log(1 - w^2)).
  EXPECT_EQ(AdaptiveIterationCount(0.99, 0.2), 113);
  EXPECT_EQ(AdaptiveIterationCount(0.99, 0.5), 17);
  EXPECT_EQ(AdaptiveIterationCount(0.99, 0.1), 459);
  EXPECT_EQ(AdaptiveIterationCount(0.99, 1.0), 1);
  for (double w : {0.1, 0.2, 0.3, 0.5, 0.8}) {
    const int k = AdaptiveIterationCount(0.99, w);
    EXPECT_GE(1 - std::pow(1 - w * w, k), 0.99) << w;
    EXPECT_LT(1 - std::pow(1 - w * w, k - 1), 0.99) << w;
  }
  // The seed's fixed 250 at w = 0.2 succeeds with probability 0.99996 (algorithms.md).
  EXPECT_NEAR(1 - std::pow(1 - 0.04, 250), 0.99996, 5e-6);
}

TEST(MultiLineRansac, AdaptiveModeFindsTheSameWallsWithFewerHypotheses) {
  // The corridor of FixedCountRunsTwoHundredFiftyHypotheses: no early exit for the first line,
  // so the fixed count runs 250 hypotheses where the adaptive one stops at
  // log(0.01) / log(1 - w^2) with w the best inlier ratio found (about 0.47: 19).
  const std::vector<ScanWall> walls = {
      {{4.0, 0.0}, DegToRad(90)}, {{0.0, 1.0}, 0.0}, {{0.0, -1.0}, 0.0}};
  ScanFixtureOptions fixture;
  fixture.outlier_ratio = 0.1;
  const std::vector<Eigen::Vector2d> points = ScanOfWalls(walls, fixture);
  MultiLineRansacOptions options;
  options.iterations = "adaptive";
  MultiLineRansac adaptive(options);
  StatusOr<LineExtraction> a = adaptive.ExtractPoints(points, 0.02);
  MultiLineRansac fixed;
  StatusOr<LineExtraction> f = fixed.ExtractPoints(points, 0.02);
  ASSERT_TRUE(a.ok() && f.ok());
  for (const ScanWall& wall : walls) {
    const WallSegment* line = Match(*a, wall);
    ASSERT_NE(line, nullptr) << RadToDeg(wall.angle_rad);
    EXPECT_LT(LineAngleErrorDeg(line->angle_rad, wall.angle_rad), 0.5);
  }
  EXPECT_LT(a->iterations, f->iterations / 2);
}

TEST(MultiLineRansac, DeterministicForASeed) {
  ScanFixtureOptions fixture;
  fixture.outlier_ratio = 0.2;
  const std::vector<Eigen::Vector2d> points = ScanOfWalls(Corner(), fixture);
  MultiLineRansac ransac;
  StatusOr<LineExtraction> first = ransac.ExtractPoints(points, 0.02);
  StatusOr<LineExtraction> second = ransac.ExtractPoints(points, 0.02);
  ASSERT_TRUE(first.ok() && second.ok());
  ASSERT_EQ(first->lines.size(), second->lines.size());
  for (size_t i = 0; i < first->lines.size(); ++i) {
    EXPECT_EQ(first->lines[i].angle_rad, second->lines[i].angle_rad);
    EXPECT_EQ(first->lines[i].inliers, second->lines[i].inliers);
  }
}

TEST(MultiLineRansac, TooFewPointsAndPureNoiseGiveNoLines) {
  MultiLineRansac ransac;
  StatusOr<LineExtraction> none = ransac.ExtractPoints({}, 0.02);
  ASSERT_TRUE(none.ok());
  EXPECT_TRUE(none->lines.empty());
  EXPECT_FALSE(none->stop_reason.empty());
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-3, 3);
  std::vector<Eigen::Vector2d> noise;
  for (int i = 0; i < 300; ++i) noise.emplace_back(u(rng) + 4, u(rng));
  StatusOr<LineExtraction> lines = ransac.ExtractPoints(noise, 0.02);
  ASSERT_TRUE(lines.ok());
  EXPECT_TRUE(lines->lines.empty()) << lines->lines.size() << " lines in uniform noise";
  EXPECT_NE(lines->stop_reason.find("step F"), std::string::npos) << lines->stop_reason;
}

TEST(MultiLineRansac, InvalidOptionsNameTheKey) {
  MultiLineRansacOptions options;
  options.iterations = "sometimes";
  std::string error;
  EXPECT_FALSE(options.IsValid(&error));
  EXPECT_NE(error.find("mapping.ransac.iterations"), std::string::npos);
  MultiLineRansac ransac(options);
  EXPECT_EQ(ransac.ExtractPoints({}, 0.02).status().code(), StatusCode::kInvalidArgument);
}

}  // namespace
}  // namespace sightline
