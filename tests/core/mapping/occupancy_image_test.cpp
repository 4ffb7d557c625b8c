#include "core/mapping/occupancy_image.h"

#include <gtest/gtest.h>

#include <cmath>

#include "core/mapping/pose2d.h"
#include "tests/core/mapping/synthetic_scene.h"

namespace sightline {
namespace {

using testing::FloorPlaneOf;
using testing::KinectCamera;
using testing::RenderDepth;
using testing::SyntheticView;

int Count(const OccupancyImage& image, OccupancyCell label) {
  return cv::countNonZero(image.cells == static_cast<uint8_t>(label));
}

// A floor and one wall 3 m ahead, perpendicular to the view.
class OccupancyFloorAndWall : public ::testing::Test {
 protected:
  void SetUp() override {
    view_.height_m = 0.8;
    view_.pitch_down_rad = DegToRad(10);
    camera_ = KinectCamera(320, 240);
    depth_ = RenderDepth(camera_, view_, {{{3.0, -4}, {3.0, 4}, 2.0}});
    ASSERT_TRUE(builder_.Configure(FloorPlaneOf(view_), camera_).ok());
  }
  SyntheticView view_;
  PinholeCamera camera_;
  cv::Mat depth_;
  OccupancyImageBuilder builder_;
};

TEST_F(OccupancyFloorAndWall, WallCellsAreOccupiedFloorIsFree) {
  StatusOr<OccupancyImage> image = builder_.Build(depth_, {});
  ASSERT_TRUE(image.ok()) << image.status().ToString();
  ASSERT_EQ(image->width(), 400);
  ASSERT_EQ(image->height(), 400);
  // The wall at x = 3 m lies in row 400 - 3 / 0.02 = 250; every occupied cell is on it.
  int occupied = 0;
  for (int r = 0; r < image->height(); ++r) {
    for (int c = 0; c < image->width(); ++c) {
      if (image->At(c, r) != OccupancyCell::kOccupied) continue;
      ++occupied;
      EXPECT_NEAR(image->CellCenter(c, r).x(), 3.0, 0.03) << "cell " << c << ", " << r;
    }
  }
  // The wall spans the field of view: 2 * 3 m * tan(31.4 deg) = 3.66 m = 183 cells.
  EXPECT_GT(occupied, 170);
  // Floor between the robot and the wall: free; beyond the wall: unknown.
  EXPECT_EQ(image->At(200, 300), OccupancyCell::kFree);     // x = 2 m, y = 0.
  EXPECT_EQ(image->At(200, 200), OccupancyCell::kUnknown);  // x = 4 m, behind the wall.
  EXPECT_GT(Count(*image, OccupancyCell::kFree), 5000);
  EXPECT_EQ(image->invalid_pixels, 0);
  EXPECT_EQ(image->sampled_pixels, 320 * 240);
  EXPECT_GT(image->floor_pixels, 0);
  EXPECT_GT(image->occupied_pixels, 0);
  // The field of view on the floor: at least the image's 2 atan(160 / 262.5) = 62.7 deg, a
  // little wider because the pitched camera's bottom corners look further sideways; symmetric.
  const double fov_deg = RadToDeg(builder_.fov_max_rad() - builder_.fov_min_rad());
  EXPECT_GT(fov_deg, 62.7);
  EXPECT_LT(fov_deg, 70.0);
  EXPECT_NEAR(builder_.fov_max_rad(), -builder_.fov_min_rad(), 1e-3);
}

TEST_F(OccupancyFloorAndWall, PersonBoxIsMarkedAndKeptOffTheWall) {
  // A person-sized box in the middle of the image covers part of the wall.
  PersonBox person;
  person.id = 7;
  person.box = cv::Rect2d(140, 40, 40, 160);
  person.image_size = cv::Size(320, 240);
  StatusOr<OccupancyImage> image = builder_.Build(depth_, {person});
  ASSERT_TRUE(image.ok());
  EXPECT_GT(Count(*image, OccupancyCell::kPerson), 10);
  ASSERT_EQ(image->people.size(), 1u);
  EXPECT_EQ(image->people[0].id, 7);
  EXPECT_NEAR(image->people[0].range_m, 3.0, 0.1);
  // The footprint sits on the wall row, around the centre column.
  EXPECT_TRUE(image->people[0].cells.contains(cv::Point(200, 250)));
}

TEST_F(OccupancyFloorAndWall, PersonBoxesScaleFromTheColourResolution) {
  PersonBox person;
  person.box = cv::Rect2d(280, 80, 80, 320);  // The same box in 640 x 480 pixels.
  person.image_size = cv::Size(640, 480);
  StatusOr<OccupancyImage> image = builder_.Build(depth_, {person});
  ASSERT_TRUE(image.ok());
  ASSERT_EQ(image->people.size(), 1u);
  EXPECT_TRUE(image->people[0].cells.contains(cv::Point(200, 250)));
}

TEST_F(OccupancyFloorAndWall, HighResolutionDepthIsSampledToTheTargetColumns) {
  const cv::Mat depth = RenderDepth(KinectCamera(640, 480), view_, {{{3.0, -4}, {3.0, 4}, 2.0}});
  StatusOr<OccupancyImage> image = builder_.Build(depth, {});
  ASSERT_TRUE(image.ok());
  EXPECT_EQ(image->sampled_pixels, 320 * 240);
  EXPECT_EQ(image->At(200, 250), OccupancyCell::kOccupied);
}

TEST_F(OccupancyFloorAndWall, DegenerateDepthGivesUnknownCells) {
  StatusOr<OccupancyImage> empty = builder_.Build(cv::Mat(), {});
  ASSERT_TRUE(empty.ok());
  EXPECT_EQ(Count(*empty, OccupancyCell::kUnknown), 400 * 400);
  const cv::Mat nan_depth(240, 320, CV_32FC1, cv::Scalar(std::nanf("")));
  StatusOr<OccupancyImage> nan_image = builder_.Build(nan_depth, {});
  ASSERT_TRUE(nan_image.ok());
  EXPECT_EQ(nan_image->invalid_pixels, 320 * 240);
  EXPECT_EQ(Count(*nan_image, OccupancyCell::kUnknown), 400 * 400);
  EXPECT_TRUE(nan_image->known_cells.empty());
  const cv::Mat wrong_type(240, 320, CV_16UC1, cv::Scalar(1000));
  EXPECT_EQ(builder_.Build(wrong_type, {}).status().code(), StatusCode::kInvalidArgument);
}

TEST(OccupancyImage, ConfigureRejectsBadInput) {
  OccupancyImageBuilder builder;
  FloorPlane floor;
  floor.d = 0.8;
  EXPECT_EQ(builder.Build(cv::Mat(), {}).status().code(), StatusCode::kFailedPrecondition);
  EXPECT_FALSE(builder.Configure(floor, PinholeCamera()).ok());
  FloorPlane down = floor;
  down.normal = Eigen::Vector3d(0, 0, -1);  // Camera looking straight down.
  EXPECT_FALSE(builder.Configure(down, KinectCamera()).ok());
  OccupancyImageOptions bad;
  bad.cell_size_m = 0;
  std::string error;
  EXPECT_FALSE(bad.IsValid(&error));
  EXPECT_NE(error.find("mapping.occupancy.cell_size_m"), std::string::npos);
}

}  // namespace
}  // namespace sightline
