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

double Radians(double deg) { return deg * M_PI / 180; }

// The view after the camera turned by `r` (current_from_previous), of a far scene: `previous`
// warped by K R K^-1, with new scene (`fill`) where it did not see.
cv::Mat Turned(const cv::Mat& previous, const cv::Mat& fill, const RectifiedStereoCamera& c,
               const Eigen::Matrix3d& r) {
  Eigen::Matrix3d k;
  k << c.f, 0, c.cx, 0, c.f, c.cy, 0, 0, 1;
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

// ... turned by `yaw_deg` about its y axis, then `pitch_deg` about x.
cv::Mat Turned(const cv::Mat& previous, const cv::Mat& fill, const RectifiedStereoCamera& c,
               double yaw_deg, double pitch_deg) {
  return Turned(previous, fill, c,
                (Eigen::AngleAxisd(Radians(yaw_deg), Eigen::Vector3d::UnitY()) *
                 Eigen::AngleAxisd(Radians(pitch_deg), Eigen::Vector3d::UnitX()))
                    .toRotationMatrix());
}

double AngleBetweenDeg(const Eigen::Matrix3d& a, const Eigen::Matrix3d& b) {
  return Eigen::AngleAxisd(a.transpose() * b).angle() * 180 / M_PI;
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

// A camera tilted 12 deg down on a vehicle turns about an axis 12 deg off its y axis. Searched
// about y alone, a 45 deg turn came out several degrees short with pitch at its limit; the
// tilt of the axis is searched for large turns, and the axis the camera has been turning about
// is given once known.
TEST(TurnSearch, FindsTurnsAboutATiltedAxis) {
  const RectifiedStereoCamera camera = Camera();
  const cv::Mat previous = Texture(640, 480, 1), fill = Texture(640, 480, 2);
  const Eigen::Vector3d up(0, std::cos(Radians(12)), std::sin(Radians(12)));
  for (double yaw : {20.0, -35.0, 45.0}) {
    const Eigen::Matrix3d truth = Eigen::AngleAxisd(Radians(yaw), up).toRotationMatrix();
    const cv::Mat current = Turned(previous, fill, camera, truth);
    std::optional<TurnEstimate> searched = FindTurn(previous, current, camera);
    ASSERT_TRUE(searched.has_value()) << yaw;
    EXPECT_LT(AngleBetweenDeg(searched->current_from_previous, truth), 1.2) << yaw;
    std::optional<TurnEstimate> given = FindTurn(previous, current, camera, {}, up);
    ASSERT_TRUE(given.has_value()) << yaw;
    EXPECT_LT(AngleBetweenDeg(given->current_from_previous, truth), 0.8) << yaw;
    EXPECT_NEAR(given->axis_tilt_deg, 0, 2.0) << yaw;
  }
}

TEST(TurnAxis, LearnsTheAxisOfLeftAndRightTurnsAndIgnoresSmallRotations) {
  const Eigen::Vector3d up(0, std::cos(Radians(10)), std::sin(Radians(10)));
  TurnAxis axis;
  EXPECT_EQ(axis.axis(), Eigen::Vector3d::UnitY());
  std::mt19937 rng(5);
  std::normal_distribution<double> wobble(0, Radians(0.2));
  auto add = [&](double yaw_deg) {
    const Eigen::Vector3d noise(wobble(rng), wobble(rng), wobble(rng));
    axis.Add((Eigen::AngleAxisd(Radians(yaw_deg), up) *
              Eigen::AngleAxisd(noise.norm(), noise.normalized()))
                 .toRotationMatrix());
  };
  for (int i = 0; i < 50; ++i) add(0);   // Driving straight: below the step threshold.
  for (int i = 0; i < 5; ++i) add(1.5);  // A slow turn: each step below it too.
  add(4);
  EXPECT_EQ(axis.axis(), Eigen::Vector3d::UnitY());  // 4 deg of turning is not enough.
  for (double yaw : {9.0, 9.0, -12.0, -12.0, 7.0}) add(yaw);
  EXPECT_LT(std::acos(std::min(1.0, axis.axis().dot(up))) * 180 / M_PI, 1.0);
  axis.Reset();
  EXPECT_EQ(axis.axis(), Eigen::Vector3d::UnitY());
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
