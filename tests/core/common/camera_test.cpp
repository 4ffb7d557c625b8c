#include "core/common/camera.h"

#include <gtest/gtest.h>

#include "tests/support/test_camera.h"

namespace sightline {
namespace {

TEST(PinholeCamera, ProjectInvertsUnproject) {
  const PinholeCamera c = testing::VgaCamera();
  const Eigen::Vector3d x = c.Unproject(100.25, 400.5, 2.5);
  const Eigen::Vector2d uv = c.Project(x);
  EXPECT_NEAR(uv.x(), 100.25, 1e-9);
  EXPECT_NEAR(uv.y(), 400.5, 1e-9);
  EXPECT_DOUBLE_EQ(x.z(), 2.5);
}

TEST(PinholeCamera, HalfResolutionHalvesFocalLength) {
  const PinholeCamera half = testing::VgaCamera().Scaled(320, 240);
  EXPECT_DOUBLE_EQ(half.fx, 262.5);
  EXPECT_DOUBLE_EQ(half.cx, 159.5);
}

TEST(PinholeCamera, ValidateNamesTheBadField) {
  PinholeCamera c = testing::VgaCamera();
  c.fx = -1;
  Status s = c.Validate();
  EXPECT_FALSE(s.ok());
  EXPECT_NE(s.message().find("focal length"), std::string::npos);
}

TEST(StereoRig, ZeroBaselineIsInvalid) {
  StereoRig rig;
  rig.left = rig.right = testing::VgaCamera();
  EXPECT_FALSE(rig.Validate().ok());
  rig.right_from_left.translation() = Eigen::Vector3d(-0.54, 0, 0);
  EXPECT_TRUE(rig.Validate().ok());
  EXPECT_NEAR(rig.BaselineM(), 0.54, 1e-12);
}

}  // namespace
}  // namespace sightline
