// The panel normal from the arm's own motion, on the simulated panel scene rendered from the
// simulated arm's plan (its sideways moves for the metric scale, then its approach): against the
// scene's true push direction, with the arm's reported positions exact and noisy.
#include "core/button/arm_plane_normal.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>

#include "core/button/arm_simulator.h"
#include "core/sim/simulator.h"

namespace sightline {
namespace {

double AngleDeg(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  return std::acos(std::clamp(a.normalized().dot(b.normalized()), -1.0, 1.0)) * 180 / M_PI;
}

struct PlaneRun {
  int estimates = 0;
  int within_2_sigma = 0;
  double max_error_deg = 0;
  std::vector<std::string> refusals;
};

// Renders the plan of `seed` every `step_s` from `from_s` to `to_s` and feeds the arm plane with
// the camera's pose from the arm (its positions off by `noise_m` per axis, as an arm reports).
PlaneRun RunPlan(int seed, double from_s, double to_s, double step_s, double noise_m) {
  PlaneRun run;
  sim::SimulationOptions options = sim::SimulationOptions::ForScene("panel");
  options.seed = seed;
  options.frames = 1;
  StatusOr<sim::Simulator> simulator = sim::Simulator::Create(options);
  StatusOr<ArmSimWorld> world = BuildArmSimWorld(seed);
  EXPECT_TRUE(simulator.ok() && world.ok());
  if (!simulator.ok() || !world.ok()) return run;
  const ArmSimButton* button = world->FindButton(5);
  EXPECT_NE(button, nullptr);
  if (button == nullptr) return run;
  const PinholeCamera camera = simulator->mono_camera();
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> noise(0, noise_m > 0 ? noise_m : 1);
  ArmPlaneNormal plane;
  int index = 0;
  for (double t = from_s; t <= to_s + 1e-9; t += step_s, ++index) {
    const Eigen::Isometry3d base_from_ee = world->PlanPose(t);
    const Eigen::Isometry3d base_from_camera = base_from_ee * world->end_effector_from_camera;
    sim::SimulatedMono mono;
    const Status rendered =
        simulator->RenderMonoAt(world->world_from_base * base_from_camera, t, index, &mono);
    EXPECT_TRUE(rendered.ok()) << rendered.ToString();
    if (!rendered.ok()) return run;
    ArmPlaneView view;
    view.image = mono.image;
    view.camera = camera;
    view.base_from_camera = base_from_camera;
    if (noise_m > 0) {
      view.base_from_camera.translation() += Eigen::Vector3d(noise(rng), noise(rng), noise(rng));
    }
    const Eigen::Vector3d in_camera = base_from_camera.inverse() * button->center;
    view.button_px = camera.Project(in_camera);
    view.region_radius_px = PanelNormalOptions().radius_m * camera.fx / in_camera.z();
    view.button_in_camera = in_camera;
    StatusOr<PanelNormal> normal = plane.Add(view);
    if (!normal.ok()) {
      run.refusals.push_back(normal.status().message());
      continue;
    }
    // The truth: the button's normal (toward the camera side) in the base frame.
    const double error =
        AngleDeg(base_from_camera.linear() * normal->normal_in_camera, button->normal);
    ++run.estimates;
    run.max_error_deg = std::max(run.max_error_deg, error);
    if (error <= 2 * normal->sigma_rad * 180 / M_PI) ++run.within_2_sigma;
  }
  return run;
}

// The plan's sideways moves (its first 16 s) of `seed`: enough planes, each within a degree of
// the truth and within its own 2 sigma on at least 90 % of them.
void ExpectSoundPlanes(int seed, double noise_m) {
  const PlaneRun run = RunPlan(seed, 0, 16, 0.25, noise_m);
  std::printf("seed %d, arm noise %.1f mm: %d estimates, max error %.2f deg, %d within 2 sigma\n",
              seed, noise_m * 1e3, run.estimates, run.max_error_deg, run.within_2_sigma);
  EXPECT_GE(run.estimates, 20) << "seed " << seed;
  EXPECT_LT(run.max_error_deg, 1.0) << "seed " << seed;
  EXPECT_GE(run.within_2_sigma, 0.9 * run.estimates) << "seed " << seed;
}

TEST(ArmPlaneNormal, TheSidewaysMovesGiveThePushDirectionWithinADegree) {
  // Measured 2026-11-29: max error 0.35-0.46 deg on seeds 1-3, 46 estimates each.
  for (int seed : {1, 2, 3}) ExpectSoundPlanes(seed, 0);
}

TEST(ArmPlaneNormal, NoiseInTheArmsReportedPositionsMovesTheStartNotTheAnswer) {
  // 0.5 mm per axis per pose, as the simulator's recorded arm: the images decide the rotation
  // and the direction of the translation, the arm only the metric length. Measured 2026-11-29:
  // max error 0.35 and 0.51 deg. Fitting the plane alone with the arm's rotation and
  // translation as given was 0.7-3.3 deg off per frame on the recorded approach of seed 5.
  for (int seed : {1, 4}) ExpectSoundPlanes(seed, 0.0005);
}

TEST(ArmPlaneNormal, AMoveStraightAtTheButtonGivesNoPlane) {
  // The plan's approach (after its sideways moves): no parallax at the button, so no plane; the
  // refusal says why.
  const PlaneRun run = RunPlan(2, 30, 40, 0.25, 0);
  EXPECT_EQ(run.estimates, 0);
  ASSERT_FALSE(run.refusals.empty());
  int parallax = 0;
  for (const std::string& why : run.refusals) parallax += why.find("parallax") != why.npos;
  EXPECT_GT(parallax, 0);
}

TEST(ArmPlaneNormal, BadInputIsAnErrorNotACrash) {
  ArmPlaneNormal plane;
  ArmPlaneView view;
  EXPECT_EQ(plane.Add(view).status().code(), StatusCode::kInvalidArgument);  // No image.
  PanelNormalOptions bad;
  bad.arm_inlier_px = 0;
  ArmPlaneNormal with_bad(bad);
  view.image = cv::Mat(48, 64, CV_8UC1, cv::Scalar(128));
  const Status s = with_bad.Add(view).status();
  EXPECT_EQ(s.code(), StatusCode::kInvalidArgument);
  EXPECT_NE(s.message().find("button.normal.arm_inlier_px"), std::string::npos);
  // A blank picture has no corners: NotFound, said so, every time.
  view.camera.fx = view.camera.fy = 50;
  view.camera.cx = 32;
  view.camera.cy = 24;
  for (int i = 0; i < 3; ++i) {
    const Status blank = plane.Add(view).status();
    EXPECT_EQ(blank.code(), StatusCode::kNotFound);
    EXPECT_NE(blank.message().find("too few corners"), std::string::npos) << blank.message();
  }
}

}  // namespace
}  // namespace sightline
