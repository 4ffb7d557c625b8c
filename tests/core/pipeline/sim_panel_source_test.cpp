// The live simulated camera sim://panel (core/pipeline/sim_panel_source.h): its URI, frames
// rendered from the newest pose on PoseBoard "arm" (the plan's start pose before any) with the
// pose's stamp, the tap on a true button and the hand-eye a run on it gets.
#include "core/pipeline/sim_panel_source.h"

#include <gtest/gtest.h>

#include <variant>

#include "core/button/arm_sim_session.h"
#include "core/io/hand_eye_file.h"
#include "core/pipeline/button_pipeline.h"
#include "core/pipeline/button_result.h"
#include "tests/support/test_data.h"

namespace sightline {
namespace {

TEST(SimPanelUri, ParsesSeedAndRateAndNamesWhatIsWrong) {
  StatusOr<SimPanelUri> plain = ParseSimPanelUri("sim://panel");
  ASSERT_TRUE(plain.ok()) << plain.status().ToString();
  EXPECT_EQ(plain->seed, 4);
  StatusOr<SimPanelUri> full = ParseSimPanelUri("sim://panel?seed=7&fps=2.5");
  ASSERT_TRUE(full.ok()) << full.status().ToString();
  EXPECT_EQ(full->seed, 7);
  EXPECT_EQ(full->fps, 2.5);
  const std::pair<const char*, const char*> bad[] = {
      {"sim://corridor", "unknown scene 'corridor'"},
      {"sim://panel?seed=x", "'seed=x'"},
      {"sim://panel?fps=0", "fps"},
      {"sim://panel?seed=1.5", "whole number"},
      {"sim://panel?color=red", "unknown key"},
      {"panel", "not a sim://"},
  };
  for (const auto& [uri, what] : bad) {
    StatusOr<SimPanelUri> parsed = ParseSimPanelUri(uri);
    ASSERT_FALSE(parsed.ok()) << uri;
    EXPECT_NE(parsed.status().message().find(what), std::string::npos) << parsed.status().message();
  }
  EXPECT_TRUE(IsLiveUri("sim://panel"));
  EXPECT_FALSE(IsLiveUri("/data/panel"));
  EXPECT_FALSE(OpenRunSource("sim://kitchen").ok());
}

// The image the source must show at `base_from_ee` for its `index`-th render.
cv::Mat Expected(int seed, const Eigen::Isometry3d& base_from_ee, int64_t index, double fps) {
  sim::SimulationOptions o = sim::SimulationOptions::ForScene("panel");
  o.seed = seed;
  o.frames = 1;
  StatusOr<sim::Simulator> simulator = sim::Simulator::Create(o);
  EXPECT_TRUE(simulator.ok());
  StatusOr<ArmSimWorld> world = BuildArmSimWorld(seed);
  EXPECT_TRUE(world.ok());
  sim::SimulatedMono mono;
  EXPECT_TRUE(
      simulator
          ->RenderMonoAt(world->world_from_base * base_from_ee * world->end_effector_from_camera,
                         index / fps, index, &mono)
          .ok());
  return mono.image;
}

TEST(SimPanelSource, RendersFromTheNewestArmPoseWithItsStamp) {
  PoseBoard::Global().Clear("arm");
  StatusOr<std::unique_ptr<Source>> opened = OpenRunSource("sim://panel?seed=6&fps=20");
  ASSERT_TRUE(opened.ok()) << opened.status().ToString();
  auto& source = static_cast<SimPanelSource&>(**opened);
  EXPECT_TRUE(source.info().live);
  EXPECT_EQ(source.info().kind, SourceKind::kMono);
  ASSERT_TRUE(source.info().camera.has_value());
  EXPECT_EQ(source.info().width, 640);
  StatusOr<ArmSimWorld> world = BuildArmSimWorld(6);
  ASSERT_TRUE(world.ok());
  // Before any pose: the plan's start pose.
  ASSERT_TRUE(source.Grab().ok());
  StatusOr<Frame> first = source.Retrieve();
  ASSERT_TRUE(first.ok());
  const cv::Mat start = Expected(6, world->PlanPose(0), source.last_grabbed().device_frame_id, 20);
  EXPECT_EQ(cv::norm(std::get<MonoFrame>(*first).image, start, cv::NORM_INF), 0);
  // A pose 10 cm to the side: the next frames show it, stamped with the pose's time.
  Eigen::Isometry3d moved = world->PlanPose(0);
  moved.translation().y() += 0.1;
  const double stamp = WallClockS() + 100;  // The arm's clock, ahead of every frame so far.
  PoseBoard::Global().Post("arm", stamp, moved);
  Frame frame;
  for (int i = 0; i < 20; ++i) {
    ASSERT_TRUE(source.Grab().ok());
    frame = *source.Retrieve();
    if (StampOf(frame).sensor_time_s == stamp) break;
  }
  ASSERT_EQ(StampOf(frame).sensor_time_s, stamp);
  const cv::Mat expected = Expected(6, moved, source.last_grabbed().device_frame_id, 20);
  EXPECT_EQ(cv::norm(std::get<MonoFrame>(frame).image, expected, cv::NORM_INF), 0);
  EXPECT_GT(cv::norm(expected, start, cv::NORM_L1), 0);
  // The arm holds still (no new pose): later frames keep its picture with later stamps.
  ASSERT_TRUE(source.Grab().ok());
  EXPECT_GT(StampOf(*source.Retrieve()).sensor_time_s, stamp);
  PoseBoard::Global().Clear("arm");
}

TEST(SimPanelSource, TapOnATrueButtonAndTheHandEyeOfARun) {
  StatusOr<ArmSimWorld> world = BuildArmSimWorld(4);
  ASSERT_TRUE(world.ok());
  // The plan looks straight at its button: its pixel is the principal point.
  StatusOr<std::string> centre = SimTapPixel("sim://panel?seed=4", world->plan_button);
  ASSERT_TRUE(centre.ok()) << centre.status().ToString();
  const PinholeCamera camera = sim::SimulationOptions::ForScene("panel").mono.Camera();
  StatusOr<ButtonTap> tap = ParseButtonTap(*centre);
  ASSERT_TRUE(tap.ok());
  EXPECT_NEAR(tap->x, camera.cx, 0.06);
  EXPECT_NEAR(tap->y, camera.cy, 0.06);
  EXPECT_EQ(tap->frame, 0);
  EXPECT_FALSE(SimTapPixel("sim://panel", 99).ok());

  OptionSet options;
  ASSERT_TRUE(ButtonPipelineInfo().declare_options(&options).ok());
  ASSERT_TRUE(options.ApplyOverride("button.run.tap=button:3").ok());
  const std::string out = testing::TempDir("sim_panel_run");
  ASSERT_TRUE(PrepareSimRun("sim://panel?seed=4", out, &options).ok());
  EXPECT_EQ(std::get<std::string>(*options.Get("button.run.tap")),
            *SimTapPixel("sim://panel?seed=4", 3));
  const std::string hand_eye = std::get<std::string>(*options.Get("mono.run.hand_eye"));
  StatusOr<HandEye> read = ReadHandEyeFile(hand_eye);
  ASSERT_TRUE(read.ok()) << read.status().ToString();
  EXPECT_LT(
      (read->end_effector_from_camera.matrix() - world->end_effector_from_camera.matrix()).norm(),
      1e-9);
  ASSERT_TRUE(read->world_from_base.has_value());
  // Other sources are left alone.
  OptionSet other;
  ASSERT_TRUE(ButtonPipelineInfo().declare_options(&other).ok());
  ASSERT_TRUE(other.ApplyOverride("button.run.tap=button:3").ok());
  ASSERT_TRUE(PrepareSimRun("/data/panel", out, &other).ok());
  EXPECT_EQ(std::get<std::string>(*other.Get("button.run.tap")), "button:3");
  ASSERT_TRUE(options.ApplyOverride("button.run.tap=button:x").ok());
  EXPECT_FALSE(PrepareSimRun("sim://panel", out, &options).ok());
}

}  // namespace
}  // namespace sightline
