#include "core/sim/renderer.h"

#include <gtest/gtest.h>

#include <cmath>

#include "core/sim/observations.h"
#include "core/sim/simulator.h"
#include "tests/core/sim/sim_test_util.h"

namespace sightline::sim {
namespace {

using testing::LookHorizontally;
using testing::MakeCamera;

// A large wall x = 3 facing the origin, a box and a bin in front of it.
Scene WallScene() {
  Scene scene("wall");
  const int grey = scene.AddMaterial({TextureKind::kChecker});
  const int wall = scene.AddObject(ObjectKind::kWall, "wall 0", 0);
  scene.AddRectangle(wall, grey, {3, 10, -10}, {0, -1, 0}, {0, 0, 1}, {20, 20});
  return scene;
}

TEST(Renderer, DepthEqualsAnalyticDistanceToAWallExactly) {
  const Scene scene = WallScene();
  const PinholeCamera camera = MakeCamera(640, 480, 525);
  Renderer renderer;
  RenderedView view;
  for (double yaw_deg : {0.0, 20.0, -35.0}) {
    const double yaw = yaw_deg * M_PI / 180;
    const Eigen::Isometry3d pose = LookHorizontally({0, 0.4, 1}, yaw);
    ASSERT_TRUE(renderer.Render(scene, {}, camera, pose, ImageKind::kColor, &view).ok());
    int checked = 0;
    for (int v = 0; v < camera.height; v += 7) {
      for (int u = 0; u < camera.width; u += 5) {
        // The ray through the pixel centre in the map frame; depth is z in the camera.
        const Eigen::Vector3d ray = pose.linear() * Eigen::Vector3d((u - camera.cx) / camera.fx,
                                                                    (v - camera.cy) / camera.fy, 1);
        const double z = (3.0 - pose.translation().x()) / ray.x();
        ASSERT_NEAR(view.depth_m.at<float>(v, u), z, 2e-6 * z)
            << u << "," << v << " yaw " << yaw_deg;
        EXPECT_EQ(view.object.at<int32_t>(v, u), 0);
        ++checked;
      }
    }
    EXPECT_GT(checked, 5000);
    // Incidence: cos = |n . ray| / |ray| with n = -x.
    const Eigen::Vector3d ray0 =
        pose.linear() * Eigen::Vector3d(-camera.cx / camera.fx, -camera.cy / camera.fy, 1);
    EXPECT_NEAR(view.incidence_cos.at<float>(0, 0), std::abs(ray0.x()) / ray0.norm(), 1e-6);
  }
}

TEST(Renderer, CurvedPrimitivesAndOcclusion) {
  Scene scene = WallScene();
  const int grey = scene.AddMaterial({TextureKind::kPlain});
  const int bin = scene.AddObject(ObjectKind::kBin, "bin", 0);
  scene.AddUprightCylinder(bin, grey, {2.0, 0, 0}, 0.25, 0.8);
  const int head = scene.AddObject(ObjectKind::kOther, "ball", 0);
  scene.Add({Sphere{{2.5, 0, 1.5}, 0.2}, grey, head});
  const PinholeCamera camera = MakeCamera(641, 481, 500);  // Pixel (320, 240) on the axis.
  Renderer renderer;
  RenderedView view;
  // Looking along +x from height 0.5: the centre ray hits the cylinder side at x = 1.75.
  ASSERT_TRUE(
      renderer.Render(scene, {}, camera, LookHorizontally({0, 0, 0.5}, 0), ImageKind::kGrey, &view)
          .ok());
  EXPECT_NEAR(view.depth_m.at<float>(240, 320), 1.75, 1e-5);
  EXPECT_EQ(view.object.at<int32_t>(240, 320), bin);
  // From height 1.5 the centre ray meets the sphere at x = 2.3.
  ASSERT_TRUE(
      renderer.Render(scene, {}, camera, LookHorizontally({0, 0, 1.5}, 0), ImageKind::kGrey, &view)
          .ok());
  EXPECT_NEAR(view.depth_m.at<float>(240, 320), 2.3, 1e-5);
  EXPECT_EQ(view.object.at<int32_t>(240, 320), head);
  EXPECT_EQ(view.image.type(), CV_8UC1);
}

TEST(Renderer, NothingHitIsNanAndBackground) {
  Scene scene("empty");
  scene.AddMaterial({});
  const PinholeCamera camera = MakeCamera(64, 48, 50);
  Renderer renderer;
  RenderedView view;
  ASSERT_TRUE(
      renderer.Render(scene, {}, camera, Eigen::Isometry3d::Identity(), ImageKind::kColor, &view)
          .ok());
  EXPECT_TRUE(std::isnan(view.depth_m.at<float>(10, 10)));
  EXPECT_EQ(view.object.at<int32_t>(10, 10), -1);
}

TEST(Renderer, RejectsInvalidAndDistortedCameras) {
  const Scene scene = WallScene();
  Renderer renderer;
  RenderedView view;
  PinholeCamera camera = MakeCamera(64, 48, 50);
  camera.distortion[0] = 0.1;
  Status s =
      renderer.Render(scene, {}, camera, Eigen::Isometry3d::Identity(), ImageKind::kNone, &view);
  EXPECT_EQ(s.code(), StatusCode::kInvalidArgument);
  EXPECT_NE(s.message().find("distortion"), std::string::npos);
  camera = MakeCamera(0, 48, 50);
  EXPECT_FALSE(
      renderer.Render(scene, {}, camera, Eigen::Isometry3d::Identity(), ImageKind::kNone, &view)
          .ok());
}

// The rendered button faces are centred where the camera model projects the button centres.
TEST(Renderer, ButtonCentresProjectWhereTheCameraModelSays) {
  SimulationOptions options = SimulationOptions::ForScene("panel");
  options.frames = 40;
  options.noise.profile = "none";
  auto sim = Simulator::Create(options);
  ASSERT_TRUE(sim.ok()) << sim.status().ToString();
  const PinholeCamera camera = sim->mono_camera();
  for (int frame : {0, 5, 39}) {
    SimulatedMono mono;
    ASSERT_TRUE(sim->RenderMono(frame, &mono).ok());
    const auto observations =
        ObserveButtons(sim->scene(), camera, mono.world_from_camera, mono.view, frame);
    ASSERT_EQ(observations.size(), 12u);
    int checked = 0;
    for (const ButtonObservation& o : observations) {
      const ButtonSpec& button = sim->scene().buttons[o.button];
      const Eigen::Vector3d x = mono.world_from_camera.inverse() * button.center;
      // Centroid of the pixels on the button's front face (the camera faces the panel, so the
      // face is at the constant depth x.z(); the rim's side lies deeper).
      double su = 0, sv = 0;
      int n = 0;
      for (int v = 0; v < camera.height; ++v) {
        for (int u = 0; u < camera.width; ++u) {
          if (mono.view.object.at<int32_t>(v, u) != button.object) continue;
          if (std::abs(mono.view.depth_m.at<float>(v, u) - x.z()) > 1e-4) continue;
          su += u, sv += v, ++n;
        }
      }
      if (!o.visible) continue;
      ASSERT_GT(n, 50) << "button " << o.button << " frame " << frame;
      const Eigen::Vector2d projected = camera.Project(x);
      EXPECT_NEAR(o.pixel.x(), projected.x(), 1e-9);
      EXPECT_NEAR(su / n, projected.x(), 0.5) << "button " << o.button << " frame " << frame;
      EXPECT_NEAR(sv / n, projected.y(), 0.5) << "button " << o.button << " frame " << frame;
      ++checked;
    }
    EXPECT_GE(checked, frame == 39 ? 1 : 12) << "frame " << frame;
  }
}

}  // namespace
}  // namespace sightline::sim
