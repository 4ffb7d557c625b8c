// The plane locator on synthetic map points (exact geometry, noise, outliers, degenerate
// views) and on the simulated panel with the true camera pose.
#include "core/button/button_locator.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>

#include "tests/core/button/panel_sim_util.h"
#include "tests/support/test_camera.h"

namespace sightline {
namespace {

// Points on the plane z = depth (camera frame = world frame) in a square of half side `half`.
std::vector<Eigen::Vector3d> PlanePoints(int n, double depth, double half, double noise,
                                         uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-half, half);
  std::normal_distribution<double> g(0, noise);
  std::vector<Eigen::Vector3d> points;
  for (int i = 0; i < n; ++i) points.emplace_back(u(rng), u(rng), depth + (noise > 0 ? g(rng) : 0));
  return points;
}

// A plate at 0.5 m (a 9 mm hole where the button is) and up to `face_points` points of a button
// face 5 mm proud of it, every point `noise` off; `behind_every` > 0 moves every such face point
// 2-6 cm behind the face (triangulated with little parallax).
std::vector<Eigen::Vector3d> PlateAndFace(int face_points, double noise, uint64_t seed,
                                          int behind_every = 0) {
  auto points = PlanePoints(700, 0.5, 0.06, noise, seed);
  std::erase_if(points, [](const Eigen::Vector3d& x) { return x.head<2>().norm() < 0.009; });
  auto face = PlanePoints(200, 0.495, 0.008, noise, seed + 100);
  std::erase_if(face, [](const Eigen::Vector3d& x) { return x.head<2>().norm() > 0.008; });
  face.resize(std::min<size_t>(face.size(), face_points));
  std::mt19937_64 rng(seed + 200);
  std::uniform_real_distribution<double> behind(0.02, 0.06);
  for (size_t i = 0; behind_every > 0 && i < face.size(); i += behind_every) {
    face[i].z() = 0.495 + behind(rng);
  }
  points.insert(points.end(), face.begin(), face.end());
  return points;
}

// The locator's input for the button at the image centre, 9 mm in radius at 0.495 m.
LocatorInput CentreButton(const std::vector<Eigen::Vector3d>* points) {
  LocatorInput in;
  in.camera = testing::VgaCamera();
  in.points_in_world = points;
  in.button_px = {319.5, 239.5};
  in.button_radius_px = 525 * 0.009 / 0.495;
  return in;
}

TEST(ButtonLocator, IntersectsTheRayWithAFrontoParallelPlane) {
  const auto points = PlanePoints(40, 0.5, 0.05, 0, 1);
  LocatorInput in;
  in.camera = testing::VgaCamera();
  in.points_in_world = &points;
  in.button_px = {330, 250};
  auto at = ButtonLocator().Locate(in);
  ASSERT_TRUE(at.ok()) << at.status().ToString();
  const Eigen::Vector3d expected = in.camera.Unproject(330, 250, 0.5);
  EXPECT_LT((at->button_in_camera - expected).norm(), 1e-9);
  EXPECT_NEAR(at->approach_in_camera.z(), 1.0, 1e-9);  // Push away from the camera.
  EXPECT_NEAR(at->normal_in_camera.z(), -1.0, 1e-9);   // Out of the panel, towards the camera.
  EXPECT_TRUE(at->plane_sound);
  EXPECT_LT(at->uncertainty_m, 1e-6);
}

TEST(ButtonLocator, ToleratesNoiseAndOutliers) {
  auto points = PlanePoints(60, 0.6, 0.05, 0.001, 2);
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(-0.05, 0.05), d(0.3, 1.0);
  for (int i = 0; i < 20; ++i) points.emplace_back(u(rng), u(rng), d(rng));  // 25 % outliers.
  LocatorInput in;
  in.camera = testing::VgaCamera();
  in.points_in_world = &points;
  in.button_px = {319.5, 239.5};
  in.scale_sigma_rel = 0.01;
  auto at = ButtonLocator().Locate(in);
  ASSERT_TRUE(at.ok()) << at.status().ToString();
  EXPECT_LT((at->button_in_camera - Eigen::Vector3d(0, 0, 0.6)).norm(), 0.002);
  EXPECT_GE(at->inliers, 50);
  EXPECT_TRUE(at->plane_sound);
  // The scale term dominates: 1 % of 0.6 m.
  EXPECT_NEAR(at->uncertainty_m, 0.006, 0.001);
}

TEST(ButtonLocator, AFewFacePointsMoveThePanelPlaneOntoTheButton) {
  // A plate at 0.5 m and a button face 5 mm proud of it, with only 4 points on the face.
  auto points = PlanePoints(60, 0.5, 0.05, 0.0005, 8);
  std::erase_if(points, [](const Eigen::Vector3d& x) { return x.head<2>().norm() < 0.012; });
  for (const Eigen::Vector2d& xy :
       {Eigen::Vector2d(0.003, 0.002), Eigen::Vector2d(-0.004, 0.001),
        Eigen::Vector2d(0.001, -0.005), Eigen::Vector2d(-0.002, -0.003)}) {
    points.emplace_back(xy.x(), xy.y(), 0.495);
  }
  LocatorInput in;
  in.camera = testing::VgaCamera();
  in.points_in_world = &points;
  in.button_px = {319.5, 239.5};
  in.button_radius_px = 525 * 0.012 / 0.495;  // A 12 mm button.
  auto at = ButtonLocator().Locate(in);
  ASSERT_TRUE(at.ok()) << at.status().ToString();
  EXPECT_TRUE(at->on_button);
  EXPECT_NEAR(at->button_in_camera.z(), 0.495, 0.001);
  in.button_radius_px = 0;  // Face unknown: the plate.
  auto plate = ButtonLocator().Locate(in);
  ASSERT_TRUE(plate.ok());
  EXPECT_FALSE(plate->on_button);
  EXPECT_NEAR(plate->button_in_camera.z(), 0.5, 0.001);
}

// A monocular map near the button is noisy by a centimetre (no parallax from the approach). A
// plate at 0.5 m and an 18 mm button 5 mm proud of it, every point 10 mm off along the view:
// the plane over six button radii moved onto the face by its points' median beats the face's
// own plane, and its stated sigma covers the error.
TEST(ButtonLocator, ACentimetreOfMapNoiseLeavesTheFaceWithinItsStatedSigma) {
  double sum2_wide = 0, sum2_face_plane = 0;
  int covered = 0, located = 0, face_plane_located = 0;
  const int draws = 40;
  for (int draw = 0; draw < draws; ++draw) {
    const auto points = PlateAndFace(30, 0.01, 100 + draw);
    const LocatorInput in = CentreButton(&points);
    auto wide = ButtonLocator().Locate(in);
    ButtonLocatorOptions own;
    own.panel_radii = 0;  // The face's own plane (its points are more than good_points).
    auto face_plane = ButtonLocator(own).Locate(in);
    ASSERT_TRUE(wide.ok()) << wide.status().ToString();
    ++located;
    const double error = wide->button_in_camera.z() - 0.495;
    sum2_wide += error * error;
    if (face_plane.ok()) {
      sum2_face_plane += std::pow(face_plane->button_in_camera.z() - 0.495, 2);
      ++face_plane_located;
    }
    EXPECT_TRUE(wide->on_button);
    if (std::abs(error) <= 2 * wide->uncertainty_m) ++covered;
  }
  const double rms_wide = std::sqrt(sum2_wide / located);
  const double rms_face_plane = std::sqrt(sum2_face_plane / std::max(1, face_plane_located));
  std::printf(
      "depth RMS over %d draws: %.2f mm (face's own plane: %.2f mm, located in %d); within 2 "
      "sigma %d\n",
      located, rms_wide * 1e3, rms_face_plane * 1e3, face_plane_located, covered);
  EXPECT_LT(rms_wide, 0.003);
  EXPECT_LT(rms_wide, 0.7 * rms_face_plane);
  EXPECT_GE(covered, 0.9 * draws);
}

TEST(ButtonLocator, AOneSidedTailOfFacePointsDoesNotDragTheFaceBack) {
  // A fifth of the face's points lie 2-6 cm behind it (triangulated with little parallax) on top
  // of a centimetre of noise: the plain median of the face's offsets moves the button back by
  // about a third of a sigma (3 mm), the median within 2.5 robust sigmas by far less.
  double bias_clipped = 0, bias_plain = 0;
  const int draws = 40;
  for (int draw = 0; draw < draws; ++draw) {
    const auto points = PlateAndFace(40, 0.01, 300 + draw, /*behind_every=*/5);
    const LocatorInput in = CentreButton(&points);
    auto clipped = ButtonLocator().Locate(in);
    ButtonLocatorOptions plain_options;
    plain_options.face_clip_sigmas = 0;
    auto plain = ButtonLocator(plain_options).Locate(in);
    ASSERT_TRUE(clipped.ok()) << clipped.status().ToString();
    ASSERT_TRUE(plain.ok()) << plain.status().ToString();
    bias_clipped += (clipped->button_in_camera.z() - 0.495) / draws;
    bias_plain += (plain->button_in_camera.z() - 0.495) / draws;
  }
  std::printf("mean depth error over %d draws: clipped %.2f mm, plain median %.2f mm\n", draws,
              bias_clipped * 1e3, bias_plain * 1e3);
  EXPECT_GT(bias_plain, 0.002);
  EXPECT_LT(std::abs(bias_clipped), 0.5 * bias_plain);
}

TEST(ButtonLocator, TooFewPointsIsNotFound) {
  const auto points = PlanePoints(2, 0.5, 0.01, 0, 4);
  LocatorInput in;
  in.camera = testing::VgaCamera();
  in.points_in_world = &points;
  in.button_px = {319.5, 239.5};
  auto at = ButtonLocator().Locate(in);
  ASSERT_FALSE(at.ok());
  EXPECT_EQ(at.status().code(), StatusCode::kNotFound);
}

TEST(ButtonLocator, GuardsNearParallelRays) {
  // A plane containing the optical axis (x = 0.001): the centre ray grazes it.
  std::vector<Eigen::Vector3d> points;
  for (int i = 0; i < 30; ++i)
    points.emplace_back(0.001, 0.01 * (i % 5) - 0.02, 0.4 + 0.02 * (i / 5));
  LocatorInput in;
  in.camera = testing::VgaCamera();
  in.points_in_world = &points;
  in.button_px = {320.8, 239.5};
  auto at = ButtonLocator().Locate(in);
  ASSERT_FALSE(at.ok());
  EXPECT_EQ(at.status().code(), StatusCode::kFailedPrecondition);
  EXPECT_NE(at.status().message().find("parallel"), std::string::npos);
}

TEST(ButtonLocator, FewPointsMakeAnUnsoundPlane) {
  const auto points = PlanePoints(4, 0.5, 0.02, 0, 5);
  LocatorInput in;
  in.camera = testing::VgaCamera();
  in.points_in_world = &points;
  in.button_px = {319.5, 239.5};
  auto at = ButtonLocator().Locate(in);
  ASSERT_TRUE(at.ok());
  EXPECT_FALSE(at->plane_sound);  // 4 < good_points = 6.
}

TEST(ButtonLocator, RejectsInvalidInput) {
  LocatorInput in;
  in.camera = testing::VgaCamera();
  EXPECT_EQ(ButtonLocator().Locate(in).status().code(),
            StatusCode::kInvalidArgument);  // No points.
  ButtonLocatorOptions bad;
  bad.min_points = 2;
  std::string error;
  EXPECT_FALSE(bad.IsValid(&error));
  EXPECT_NE(error.find("min_points"), std::string::npos);
  EXPECT_GT(ButtonLocatorOptions::Describe().entries().size(), 5u);
}

TEST(ButtonLocator, BaseFromCameraComposesTheHandEye) {
  Eigen::Isometry3d base_from_ee = Eigen::Isometry3d::Identity();
  base_from_ee.translation() = Eigen::Vector3d(0.5, 0, 0.2);
  Eigen::Isometry3d ee_from_camera = Eigen::Isometry3d::Identity();
  ee_from_camera.linear() =
      Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  ee_from_camera.translation() = Eigen::Vector3d(0.06, 0, -0.03);
  const Eigen::Vector3d x_in_base =
      BaseFromCamera(base_from_ee, ee_from_camera) * Eigen::Vector3d(1, 0, 0);
  EXPECT_LT((x_in_base - Eigen::Vector3d(0.56, 1, 0.17)).norm(), 1e-12);
}

// The simulated panel: points sampled from the exact render on and around the target button
// (standing in for the SLAM's map points), with 1 mm noise and 20 % outliers, and the true pose.
TEST(ButtonLocator, FindsTheSimulatedButtonWithinThreeMillimetres) {
  const testing::PanelApproach a = testing::RenderPanelApproach(0, 30);
  ASSERT_FALSE(a.frames.empty());
  const int b = a.target_button;
  std::mt19937_64 rng(7);
  std::normal_distribution<double> noise(0, 0.001);
  std::uniform_real_distribution<double> unit(0, 1);
  double worst_mm = 0;
  for (size_t f = 0; f < a.frames.size(); ++f) {
    const testing::PanelFrame& frame = a.frames[f];
    const Eigen::Vector2d c = a.Project(int(f), b);
    const double r = a.RadiusPx(int(f), b);
    std::vector<Eigen::Vector3d> points_in_world;
    for (int k = 0; k < 300; ++k) {
      // Pixels up to 3 radii around the button: its face, its rim and the plate.
      const double rho = 3 * r * std::sqrt(unit(rng)), phi = 2 * M_PI * unit(rng);
      const int u = int(std::lround(c.x() + rho * std::cos(phi)));
      const int v = int(std::lround(c.y() + rho * std::sin(phi)));
      if (u < 0 || v < 0 || u >= frame.depth_m.cols || v >= frame.depth_m.rows) continue;
      const float z = frame.depth_m.at<float>(v, u);
      if (!std::isfinite(z)) continue;
      Eigen::Vector3d x =
          a.camera.Unproject(u, v, z) + Eigen::Vector3d(noise(rng), noise(rng), noise(rng));
      if (unit(rng) < 0.2) x *= 0.7 + 0.6 * unit(rng);  // Outlier along the ray.
      points_in_world.push_back(frame.world_from_camera * x);
    }
    LocatorInput in;
    in.camera = a.camera;
    in.camera_from_world = frame.world_from_camera.inverse();
    in.points_in_world = &points_in_world;
    in.button_px = c;
    in.button_radius_px = r;
    auto at = ButtonLocator().Locate(in);
    ASSERT_TRUE(at.ok()) << "frame " << f * 30 << ": " << at.status().ToString();
    EXPECT_TRUE(at->on_button);
    EXPECT_TRUE(at->plane_sound);
    const Eigen::Vector3d truth = in.camera_from_world * a.buttons[b].center;
    const double err_mm = (at->button_in_camera - truth).norm() * 1e3;
    worst_mm = std::max(worst_mm, err_mm);
    EXPECT_LT(err_mm, 3.0) << "frame " << f * 30;
    // The approach direction is the panel's inward normal (+x in the map).
    const Eigen::Vector3d approach_in_world =
        frame.world_from_camera.linear() * at->approach_in_camera;
    EXPECT_GT(approach_in_world.dot(-a.buttons[b].normal), 0.99);
  }
  std::printf("locator on the simulated panel: worst 3D error %.2f mm over %zu frames\n", worst_mm,
              a.frames.size());
}

}  // namespace
}  // namespace sightline
