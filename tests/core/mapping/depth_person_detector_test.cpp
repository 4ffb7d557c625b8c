// The depth person detector on synthetic geometry: a walking person (body, head, an arm swung
// forward and one back, a leg stepping forward, all standing blocks) is found where it stands;
// walls, a knee-high box, a cabinet along a wall and a pillar taller than a person are not.
#include "core/mapping/depth_person_detector.h"

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
using testing::SyntheticWall;

// A closed rectangle of walls centred at (x, y): a standing block seen from any side.
void AddBlock(double x, double y, double size_x, double size_y, double height,
              std::vector<SyntheticWall>* walls) {
  const Eigen::Vector2d c(x, y), a(size_x / 2, size_y / 2), b(size_x / 2, -size_y / 2);
  walls->push_back({c - a, c + b, height});
  walls->push_back({c + b, c + a, height});
  walls->push_back({c + a, c - b, height});
  walls->push_back({c - b, c - a, height});
}

// A walking person of height `h` centred at (x, y), facing -x (the camera); the limbs touch
// the body, as a person's do.
void AddWalker(double x, double y, double h, std::vector<SyntheticWall>* walls) {
  const double k = h / 1.75;
  AddBlock(x, y, 0.22, 0.38, 1.45 * k, walls);                // Body.
  AddBlock(x, y, 0.18, 0.16, h, walls);                       // Head.
  AddBlock(x - 0.14, y + 0.23, 0.09, 0.09, 1.35 * k, walls);  // Arm swung forward.
  AddBlock(x + 0.12, y - 0.23, 0.09, 0.09, 1.35 * k, walls);  // Arm swung back.
  AddBlock(x - 0.17, y + 0.08, 0.12, 0.12, 0.85 * k, walls);  // Leg stepping forward.
}

// The camera 1.0 m up, pitched 5 deg down, at the origin looking along +x.
class DepthPeople : public ::testing::Test {
 protected:
  void SetUp() override {
    view_.height_m = 1.0;
    view_.pitch_down_rad = DegToRad(5);
    camera_ = KinectCamera(320, 240);
  }
  std::vector<PersonBox> Detect(const std::vector<SyntheticWall>& walls, double noise = 0.0) {
    DepthPersonDetector detector;
    EXPECT_TRUE(detector.Configure(FloorPlaneOf(view_), camera_).ok());
    const cv::Mat depth = RenderDepth(camera_, view_, walls, true, 8.0, noise);
    StatusOr<std::vector<PersonBox>> people = detector.Detect(depth);
    EXPECT_TRUE(people.ok()) << people.status().ToString();
    return people.ok() ? *people : std::vector<PersonBox>();
  }
  // A 1.75 m walker at (x, y) in the depth sensor's noise.
  std::vector<PersonBox> DetectWalker(double x, double y) {
    std::vector<SyntheticWall> walls;
    AddWalker(x, y, 1.75, &walls);
    return Detect(walls, 1.425e-3);
  }
  // Pixel column of a floor point straight ahead at lateral offset y (left positive).
  double Column(double x, double y) const { return camera_.cx - camera_.fx * y / x; }
  SyntheticView view_;
  PinholeCamera camera_;
};

TEST_F(DepthPeople, AWalkingPersonIsFoundWhereItStands) {
  for (double x : {2.0, 3.5, 5.0}) {
    for (double y : {-0.8, 0.0, 0.6}) {
      const std::vector<PersonBox> people = DetectWalker(x, y);
      ASSERT_EQ(people.size(), 1u) << "at " << x << ", " << y;
      // Between the body's outline and the outline with both arms.
      const cv::Rect2d& box = people[0].box;
      EXPECT_NEAR(box.x + box.width / 2, Column(x, y), 8) << "at " << x << ", " << y;
      EXPECT_GE(box.width, camera_.fx * 0.38 / x - 4) << "at " << x << ", " << y;
      EXPECT_LE(box.width, camera_.fx * 0.6 / (x - 0.3) + 4) << "at " << x << ", " << y;
      EXPECT_EQ(people[0].image_size, cv::Size(320, 240));
    }
  }
}

// The whole body from the floor to the head, for HOG to score at the right size: known when the
// head and the feet are in view, empty when the head is cut off by the image's top (the camera
// 1 m up sees a 1.75 m person 2 m away only up to the shoulders).
TEST_F(DepthPeople, TheBodyBoxSpansTheFloorToTheHeadWhenBothAreInView) {
  // Image row of a point `forward` m ahead and `up` m above the floor.
  const auto row = [&](double forward, double up) {
    const double c = std::cos(view_.pitch_down_rad), s = std::sin(view_.pitch_down_rad);
    const double dz = up - view_.height_m;
    const double z = forward * c - dz * s, y = -forward * s - dz * c;
    return camera_.cy + camera_.fy * y / z;
  };
  for (double x : {2.0, 3.5, 5.0}) {
    for (double y : {-0.8, 0.0, 0.6}) {
      const std::vector<PersonBox> people = DetectWalker(x, y);
      ASSERT_EQ(people.size(), 1u) << "at " << x << ", " << y;
      const cv::Rect2d& body = people[0].body;
      if (row(x, 1.75) < 0 || row(x, 0.0) > camera_.height) {
        EXPECT_TRUE(body.empty()) << "at " << x << ", " << y;
        continue;
      }
      ASSERT_FALSE(body.empty()) << "at " << x << ", " << y;
      // The head's top and the feet within 4 px (5 cm cells, the footprint's centre).
      EXPECT_NEAR(body.y, row(x, 1.75), 4) << "at " << x << ", " << y;
      EXPECT_NEAR(body.br().y, row(x, 0.0), 4) << "at " << x << ", " << y;
      EXPECT_NEAR(body.x, people[0].box.x, 1e-9);
      EXPECT_NEAR(body.width, people[0].box.width, 1e-9);
    }
  }
}

TEST_F(DepthPeople, WallsBoxesAndPillarsAreNotPeople) {
  std::vector<SyntheticWall> walls = testing::Corridor(-1, 7, 2.4);
  AddBlock(3.0, 0.7, 0.5, 0.5, 0.6, &walls);   // A knee-high box.
  AddBlock(5.5, -0.6, 0.3, 0.3, 2.6, &walls);  // A pillar, its top in view from here.
  AddBlock(3.5, -1.0, 1.2, 0.4, 1.7, &walls);  // A cabinet along the wall, longer than a person.
  for (const PersonBox& p : Detect(walls, 1.425e-3)) ADD_FAILURE() << "a person at " << p.box;
}

TEST_F(DepthPeople, BadInputIsAClearStatus) {
  DepthPersonDetector unconfigured;
  EXPECT_EQ(unconfigured.Detect(cv::Mat(240, 320, CV_32FC1, 1.0f)).status().code(),
            StatusCode::kFailedPrecondition);
  PersonDetectorOptions bad;
  bad.depth_max_height_m = 0.5;
  DepthPersonDetector detector(bad);
  const Status s = detector.Configure(FloorPlaneOf(view_), camera_);
  EXPECT_EQ(s.code(), StatusCode::kInvalidArgument);
  EXPECT_NE(s.message().find("depth_min_height_m"), std::string::npos) << s.ToString();
  DepthPersonDetector good;
  ASSERT_TRUE(good.Configure(FloorPlaneOf(view_), camera_).ok());
  EXPECT_EQ(good.Detect(cv::Mat(240, 320, CV_16UC1)).status().code(), StatusCode::kInvalidArgument);
  EXPECT_TRUE(good.Detect(cv::Mat()).ok());
  cv::Mat nan(240, 320, CV_32FC1, std::nanf(""));
  ASSERT_TRUE(good.Detect(nan).ok());
  EXPECT_TRUE(good.Detect(nan)->empty());
}

}  // namespace
}  // namespace sightline
