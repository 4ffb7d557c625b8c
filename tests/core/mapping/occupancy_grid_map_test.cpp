#include "core/mapping/occupancy_grid_map.h"

#include <gtest/gtest.h>

#include <fstream>
#include <opencv2/imgcodecs.hpp>
#include <sstream>

#include "tests/support/test_data.h"

namespace sightline {
namespace {

// A local image: free floor in front of the robot up to a wall 2 m ahead (row 300).
OccupancyImage WallAhead() {
  OccupancyImage image;
  image.cell_size_m = 0.02;
  image.cells = cv::Mat(400, 400, CV_8UC1, cv::Scalar(0));
  image.cells(cv::Rect(150, 301, 100, 99)).setTo(static_cast<int>(OccupancyCell::kFree));
  image.cells(cv::Rect(150, 300, 100, 1)).setTo(static_cast<int>(OccupancyCell::kOccupied));
  image.known_cells = cv::Rect(150, 300, 100, 100);
  return image;
}

TEST(OccupancyGridMap, WallLandsWhereThePoseSaysAndFloorIsFree) {
  OccupancyGridMap map;
  const Pose2d pose{5.0, -2.0, M_PI / 2};  // Facing world +y.
  // Free needs p < 0.196, i.e. four misses of -0.4; one hit of 0.85 makes a cell occupied.
  for (int k = 0; k < 4; ++k) ASSERT_TRUE(map.Insert(WallAhead(), pose).ok());
  // The wall 2 m ahead of (5, -2) facing +y lies at y = 0, x in 4 .. 6.
  for (double x = 4.1; x < 5.9; x += 0.1) {
    const Eigen::Vector2i wall = map.CellOf({x, -0.01});
    EXPECT_TRUE(map.IsOccupied(wall.x(), wall.y())) << x;
    const Eigen::Vector2i floor = map.CellOf({x, -1.0});
    EXPECT_TRUE(map.IsFree(floor.x(), floor.y())) << x;
  }
  const Eigen::Vector2i behind = map.CellOf({5.0, 0.5});
  EXPECT_FALSE(map.IsKnown(behind.x(), behind.y()));
  EXPECT_EQ(map.frames(), 4);
}

TEST(OccupancyGridMap, GrowsAndKeepsWhatItHad) {
  OccupancyGridMap map;
  ASSERT_TRUE(map.Insert(WallAhead(), Pose2d{0, 0, 0}).ok());
  ASSERT_TRUE(map.Insert(WallAhead(), Pose2d{0, 0, 0}).ok());
  const Eigen::Vector2d wall_point(1.99, 0.0);  // Local row 300 covers x in [1.98, 2.0).
  ASSERT_TRUE(map.IsOccupied(map.CellOf(wall_point).x(), map.CellOf(wall_point).y()));
  const int old_width = map.width();
  ASSERT_TRUE(map.Insert(WallAhead(), Pose2d{30, -20, M_PI}).ok());
  EXPECT_GT(map.width(), old_width);
  EXPECT_TRUE(map.IsOccupied(map.CellOf(wall_point).x(), map.CellOf(wall_point).y()));
  map.Clear();
  EXPECT_TRUE(map.empty());
}

TEST(OccupancyGridMap, FreeEvidenceErasesAStaleObstacle) {
  OccupancyGridMap map;
  ASSERT_TRUE(map.Insert(WallAhead(), Pose2d{0, 0, 0}).ok());
  // The wall moves 1 m further away; the old wall cells are seen free many times.
  OccupancyImage farther = WallAhead();
  farther.cells(cv::Rect(150, 250, 100, 51)).setTo(static_cast<int>(OccupancyCell::kFree));
  farther.cells(cv::Rect(150, 250, 100, 1)).setTo(static_cast<int>(OccupancyCell::kOccupied));
  farther.known_cells = cv::Rect(150, 250, 100, 150);
  for (int k = 0; k < 10; ++k) ASSERT_TRUE(map.Insert(farther, Pose2d{0, 0, 0}).ok());
  const Eigen::Vector2i old_wall = map.CellOf({2.005, 0.0});
  EXPECT_TRUE(map.IsFree(old_wall.x(), old_wall.y()));
}

TEST(OccupancyGridMap, RosExportFollowsMapServerConvention) {
  OccupancyGridMap map;
  for (int k = 0; k < 4; ++k) ASSERT_TRUE(map.Insert(WallAhead(), Pose2d{1.0, 2.0, 0.3}).ok());
  const std::string dir = testing::TempDir("grid_map");
  ASSERT_TRUE(map.SaveRos(dir, "map").ok());
  ASSERT_TRUE(map.SavePng(dir + "/map.png", {Pose2d{1.0, 2.0, 0.3}}).ok());
  const cv::Mat pgm = cv::imread(dir + "/map.pgm", cv::IMREAD_UNCHANGED);
  ASSERT_EQ(pgm.type(), CV_8UC1);
  EXPECT_EQ(pgm.cols, map.width());
  EXPECT_EQ(pgm.rows, map.height());
  // Values are 0 (occupied), 205 (unknown) or 254 (free), and row 0 is the top (largest y).
  const Eigen::Vector2i wall = map.CellOf(Pose2d{1.0, 2.0, 0.3}.Apply({2.01, 0.0}));
  EXPECT_EQ(pgm.at<uint8_t>(map.height() - 1 - wall.y(), wall.x()), 0);
  const Eigen::Vector2i floor = map.CellOf(Pose2d{1.0, 2.0, 0.3}.Apply({1.0, 0.0}));
  EXPECT_EQ(pgm.at<uint8_t>(map.height() - 1 - floor.y(), floor.x()), 254);
  EXPECT_EQ(pgm.at<uint8_t>(0, 0), 205);
  std::ifstream yaml(dir + "/map.yaml");
  std::stringstream text;
  text << yaml.rdbuf();
  EXPECT_NE(text.str().find("image: map.pgm"), std::string::npos);
  EXPECT_NE(text.str().find("resolution: 0.050000"), std::string::npos);
  EXPECT_NE(text.str().find("origin: ["), std::string::npos);
  EXPECT_NE(text.str().find("occupied_thresh: 0.650"), std::string::npos);
  EXPECT_NE(text.str().find("free_thresh: 0.196"), std::string::npos);
  EXPECT_NE(text.str().find("negate: 0"), std::string::npos);
  const cv::Mat png = cv::imread(dir + "/map.png");
  EXPECT_EQ(png.type(), CV_8UC3);
}

TEST(OccupancyGridMap, EmptyMapAndBadInputAreErrors) {
  OccupancyGridMap map;
  EXPECT_EQ(map.SaveRos(testing::TempDir("grid_empty")).code(), StatusCode::kFailedPrecondition);
  EXPECT_EQ(map.Insert(OccupancyImage(), Pose2d()).code(), StatusCode::kInvalidArgument);
  OccupancyImage unknown = WallAhead();
  unknown.cells.setTo(0);
  unknown.known_cells = cv::Rect();
  EXPECT_TRUE(map.Insert(unknown, Pose2d()).ok());
  EXPECT_TRUE(map.empty());
}

}  // namespace
}  // namespace sightline
