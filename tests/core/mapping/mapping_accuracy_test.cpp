#include "core/mapping/mapping_accuracy.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

#include "tests/support/test_data.h"

namespace sightline {
namespace {

TEST(MappingAccuracy, AlignSe2RecoversAKnownTransform) {
  const Pose2d truth_from_estimate{1.5, -2.0, DegToRad(30)};
  std::vector<Eigen::Vector2d> estimate, truth;
  for (int i = 0; i < 20; ++i) {
    estimate.emplace_back(0.3 * i, std::sin(0.4 * i));
    truth.push_back(truth_from_estimate.Apply(estimate.back()));
  }
  const Pose2d found = AlignSe2(estimate, truth);
  EXPECT_NEAR(found.x, 1.5, 1e-9);
  EXPECT_NEAR(found.y, -2.0, 1e-9);
  EXPECT_NEAR(RadToDeg(found.heading_rad), 30.0, 1e-9);
}

TEST(MappingAccuracy, HeadingErrorsAreRelativeToTheFirstFrame) {
  const HeadingErrors e = ComputeHeadingErrors({1.0, 1.1, 1.0 + M_PI}, {0.0, 0.12, M_PI - 0.02});
  ASSERT_EQ(e.error_deg.size(), 3u);
  EXPECT_NEAR(e.error_deg[0], 0.0, 1e-9);
  EXPECT_NEAR(e.error_deg[1], RadToDeg(0.02), 1e-9);
  EXPECT_NEAR(e.error_deg[2], RadToDeg(0.02), 1e-9);  // Across the +-180 deg wrap.
  EXPECT_NEAR(e.max_deg, RadToDeg(0.02), 1e-9);
}

TEST(MappingAccuracy, SegmentsMatchTheirWall) {
  const std::vector<TrueWall> walls = {{0, {0, 1}, {10, 1}}, {1, {10, 1}, {10, 5}}};
  auto match = MatchSegmentToWalls({2, 1.05}, {4, 1.05 + 2 * std::tan(DegToRad(0.4))}, walls);
  ASSERT_TRUE(match.has_value());
  EXPECT_EQ(match->wall_index, 0);
  EXPECT_NEAR(match->angle_error_deg, 0.4, 1e-6);
  EXPECT_FALSE(MatchSegmentToWalls({2, 2.0}, {4, 2.0}, walls).has_value());  // 1 m off.
  EXPECT_FALSE(MatchSegmentToWalls({2, 1.0}, {4, 1.7}, walls).has_value());  // 19 deg off.
}

TEST(MappingAccuracy, VisibleWallsRespectOcclusion) {
  // A wall 3 m ahead across the view, and a box face in front of its left half.
  const std::vector<TrueWall> walls = {{0, {3, -3}, {3, 3}}};
  const Pose2d pose{0, 0, 0};
  const auto all = VisibleWalls(pose, DegToRad(-30), DegToRad(30), DegToRad(0.2), 5.0, walls);
  ASSERT_EQ(all.size(), 1u);
  EXPECT_EQ(all[0].rays, 301);
  EXPECT_NEAR(all[0].visible_length_m, 2 * 3 * std::tan(DegToRad(30)), 0.02);
  const auto half = VisibleWalls(pose, DegToRad(-30), DegToRad(30), DegToRad(0.2), 5.0, walls,
                                 {{9, {1, 0}, {1, 2}}});
  ASSERT_EQ(half.size(), 1u);
  EXPECT_NEAR(half[0].rays, 151, 2);
  EXPECT_TRUE(VisibleWalls(pose, DegToRad(-30), DegToRad(30), DegToRad(0.2), 2.0, walls).empty());
}

TEST(MappingAccuracy, MapAgreementOfAPerfectAndAShiftedMap) {
  // A map built from a local image whose wall lies exactly on a true wall.
  OccupancyImage image;
  image.cell_size_m = 0.02;
  image.cells = cv::Mat(400, 400, CV_8UC1, cv::Scalar(0));
  image.cells(cv::Rect(100, 301, 200, 99)).setTo(static_cast<int>(OccupancyCell::kFree));
  image.cells(cv::Rect(100, 300, 200, 1)).setTo(static_cast<int>(OccupancyCell::kOccupied));
  image.known_cells = cv::Rect(100, 300, 200, 100);
  OccupancyGridMap map;
  for (int k = 0; k < 3; ++k) ASSERT_TRUE(map.Insert(image, Pose2d{}).ok());
  const std::vector<TrueWall> walls = {{0, {1.99, -2}, {1.99, 2}}};
  const MapAgreement same = CompareMapWithWalls(map, walls, Pose2d(), 1);
  EXPECT_GT(same.precision, 0.99);
  EXPECT_GT(same.recall, 0.95);
  EXPECT_GT(same.iou, 0.95);
  // The truth 30 cm away: nothing matches.
  const MapAgreement shifted = CompareMapWithWalls(map, walls, Pose2d{0.3, 0, 0}, 1);
  EXPECT_LT(shifted.iou, 0.05);
}

TEST(MappingAccuracy, WallsCsvErrorsNameTheLine) {
  const std::string dir = testing::TempDir("walls_csv");
  {
    std::ofstream out(dir + "/walls.csv");
    out << "# wall,x1,y1,x2,y2,a,b,c\n0,0,1,10,1,0,-1,1\n1,10,1,ten,5,1,0,-10\n";
  }
  StatusOr<std::vector<TrueWall>> walls = ReadWallsCsv(dir + "/walls.csv");
  ASSERT_FALSE(walls.ok());
  EXPECT_NE(walls.status().message().find("line 3"), std::string::npos) << walls.status().message();
  {
    std::ofstream out(dir + "/walls.csv");
    out << "# wall,x1,y1,x2,y2,a,b,c\n0,0,1,10,1,0,-1,1\n";
  }
  walls = ReadWallsCsv(dir + "/walls.csv");
  ASSERT_TRUE(walls.ok());
  ASSERT_EQ(walls->size(), 1u);
  EXPECT_NEAR((*walls)[0].LengthM(), 10.0, 1e-12);
}

}  // namespace
}  // namespace sightline
