#include "core/common/depth_cloud.h"

#include <gtest/gtest.h>

#include <cmath>

namespace sightline {
namespace {

TEST(DepthToCloud, BackProjectsAndKeepsInvalidAsNan) {
  PinholeCamera cam;
  cam.width = 4;
  cam.height = 2;
  cam.fx = cam.fy = 2;
  cam.cx = 1.5;
  cam.cy = 0.5;
  cv::Mat depth(2, 4, CV_32FC1, cv::Scalar(2.0f));
  depth.at<float>(1, 3) = std::nanf("");
  depth.at<float>(0, 0) = 0;
  cv::Mat color(2, 4, CV_8UC3, cv::Scalar(10, 20, 30));  // BGR.
  const PointCloud cloud = DepthToCloud(depth, color, cam);
  ASSERT_EQ(cloud.size(), 8u);
  EXPECT_TRUE(cloud.organized());
  EXPECT_FALSE(cloud.points[0].allFinite());          // Zero depth.
  EXPECT_FALSE(cloud.points[7].allFinite());          // NaN depth.
  const Eigen::Vector3f p = cloud.points[1 * 4 + 0];  // u=0, v=1, z=2.
  EXPECT_FLOAT_EQ(p.x(), (0 - 1.5f) * 2 / 2);
  EXPECT_FLOAT_EQ(p.y(), (1 - 0.5f) * 2 / 2);
  EXPECT_FLOAT_EQ(p.z(), 2);
  EXPECT_EQ(cloud.colors[1](0), 30);  // RGB order.
}

}  // namespace
}  // namespace sightline
