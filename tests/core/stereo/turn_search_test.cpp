#include "core/stereo/turn_search.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <opencv2/imgproc.hpp>
#include <random>

#include "stereo_test_util.h"

namespace sightline {
namespace {

// Blurred noise: a scene of many surfaces.
cv::Mat Texture(int cols, int rows, unsigned seed) {
  cv::Mat noise(rows, cols, CV_8UC1);
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> grey(0, 255);
  for (int v = 0; v < rows; ++v) {
    for (int u = 0; u < cols; ++u) noise.at<uchar>(v, u) = static_cast<uchar>(grey(rng));
  }
  cv::GaussianBlur(noise, noise, cv::Size(0, 0), 4.0);
  return noise;
}

// testing::TestCamera with a 90 deg field of view across its 640 px.
RectifiedStereoCamera Camera() {
  RectifiedStereoCamera camera = testing::TestCamera();
  camera.f = 320;
  return camera;
}

// The view after the camera turned by `yaw_deg` (about its y axis) and `pitch_deg`, of a far
// scene: `previous` warped by K R K^-1, with new scene (`fill`) where it did not see.
cv::Mat Turned(const cv::Mat& previous, const cv::Mat& fill, const RectifiedStereoCamera& c,
               double yaw_deg, double pitch_deg) {
  Eigen::Matrix3d k;
  k << c.f, 0, c.cx, 0, c.f, c.cy, 0, 0, 1;
  const Eigen::Matrix3d r = (Eigen::AngleAxisd(yaw_deg * M_PI / 180, Eigen::Vector3d::UnitY()) *
                             Eigen::AngleAxisd(pitch_deg * M_PI / 180, Eigen::Vector3d::UnitX()))
                                .toRotationMatrix();
  const Eigen::Matrix3d h = k * r * k.inverse();
  cv::Mat hm(3, 3, CV_64F);
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) hm.at<double>(i, j) = h(i, j);
  }
  cv::Mat warped, mask;
  cv::warpPerspective(previous, warped, hm, previous.size());
  cv::warpPerspective(cv::Mat(previous.size(), CV_8UC1, cv::Scalar(255)), mask, hm, previous.size(),
                      cv::INTER_NEAREST);
  cv::Mat out = fill.clone();
  warped.copyTo(out, mask);
  return out;
}

TEST(TurnSearch, FindsTurnsOfUpTo50DegreesPerFrame) {
  const RectifiedStereoCamera camera = Camera();
  const cv::Mat previous = Texture(640, 480, 1), fill = Texture(640, 480, 2);
  for (const auto& [yaw, pitch] : std::vector<std::pair<double, double>>{
           {0, 0}, {8, 0}, {-23, 1.5}, {31, -2}, {-47, 0}, {50, 1}}) {
    std::optional<TurnEstimate> t =
        FindTurn(previous, Turned(previous, fill, camera, yaw, pitch), camera);
    ASSERT_TRUE(t.has_value()) << yaw;
    // Within a reduced pixel (4 px, 0.7 deg at this focal length) and a fine step.
    EXPECT_NEAR(t->yaw_deg, yaw, 0.8) << yaw;
    EXPECT_NEAR(t->pitch_deg, pitch, 0.8) << yaw;
    EXPECT_GT(t->correlation, 0.5) << yaw;
    const Eigen::Vector3d ray = t->current_from_previous * Eigen::Vector3d::UnitZ();
    EXPECT_NEAR(std::atan2(ray.x(), ray.z()) * 180 / M_PI, yaw, 0.8) << yaw;
  }
}

TEST(TurnSearch, NoAnswerWhenTheViewsShareNothing) {
  const RectifiedStereoCamera camera = Camera();
  const cv::Mat previous = Texture(640, 480, 1);
  EXPECT_FALSE(FindTurn(previous, Texture(640, 480, 3), camera).has_value());
  EXPECT_FALSE(FindTurn(previous, cv::Mat(), camera).has_value());
  EXPECT_FALSE(FindTurn(previous, Texture(320, 240, 3), camera).has_value());
  EXPECT_FALSE(FindTurn(cv::Mat(480, 640, CV_8UC1, cv::Scalar(90)),
                        cv::Mat(480, 640, CV_8UC1, cv::Scalar(90)), camera)
                   .has_value());  // Uniform: nothing to correlate.
}

}  // namespace
}  // namespace sightline
