#include "core/sensors/depth_conversion.h"

#include <gtest/gtest.h>

#include <cmath>

namespace sightline {
namespace {

TEST(DepthConversion, MillimetresBecomeMetresAndZeroBecomesNan) {
  cv::Mat raw = (cv::Mat_<uint16_t>(1, 3) << 0, 1500, 65535);
  cv::Mat m = RawDepthToMetres(raw, 1000);
  ASSERT_EQ(m.type(), CV_32FC1);
  EXPECT_TRUE(std::isnan(m.at<float>(0, 0)));
  EXPECT_FLOAT_EQ(m.at<float>(0, 1), 1.5f);
  EXPECT_FLOAT_EQ(m.at<float>(0, 2), 65.535f);
  cv::Mat fine = RawDepthToMetres(raw, 10000);  // 100 um units.
  EXPECT_FLOAT_EQ(fine.at<float>(0, 1), 0.15f);
}

TEST(DepthConversion, PinholeFromFieldOfView) {
  const double hfov = 1.0144686, vfov = 0.7898090;  // A PrimeSense depth camera.
  PinholeCamera c = PinholeFromFov(640, 480, hfov, vfov);
  EXPECT_NEAR(c.fx, 640 / (2 * std::tan(hfov / 2)), 1e-9);
  EXPECT_NEAR(c.fx, 575.8, 0.1);  // OpenNI's well-known default focal length.
  EXPECT_NEAR(c.fy, 575.8, 0.1);
  EXPECT_DOUBLE_EQ(c.cx, 320);
  EXPECT_DOUBLE_EQ(c.cy, 240);
  EXPECT_TRUE(c.Validate().ok());
}

}  // namespace
}  // namespace sightline
