#include "core/mapping/split_and_merge.h"

#include <gtest/gtest.h>

#include <cmath>

#include "core/mapping/multi_line_ransac.h"
#include "core/mapping/pose2d.h"
#include "tests/core/mapping/scan_fixtures.h"

namespace sightline {
namespace {

using testing::ScanFixtureOptions;
using testing::ScanOfWalls;
using testing::ScanWall;

double LineAngleErrorDeg(double a_rad, double b_rad) {
  return std::abs(RadToDeg(WrapHalfTurn(a_rad - b_rad)));
}

const WallSegment* Match(const LineExtraction& lines, const ScanWall& wall) {
  const Eigen::Vector2d n(-std::sin(wall.angle_rad), std::cos(wall.angle_rad));
  for (const WallSegment& line : lines.lines) {
    if (LineAngleErrorDeg(line.angle_rad, wall.angle_rad) < 5 &&
        std::abs(std::abs(line.offset_m) - std::abs(n.dot(wall.point))) < 0.15) {
      return &line;
    }
  }
  return nullptr;
}

// A room corner 3 m ahead (bearing 5.7 deg): one wall at 20 deg, a perpendicular one at 110 deg.
std::vector<ScanWall> Corner() { return {{{3.0, 0.3}, DegToRad(110)}, {{3.0, 0.3}, DegToRad(20)}}; }

TEST(SplitAndMerge, FindsTwoPerpendicularWallsWithOutliers) {
  ScanFixtureOptions fixture;
  fixture.outlier_ratio = 0.05;
  const std::vector<Eigen::Vector2d> points = ScanOfWalls(Corner(), fixture);
  SplitAndMerge extractor;
  StatusOr<LineExtraction> lines = extractor.ExtractPoints(points, 0.02);
  ASSERT_TRUE(lines.ok()) << lines.status().ToString();
  for (const ScanWall& wall : Corner()) {
    const WallSegment* line = Match(*lines, wall);
    ASSERT_NE(line, nullptr) << "wall at " << RadToDeg(wall.angle_rad) << " deg not found";
    EXPECT_LT(LineAngleErrorDeg(line->angle_rad, wall.angle_rad), 0.5);
    EXPECT_GT(line->inliers, 30);
  }
  EXPECT_EQ(lines->point_line.size(), points.size());
}

TEST(SplitAndMerge, AgreesWithRansacOnACorridor) {
  const std::vector<ScanWall> walls = {
      {{4.0, 0.0}, DegToRad(90)}, {{0.0, 1.0}, 0.0}, {{0.0, -1.0}, 0.0}};
  const std::vector<Eigen::Vector2d> points = ScanOfWalls(walls, ScanFixtureOptions());
  SplitAndMerge split;
  MultiLineRansac ransac;
  StatusOr<LineExtraction> a = split.ExtractPoints(points, 0.02);
  StatusOr<LineExtraction> b = ransac.ExtractPoints(points, 0.02);
  ASSERT_TRUE(a.ok() && b.ok());
  for (const ScanWall& wall : walls) {
    const WallSegment* la = Match(*a, wall);
    const WallSegment* lb = Match(*b, wall);
    ASSERT_NE(la, nullptr);
    ASSERT_NE(lb, nullptr);
    EXPECT_LT(LineAngleErrorDeg(la->angle_rad, wall.angle_rad), 0.5);
    EXPECT_LT(LineAngleErrorDeg(la->angle_rad, lb->angle_rad), 0.5);
  }
}

TEST(SplitAndMerge, CollinearPiecesAcrossAGapMerge) {
  // One wall seen in two pieces (a doorway or a person in between).
  std::vector<Eigen::Vector2d> points;
  for (double y = -1.5; y < -0.3; y += 0.02) points.emplace_back(3.0, y);
  for (double y = 0.4; y < 1.5; y += 0.02) points.emplace_back(3.0, y);
  SplitAndMerge extractor;
  StatusOr<LineExtraction> lines = extractor.ExtractPoints(points, 0.02);
  ASSERT_TRUE(lines.ok());
  ASSERT_EQ(lines->lines.size(), 1u);
  EXPECT_EQ(lines->lines[0].inliers, static_cast<int>(points.size()));
  EXPECT_NEAR(lines->lines[0].length_m, 2.98, 0.03);
}

TEST(SplitAndMerge, EmptyAndTinyInput) {
  SplitAndMerge extractor;
  StatusOr<LineExtraction> none = extractor.ExtractPoints({}, 0.02);
  ASSERT_TRUE(none.ok());
  EXPECT_TRUE(none->lines.empty());
  StatusOr<LineExtraction> few = extractor.ExtractPoints({{1, 0}, {1, 0.1}}, 0.02);
  ASSERT_TRUE(few.ok());
  EXPECT_TRUE(few->lines.empty());
  EXPECT_EQ(extractor.ExtractPoints({}, 0).status().code(), StatusCode::kInvalidArgument);
}

}  // namespace
}  // namespace sightline
