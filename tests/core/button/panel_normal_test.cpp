// The panel normal: a robust plane through the map points around the button, oriented toward the
// camera, with a sigma that covers its error; and its average over frames in data time.
#include "core/button/panel_normal.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>

namespace sightline {
namespace {

double AngleDeg(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  return std::acos(std::clamp(a.normalized().dot(b.normalized()), -1.0, 1.0)) * 180 / M_PI;
}

// A 40 x 40 cm panel 0.6 m in front of the camera, tilted by `tilt_deg` about the camera's y
// axis, sampled with `noise_m` of noise and `outliers` of the points off the plane.
struct Panel {
  Eigen::Vector3d normal_toward_camera;
  Eigen::Vector3d button;
  std::vector<Eigen::Vector3d> points;
};

Panel MakePanel(double tilt_deg, double noise_m, double outliers, uint64_t seed, int n = 400) {
  Panel p;
  const double t = tilt_deg * M_PI / 180;
  p.normal_toward_camera = Eigen::Vector3d(std::sin(t), 0, -std::cos(t));
  p.button = {0.02, -0.01, 0.6};
  const Eigen::Vector3d u = Eigen::Vector3d::UnitY().cross(p.normal_toward_camera).normalized();
  const Eigen::Vector3d v = p.normal_toward_camera.cross(u);
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> in(-0.2, 0.2), unit(0, 1);
  std::normal_distribution<double> noise(0, noise_m);
  for (int i = 0; i < n; ++i) {
    Eigen::Vector3d x = p.button + in(rng)*u + in(rng)*v + noise(rng) * p.normal_toward_camera;
    if (unit(rng) < outliers) x += (0.02 + 0.1 * unit(rng)) * p.normal_toward_camera;
    p.points.push_back(x);
  }
  return p;
}

TEST(PanelNormal, TheNormalOfANoisyPanelWithOutliersFacesTheCamera) {
  for (double tilt : {0.0, 25.0, -50.0}) {
    const Panel p = MakePanel(tilt, 0.001, 0.2, 3);
    StatusOr<PanelNormal> n = EstimatePanelNormal(p.points, p.button, {});
    ASSERT_TRUE(n.ok()) << n.status().ToString();
    EXPECT_LT(AngleDeg(n->normal_in_camera, p.normal_toward_camera), 0.5) << tilt;
    EXPECT_LT(n->normal_in_camera.z(), 0) << tilt;  // Toward the camera at the origin.
    EXPECT_GT(n->inliers, 250);
    EXPECT_LT(n->inliers, 340);  // The outliers stay out.
  }
}

TEST(PanelNormal, TheStatedSigmaCoversTheErrorOnNinetyFivePercentOfPanels) {
  PanelNormalOptions o;
  o.min_sigma_deg = 0.01;  // The fit's own figure, without the floor.
  int covered = 0;
  const int trials = 200;
  for (int seed = 0; seed < trials; ++seed) {
    // Noise well inside the inlier distance (3 mm): the residual is not truncated.
    const Panel p = MakePanel(10, 0.001, 0.0, 100 + seed, 40);
    StatusOr<PanelNormal> n = EstimatePanelNormal(p.points, p.button, o);
    ASSERT_TRUE(n.ok()) << n.status().ToString();
    covered +=
        AngleDeg(n->normal_in_camera, p.normal_toward_camera) <= 3 * n->sigma_rad * 180 / M_PI;
  }
  std::printf("fit sigma covers the error on %d of %d panels\n", covered, trials);
  EXPECT_GE(covered, trials * 95 / 100);
}

// A side wall at right angles to the panel, 15 cm beside the button, with more map points than
// the panel itself: the plane with the most support is the wall, but it does not pass near the
// button, so the panel's normal is kept.
TEST(PanelNormal, ASideWallWithMorePointsDoesNotGiveTheNormal) {
  Panel p = MakePanel(10, 0.001, 0.0, 5, 150);
  const Eigen::Vector3d u = Eigen::Vector3d::UnitY().cross(p.normal_toward_camera).normalized();
  std::mt19937_64 rng(6);
  std::uniform_real_distribution<double> along(0.0, 0.3), up(-0.2, 0.2);
  std::normal_distribution<double> noise(0, 0.001);
  for (int i = 0; i < 400; ++i) {  // The wall: the plane through button + 0.15 u, normal u.
    p.points.push_back(p.button + (0.15 + noise(rng)) * u + along(rng) * p.normal_toward_camera +
                       up(rng) * Eigen::Vector3d::UnitY());
  }
  StatusOr<PanelNormal> n = EstimatePanelNormal(p.points, p.button, {});
  ASSERT_TRUE(n.ok()) << n.status().ToString();
  EXPECT_LT(AngleDeg(n->normal_in_camera, p.normal_toward_camera), 1.0);
  // Without the condition (any plane), the wall wins and the push would go along it.
  PanelNormalOptions any;
  any.max_button_offset_m = 1.0;
  StatusOr<PanelNormal> wall = EstimatePanelNormal(p.points, p.button, any);
  ASSERT_TRUE(wall.ok()) << wall.status().ToString();
  EXPECT_GT(AngleDeg(wall->normal_in_camera, p.normal_toward_camera), 45.0);
}

TEST(PanelNormal, TooFewPointsNearTheButtonGiveNoNormal) {
  Panel p = MakePanel(0, 0.001, 0, 4, 400);
  PanelNormalOptions o;
  o.radius_m = 0.01;
  StatusOr<PanelNormal> n = EstimatePanelNormal(p.points, p.button, o);
  EXPECT_EQ(n.status().code(), StatusCode::kNotFound);
  EXPECT_NE(n.status().message().find("map points within"), std::string::npos);
  o = PanelNormalOptions();
  o.min_points = 2;
  EXPECT_EQ(EstimatePanelNormal(p.points, p.button, o).status().code(),
            StatusCode::kInvalidArgument);
}

TEST(NormalAverage, WeighsBySigmaSkipsOutliersAndFadesInDataTime) {
  PanelNormalOptions o;
  o.smoothing_s = 1.0;
  NormalAverage avg(o);
  EXPECT_TRUE(avg.empty());
  EXPECT_FALSE(std::isfinite(avg.sigma_rad()));
  const Eigen::Vector3d x = Eigen::Vector3d::UnitX();
  const Eigen::Vector3d tilted = Eigen::AngleAxisd(0.02, Eigen::Vector3d::UnitZ()) * x;
  EXPECT_TRUE(avg.Add(0.0, x, 0.01));
  EXPECT_TRUE(avg.Add(0.1, tilted, 0.01));
  EXPECT_TRUE(avg.Add(0.2, x, 0.01));
  EXPECT_LT(AngleDeg(avg.normal(), x), 0.02 * 180 / M_PI);
  // A normal far off the average (a wrong plane in one frame) is skipped.
  EXPECT_FALSE(avg.Add(0.3, Eigen::Vector3d::UnitY(), 0.01));
  EXPECT_EQ(avg.frames(), 3);
  // A less certain frame weighs less.
  NormalAverage weighted(o);
  weighted.Add(0.0, x, 0.01);
  weighted.Add(0.0, tilted, 0.1);
  EXPECT_LT(AngleDeg(weighted.normal(), x), 0.1 * AngleDeg(tilted, x));
  // Ten time constants later the old frames have faded: the new direction wins.
  NormalAverage fading(o);
  fading.Add(0.0, x, 0.01);
  fading.Add(10.0, tilted, 0.01);
  EXPECT_LT(AngleDeg(fading.normal(), tilted), 0.01);
  // Data time going back starts again.
  fading.Add(5.0, x, 0.01);
  EXPECT_EQ(fading.frames(), 1);
}

// An average of three frames along x at 0, 0.1 and 0.2 s, 2 s smoothing.
NormalAverage ThreeFramesAlongX() {
  PanelNormalOptions o;
  o.smoothing_s = 2.0;
  NormalAverage avg(o);
  for (int i = 0; i < 3; ++i) avg.Add(0.1 * i, Eigen::Vector3d::UnitX(), 0.01);
  return avg;
}

TEST(NormalAverage, SkippedFramesDoNotFadeTheAverageTwice) {
  NormalAverage avg = ThreeFramesAlongX();
  const Eigen::Vector3d x = Eigen::Vector3d::UnitX();
  // 1.5 s of far-off frames at 100 Hz: all skipped, shorter than the smoothing time.
  for (int i = 1; i <= 150; ++i) {
    EXPECT_FALSE(avg.Add(0.2 + 0.01 * i, Eigen::Vector3d::UnitY(), 0.01)) << i;
    ASSERT_TRUE(avg.normal().allFinite()) << i;
    ASSERT_NEAR(avg.normal().norm(), 1.0, 1e-9) << i;
  }
  // The three frames faded once, by exp(-1.6 / 2): a new frame 1.1 deg off moves the average
  // by about a third of that, not all the way.
  const Eigen::Vector3d tilted = Eigen::AngleAxisd(0.02, Eigen::Vector3d::UnitZ()) * x;
  ASSERT_TRUE(avg.Add(1.8, tilted, 0.01));
  const double moved = AngleDeg(avg.normal(), x) / AngleDeg(tilted, x);
  EXPECT_GT(moved, 0.2);
  EXPECT_LT(moved, 0.45);
}

TEST(NormalAverage, ANormalSkippedForLongerThanTheSmoothingTimeBecomesTheAverage) {
  PanelNormalOptions o;
  o.smoothing_s = 2.0;
  NormalAverage avg(o);
  const Eigen::Vector3d x = Eigen::Vector3d::UnitX();
  const Eigen::Vector3d other = Eigen::AngleAxisd(0.3, Eigen::Vector3d::UnitZ()) * x;
  for (int i = 0; i < 3; ++i) ASSERT_TRUE(avg.Add(0.1 * i, x, 0.01));
  // Ten seconds of a consistent other normal at 10 Hz (the map improved): skipped for two
  // seconds, then taken; the average is a unit vector on every frame.
  int skipped = 0;
  for (int i = 1; i <= 100; ++i) {
    if (!avg.Add(0.2 + 0.1 * i, other, 0.01)) ++skipped;
    ASSERT_TRUE(avg.normal().allFinite()) << i;
    ASSERT_NEAR(avg.normal().norm(), 1.0, 1e-9) << i;
    EXPECT_LT(avg.sigma_rad(), 1.0) << i;
  }
  EXPECT_GE(skipped, 19);
  EXPECT_LE(skipped, 21);
  EXPECT_LT(AngleDeg(avg.normal(), other), 0.01);
}

TEST(NormalAverage, AnHourLongGapLeavesAUnitNormal) {
  NormalAverage avg = ThreeFramesAlongX();
  const Eigen::Vector3d x = Eigen::Vector3d::UnitX();
  const Eigen::Vector3d y = Eigen::Vector3d::UnitY();
  EXPECT_TRUE(avg.Add(3600.0, y, 0.01));
  EXPECT_EQ(avg.frames(), 1);
  EXPECT_LT(AngleDeg(avg.normal(), y), 1e-6);
  EXPECT_TRUE(std::isfinite(avg.sigma_rad()));
  EXPECT_EQ(ThreeFramesAlongX().frames(), 3);
  EXPECT_FALSE(NormalAverage().normal().allFinite());
}

}  // namespace
}  // namespace sightline
