#include "core/sim/simulator.h"

#include <gtest/gtest.h>

#include <set>

#include "core/options/option_set.h"

namespace sightline::sim {
namespace {

std::string InvalidMessage(const SimulationOptions& options) {
  auto sim = Simulator::Create(options);
  EXPECT_FALSE(sim.ok());
  if (sim.ok()) return "";
  EXPECT_EQ(sim.status().code(), StatusCode::kInvalidArgument);
  return sim.status().message();
}

TEST(SimulationOptions, DegenerateOptionsGiveClearErrors) {
  SimulationOptions o = SimulationOptions::ForScene("corridor");
  o.frames = 0;
  EXPECT_NE(InvalidMessage(o).find("sim.frames"), std::string::npos);
  o = SimulationOptions::ForScene("corridor");
  o.stereo.baseline_m = -0.11;
  EXPECT_NE(InvalidMessage(o).find("sim.stereo.baseline_m"), std::string::npos);
  o = SimulationOptions::ForScene("panel");
  o.mono.width = 100000;
  o.mono.height = 1;
  EXPECT_NE(InvalidMessage(o).find("sim.mono.width"), std::string::npos);
  o = SimulationOptions::ForScene("corridor");
  o.rgbd.resolution = "1920x1080";
  EXPECT_NE(InvalidMessage(o).find("sim.rgbd.resolution"), std::string::npos);
  o = SimulationOptions::ForScene("corridor");
  o.sensors = "rgbd,lidar";
  EXPECT_NE(InvalidMessage(o).find("lidar"), std::string::npos);
  o = SimulationOptions::ForScene("corridor");
  o.noise.profile = "loud";
  EXPECT_NE(InvalidMessage(o).find("sim.noise.profile"), std::string::npos);
  o = SimulationOptions::ForScene("garden");
  EXPECT_NE(InvalidMessage(o).find("sim.scene"), std::string::npos);
}

TEST(SimulationOptions, DescribeTableDeclaresEveryOptionWithValidDefaults) {
  OptionSet set;
  for (const std::string& scene : SceneNames()) {
    OptionSet per_scene;
    const SimulationOptions defaults = SimulationOptions::ForScene(scene);
    ASSERT_TRUE(per_scene.Declare(SimulationOptions::Describe(), defaults).ok()) << scene;
    std::string error;
    EXPECT_TRUE(defaults.IsValid(&error)) << scene << ": " << error;
  }
  ASSERT_TRUE(set.Declare(SimulationOptions::Describe()).ok());
  std::set<std::string> keys;
  for (const OptionSpec& spec : set.specs()) {
    EXPECT_TRUE(keys.insert(spec.key).second) << spec.key;
    EXPECT_FALSE(spec.description.empty()) << spec.key;
  }
  EXPECT_TRUE(keys.count("sim.stereo.baseline_m"));
  EXPECT_TRUE(keys.count("sim.corridor.people"));
  // --set overrides reach the typed struct.
  ASSERT_TRUE(set.ApplyOverride("sim.terrain.ramp_slope_deg=30").ok());
  EXPECT_EQ(set.Extract(SimulationOptions::Describe()).terrain.ramp_slope_deg, 30);
  EXPECT_FALSE(set.ApplyOverride("sim.stereo.baseline_m=-1").ok());
}

TEST(Simulator, RendersEveryBuiltInSceneAndRefusesFramesOutOfRange) {
  for (const std::string& scene : SceneNames()) {
    SimulationOptions o = SimulationOptions::ForScene(scene);
    o.frames = 3;
    o.rgbd.resolution = "320x240";
    auto sim = Simulator::Create(o);
    ASSERT_TRUE(sim.ok()) << scene << ": " << sim.status().ToString();
    SimulatedRgbd rgbd;
    ASSERT_TRUE(sim->RenderRgbd(0, &rgbd).ok());
    EXPECT_EQ(rgbd.color.size(), cv::Size(320, 240));
    EXPECT_EQ(rgbd.depth_m.type(), CV_32FC1);
    // Most of the image sees a surface with a valid depth reading.
    const int valid = cv::countNonZero(rgbd.depth_m == rgbd.depth_m);
    EXPECT_GT(valid, 320 * 240 / 3) << scene;
    EXPECT_TRUE(sim->RenderRgbd(2, &rgbd).ok());
    EXPECT_EQ(sim->RenderRgbd(3, &rgbd).code(), StatusCode::kOutOfRange);
    EXPECT_EQ(sim->RenderMono(-1, nullptr).code(), StatusCode::kOutOfRange);
  }
}

TEST(Simulator, StereoRightImageIsTheLeftShiftedByTheDisparity) {
  SimulationOptions o = SimulationOptions::ForScene("corridor");
  o.frames = 1;
  o.noise.profile = "none";
  o.corridor.people = 0;
  auto sim = Simulator::Create(o);
  ASSERT_TRUE(sim.ok());
  SimulatedStereo stereo;
  ASSERT_TRUE(sim->RenderStereo(0, &stereo).ok());
  const StereoRig rig = sim->stereo_rig();
  // Reproject left pixels with their exact depth into the right image: intensities agree.
  int compared = 0, equal = 0;
  for (int v = 40; v < stereo.left.rows - 40; v += 9) {
    for (int u = 60; u < stereo.left.cols - 60; u += 7) {
      const float z = stereo.left_view.depth_m.at<float>(v, u);
      if (!(z > 0.5f && z < 20)) continue;
      const double d = rig.left.fx * rig.BaselineM() / z;
      const int ur = static_cast<int>(std::lround(u - d));
      if (std::abs(ur - (u - d)) > 0.05 || ur < 0) continue;  // Only near-integer disparities.
      ++compared;
      equal += std::abs(stereo.left.at<uint8_t>(v, u) - stereo.right.at<uint8_t>(v, ur)) <= 3;
    }
  }
  ASSERT_GT(compared, 50);
  EXPECT_GT(equal, compared * 8 / 10);
}

TEST(Simulator, CustomScenesUseTheirOwnHints) {
  Scene scene("room");
  const int grey = scene.AddMaterial({TextureKind::kChecker});
  const int wall = scene.AddObject(ObjectKind::kWall, "wall 0", 0);
  scene.AddRectangle(wall, grey, {3, 2, 0}, {0, -1, 0}, {0, 0, 1}, {4, 2.5});
  scene.hints.route = {{0, 0}, {1, 0}};
  SimulationOptions o;
  o.frames = 2;
  o.sensors = "mono";
  auto sim = Simulator::Create(o, scene);
  ASSERT_TRUE(sim.ok()) << sim.status().ToString();
  SimulatedMono mono;
  ASSERT_TRUE(sim->RenderMono(0, &mono).ok());
  // The camera (0.1 m ahead of the robot) looks at the wall 2.9 m ahead, pitched down 10 deg.
  const PinholeCamera c = sim->mono_camera();
  EXPECT_NEAR(mono.view.depth_m.at<float>(static_cast<int>(c.cy), static_cast<int>(c.cx)),
              2.9 / std::cos(10 * M_PI / 180), 2e-3);
}

}  // namespace
}  // namespace sightline::sim
