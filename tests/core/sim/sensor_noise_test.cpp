#include "core/sim/sensor_noise.h"

#include <gtest/gtest.h>

#include <cmath>

#include "tests/core/sim/sim_test_util.h"

namespace sightline::sim {
namespace {

using testing::LookHorizontally;
using testing::MakeCamera;

// A wall at x = 3 seen obliquely, so the depths span about 2.3 to 4.5 m, and a floor.
RenderedView RenderTiltedWall() {
  Scene scene("wall");
  const int grey = scene.AddMaterial({TextureKind::kPlain});
  const int wall = scene.AddObject(ObjectKind::kWall, "wall 0", 0);
  scene.AddRectangle(wall, grey, {3, 10, -10}, {0, -1, 0}, {0, 0, 1}, {20, 20});
  const int floor = scene.AddObject(ObjectKind::kFloor, "floor", 0);
  scene.AddRectangle(floor, grey, {-5, -10, 0}, {1, 0, 0}, {0, 1, 0}, {8, 20});
  Renderer renderer;
  RenderedView view;
  EXPECT_TRUE(renderer
                  .Render(scene, {}, RgbdSensorOptions().Camera(),
                          LookHorizontally({0, 0, 1.0}, 25 * M_PI / 180), ImageKind::kNone, &view)
                  .ok());
  return view;
}

TEST(DepthModel, NoNoiseKeepsExactDepthInsideTheSensorLimits) {
  const RenderedView view = RenderTiltedWall();
  RgbdSensorOptions sensor;
  NoiseOptions none;
  none.profile = "none";
  cv::Mat depth;
  ApplyDepthModel(view, sensor, none.Effective(), 1, &depth);
  const float min_cos = std::cos(sensor.max_incidence_deg * M_PI / 180);
  int exact = 0, dropped_range = 0, dropped_grazing = 0;
  for (int v = 0; v < depth.rows; ++v) {
    for (int u = 0; u < depth.cols; ++u) {
      const float truth = view.depth_m.at<float>(v, u), z = depth.at<float>(v, u);
      const bool in_range = truth >= sensor.min_depth_m && truth <= sensor.max_depth_m;
      const bool steep = view.incidence_cos.at<float>(v, u) >= min_cos;
      if (in_range && steep) {
        ASSERT_EQ(z, truth) << u << "," << v;
        ++exact;
      } else {
        ASSERT_TRUE(std::isnan(z)) << u << "," << v;
        dropped_range += in_range ? 0 : 1;
        dropped_grazing += in_range ? 1 : 0;
      }
    }
  }
  EXPECT_GT(exact, 100000);
  EXPECT_GT(dropped_range, 1000);   // The far part of the wall lies beyond 4.5 m.
  EXPECT_GT(dropped_grazing, 100);  // The floor far ahead is seen at grazing angles.
}

TEST(DepthModel, KinectNoiseFollowsTheQuadraticModel) {
  const RenderedView view = RenderTiltedWall();
  RgbdSensorOptions sensor;
  NoiseOptions kinect;  // Default profile: sigma_z = 1.425e-3 z^2, 1/8 px disparity steps.
  const NoiseModel model = kinect.Effective();
  cv::Mat depth;
  ApplyDepthModel(view, sensor, model, 42, &depth);
  const double fb = sensor.focal_px * model.ir_baseline_m;
  double sum_normalised = 0, sum_sq_normalised = 0;
  int n = 0, beyond = 0;
  for (int v = 0; v < depth.rows; ++v) {
    for (int u = 0; u < depth.cols; ++u) {
      const double truth = view.depth_m.at<float>(v, u), z = depth.at<float>(v, u);
      if (std::isnan(z)) continue;
      const double sigma = model.depth_sigma_coeff * truth * truth;
      const double half_step = 0.5 * model.disparity_step_px * truth * truth / fb;
      const double error = z - truth;
      if (std::abs(error) > 4 * sigma + 1.05 * half_step) ++beyond;
      sum_normalised += error / sigma;
      sum_sq_normalised += (error / sigma) * (error / sigma);
      ++n;
      // Every reading lies on the 1/8 pixel disparity grid.
      const double steps = fb / z / model.disparity_step_px;
      ASSERT_NEAR(steps, std::round(steps), 1e-3);
    }
  }
  ASSERT_GT(n, 100000);
  EXPECT_LT(beyond, n / 1000);  // Gaussian tails beyond 4 sigma: 6e-5.
  const double mean = sum_normalised / n;
  const double rms = std::sqrt(sum_sq_normalised / n);
  EXPECT_LT(std::abs(mean), 0.05) << "mean error in sigmas";
  // Noise plus quantisation (uniform over a step of about 2.2 sigma: +0.4 sigma^2).
  EXPECT_GT(rms, 0.95);
  EXPECT_LT(rms, 1.35);
}

TEST(DepthModel, SameSeedSameNoiseOtherSeedOtherNoise) {
  const RenderedView view = RenderTiltedWall();
  const NoiseModel model = NoiseOptions().Effective();
  cv::Mat a, b, c;
  ApplyDepthModel(view, RgbdSensorOptions(), model, 5, &a);
  ApplyDepthModel(view, RgbdSensorOptions(), model, 5, &b);
  ApplyDepthModel(view, RgbdSensorOptions(), model, 6, &c);
  // NaN at the same pixels, equal values elsewhere.
  EXPECT_EQ(cv::countNonZero((a == a) != (b == b)), 0);
  EXPECT_EQ(cv::norm(a, b, cv::NORM_L1, a == a), 0);
  EXPECT_GT(cv::norm(a, c, cv::NORM_L1, (a == a) & (c == c)), 1.0);
}

TEST(ImageNoise, HasTheRequestedSigmaAndIsSeeded) {
  cv::Mat flat(240, 320, CV_8UC3, cv::Scalar(100, 120, 140)), again, other;
  cv::Mat noisy = flat.clone();
  AddImageNoise(3.0, 9, &noisy);
  again = flat.clone();
  AddImageNoise(3.0, 9, &again);
  other = flat.clone();
  AddImageNoise(3.0, 10, &other);
  cv::Mat signed_diff;
  noisy.convertTo(signed_diff, CV_32F);
  cv::Mat base;
  flat.convertTo(base, CV_32F);
  cv::Scalar mean, stddev;
  const cv::Mat difference = signed_diff - base;
  cv::meanStdDev(difference.reshape(1), mean, stddev);
  EXPECT_NEAR(mean[0], 0, 0.1);
  EXPECT_NEAR(stddev[0], 3.0, 0.2);  // Rounding adds 1/12 grey level^2.
  EXPECT_EQ(cv::norm(noisy, again, cv::NORM_L1), 0);
  EXPECT_GT(cv::norm(noisy, other, cv::NORM_L1), 1000);
}

}  // namespace
}  // namespace sightline::sim
