// Odometry and arm poses from a bag's tf (io.rosbag.odom_frame / base_frame, arm_base_frame /
// end_effector_frame): the same runs as from an Odometry topic or arm_poses.txt, and a missing
// frame named with its option key.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>

#include "core/common/trajectory.h"
#include "core/pipeline/button_pipeline.h"
#include "core/pipeline/mapping_pipeline.h"
#include "core/pipeline/mapping_recording.h"
#include "core/pipeline/pipeline_registry.h"
#include "core/ros/bag_source.h"
#include "core/ros/bag_writer.h"
#include "core/sim/simulate.h"
#include "core/sim/simulator.h"
#include "tests/ros/bag_test_writer.h"
#include "tests/support/run_figures.h"
#include "tests/support/test_data.h"

namespace sightline {
namespace {

namespace fs = std::filesystem;

bool Contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

StatusOr<RunReport> RunOn(const std::string& pipeline, const std::string& path,
                          const std::string& out, const std::vector<std::string>& overrides = {}) {
  RunRequest request;
  request.pipeline = pipeline;
  request.dataset_path = path;
  request.out_dir = out;
  request.overrides = overrides;
  return RunPipeline(BuiltinPipelines(), request);
}

std::string ReadText(const std::string& path) {
  std::ifstream in(path);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

Trajectory Estimate(const std::string& out) {
  StatusOr<Trajectory> t = ReadTumTrajectory(out + "/trajectory.txt");
  return t.ok() ? *t : Trajectory();
}

// The corridor with its odometry on /odom and the same corridor with it only on /tf: the same
// odometry at the frames and the same map.
TEST(BagTf, OdometryOnlyOnTfMapsAsTheOdometryTopic) {
  const std::string dir = testing::TempDir("bag_tf_odometry");
  testing::SimBagOptions options;
  options.frames = 12;
  options.stereo = false;
  StatusOr<testing::SimBag> topic = testing::WriteSimBag(dir + "/topic.bag", options);
  ASSERT_TRUE(topic.ok()) << topic.status().ToString();
  options.odometry_on_tf = true;
  StatusOr<testing::SimBag> tf = testing::WriteSimBag(dir + "/tf.bag", options);
  ASSERT_TRUE(tf.ok()) << tf.status().ToString();

  BagSource a(dir + "/topic.bag"), b(dir + "/tf.bag");
  ASSERT_TRUE(a.Open().ok());
  const Status opened = b.Open();
  ASSERT_TRUE(opened.ok()) << opened.ToString();
  EXPECT_TRUE(b.choice().odometry.empty());
  ASSERT_NE(b.odometry(), nullptr);
  ASSERT_NE(a.odometry(), nullptr);
  // The camera's truth is still world -> camera, not the odometry's transform.
  ASSERT_NE(b.ground_truth(), nullptr);
  EXPECT_TRUE(b.ground_truth()->poses()[3].world_from_sensor.isApprox(
      tf->camera_truth.poses()[3].world_from_sensor, 1e-9));
  // At every frame stamp, the pose the odometry topic gives there.
  ASSERT_EQ(b.odometry()->size(), size_t(b.info().frame_count));
  for (int64_t i = 0; i < b.info().frame_count; ++i) {
    const TimedPose& p = b.odometry()->poses()[size_t(i)];
    EXPECT_NEAR(p.time_s, b.FrameTimeS(i), 1e-9);
    std::optional<size_t> j = a.odometry()->Nearest(p.time_s, 1e-6);
    ASSERT_TRUE(j.has_value()) << "no odometry message at frame " << i;
    EXPECT_TRUE(p.world_from_sensor.isApprox(a.odometry()->poses()[*j].world_from_sensor, 1e-9));
  }
  bool noted = false;
  for (const std::string& note : b.info().notes) noted |= Contains(note, "odometry: tf odom");
  EXPECT_TRUE(noted);

  StatusOr<RunReport> from_topic = RunOn("mapping", dir + "/topic.bag", dir + "/out_topic");
  ASSERT_TRUE(from_topic.ok()) << from_topic.status().ToString();
  StatusOr<RunReport> from_tf = RunOn("mapping", dir + "/tf.bag", dir + "/out_tf");
  ASSERT_TRUE(from_tf.ok()) << from_tf.status().ToString();
  for (const std::string out : {"/out_topic", "/out_tf"}) {
    const std::string log = ReadText(dir + out + "/mapping_log.txt");
    EXPECT_TRUE(Contains(log, "pose source: the recording's odometry (12 poses)")) << out << log;
  }
  const std::map<std::string, double> x = testing::RunFigures(*from_topic),
                                      y = testing::RunFigures(*from_tf);
  ASSERT_EQ(x.size(), y.size());
  for (const auto& [key, value] : x) {
    ASSERT_EQ(y.count(key), 1u) << key;
    EXPECT_NEAR(y.at(key), value, 1e-6 * std::max(1.0, std::abs(value))) << key;
  }
  const Trajectory ex = Estimate(dir + "/out_topic"), ey = Estimate(dir + "/out_tf");
  ASSERT_GT(ex.size(), 0u);
  ASSERT_EQ(ex.size(), ey.size());
  for (size_t i = 0; i < ex.size(); ++i) {
    EXPECT_LT((ex.poses()[i].world_from_sensor.translation() -
               ey.poses()[i].world_from_sensor.translation())
                  .norm(),
              1e-6);
  }
}

TEST(BagTf, AMissingFrameIsNamedWithItsOptionKey) {
  const std::string path = testing::TempDir("bag_tf_missing") + "/m.bag";
  PinholeCamera camera;
  camera.width = 32, camera.height = 24, camera.fx = camera.fy = 30, camera.cx = 16, camera.cy = 12;
  {
    StatusOr<std::unique_ptr<BagWriter>> bag = BagWriter::Create(path);
    ASSERT_TRUE(bag.ok());
    for (int i = 0; i < 3; ++i) {
      const double t = 50.0 + 0.1 * i;
      ASSERT_TRUE((*bag)->WriteMonoFrame(t, cv::Mat(24, 32, CV_8UC1, cv::Scalar(9)), camera).ok());
      ASSERT_TRUE((*bag)->WriteTransform(t, "odom", "robot", Eigen::Isometry3d::Identity()).ok());
      ASSERT_TRUE(
          (*bag)->WriteTransform(t, "wrist", "end_effector", Eigen::Isometry3d::Identity()).ok());
    }
    ASSERT_TRUE((*bag)->Close().ok());
  }
  BagSource source(path);
  const Status opened = source.Open();
  ASSERT_FALSE(opened.ok());
  EXPECT_TRUE(Contains(opened.message(), "'base_link'")) << opened.message();
  EXPECT_TRUE(Contains(opened.message(), "io.rosbag.base_frame")) << opened.message();
  EXPECT_TRUE(Contains(opened.message(), "robot")) << opened.message();  // The frames it has.
  // Naming the frames opens it; the arm's base is then the missing one.
  RosBagOptions options;
  options.base_frame = "robot";
  BagSource renamed(path, options);
  const Status arm = renamed.Open();
  ASSERT_FALSE(arm.ok());
  EXPECT_TRUE(Contains(arm.message(), "io.rosbag.arm_base_frame")) << arm.message();
  options.arm_base_frame = "wrist";
  BagSource both(path, options);
  ASSERT_TRUE(both.Open().ok());
  ASSERT_NE(both.odometry(), nullptr);
  ASSERT_NE(both.arm_poses(), nullptr);
  EXPECT_EQ(both.arm_poses()->size(), 3u);
}

// The arm's base on /tf_static below base_link, the end effector moving on /tf at 50 Hz: the arm
// poses at the 10 Hz frame stamps are the chain, interpolated.
TEST(BagTf, ArmPosesChainStaticAndDynamicTransformsAtTheFrameStamps) {
  const std::string path = testing::TempDir("bag_tf_arm") + "/a.bag";
  PinholeCamera camera;
  camera.width = 32, camera.height = 24, camera.fx = camera.fy = 30, camera.cx = 16, camera.cy = 12;
  Eigen::Isometry3d base_from_mount = Eigen::Isometry3d::Identity();
  base_from_mount.translation() = Eigen::Vector3d(0.2, 0, 0.4);
  base_from_mount.linear() = Eigen::AngleAxisd(0.5, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  auto mount_from_ee = [](double t) {
    Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
    pose.translation() = Eigen::Vector3d(0.1 * (t - 20), 0.3, 0);
    return pose;
  };
  {
    StatusOr<std::unique_ptr<BagWriter>> bag = BagWriter::Create(path, "lz4");
    ASSERT_TRUE(bag.ok());
    ASSERT_TRUE((*bag)->WriteTransform(20.0, "base_link", "arm_mount", base_from_mount, true).ok());
    for (int i = 0; i <= 25; ++i) {
      const double t = 20.0 + 0.02 * i;
      ASSERT_TRUE((*bag)->WriteTransform(t, "arm_mount", "end_effector", mount_from_ee(t)).ok());
    }
    for (int i = 0; i < 5; ++i) {
      const double t = 20.01 + 0.1 * i;
      ASSERT_TRUE((*bag)->WriteMonoFrame(t, cv::Mat(24, 32, CV_8UC1, cv::Scalar(9)), camera).ok());
    }
    ASSERT_TRUE((*bag)->Close().ok());
  }
  BagSource source(path);
  const Status opened = source.Open();
  ASSERT_TRUE(opened.ok()) << opened.ToString();
  ASSERT_NE(source.arm_poses(), nullptr);
  EXPECT_EQ(source.odometry(), nullptr);  // No odom frame.
  ASSERT_EQ(source.arm_poses()->size(), 5u);
  for (int i = 0; i < 5; ++i) {
    const TimedPose& p = source.arm_poses()->poses()[size_t(i)];
    EXPECT_NEAR(p.time_s, source.FrameTimeS(i), 1e-9);
    EXPECT_TRUE(p.world_from_sensor.isApprox(base_from_mount * mount_from_ee(p.time_s), 1e-7))
        << "frame " << i;
  }
  // A gap limit below the 20 ms between samples refuses every frame, naming the frames.
  RosBagOptions strict;
  strict.tf_max_gap_s = 0.01;
  BagSource refused(path, strict);
  const Status gap = refused.Open();
  ASSERT_FALSE(gap.ok());
  EXPECT_TRUE(Contains(gap.message(), "tf base_link -> end_effector at 20.010 s")) << gap.message();
}

// The simulated panel approach as a folder (arm_poses.txt) and as a bag whose arm is only on
// /tf base_link -> end_effector: the same metric scale and the same target, within the accuracy
// the folder run has against the true button.
TEST(BagTf, ButtonWithTheArmOnTfMatchesArmPosesTxt) {
  const std::string dir = testing::TempDir("bag_tf_button");
  sim::SimulationOptions options = sim::SimulationOptions::ForScene("panel");
  options.arm.sideways_m = 0.12;
  ASSERT_TRUE(sim::Simulate(options, dir + "/folder").ok());
  fs::create_directories(dir + "/bag");
  for (const char* name : {"hand_eye.yaml", "buttons.csv", "scene.yaml"}) {
    if (fs::exists(dir + "/folder/" + name)) {
      fs::copy_file(dir + "/folder/" + name, dir + "/bag/" + name);
    }
  }
  ASSERT_FALSE(fs::exists(dir + "/bag/arm_poses.txt"));
  StatusOr<sim::Simulator> simulator = sim::Simulator::Create(options);
  ASSERT_TRUE(simulator.ok()) << simulator.status().ToString();
  constexpr double kEpochS = 1.0;  // A bag holds no time 0.
  {
    StatusOr<std::unique_ptr<BagWriter>> bag = BagWriter::Create(dir + "/bag/panel.bag");
    ASSERT_TRUE(bag.ok());
    for (int i = 0; i < simulator->frames(); ++i) {
      sim::SimulatedMono f;
      ASSERT_TRUE(simulator->RenderMono(i, &f).ok());
      const double t = kEpochS + simulator->TimeOf(i);
      ASSERT_TRUE((*bag)->WriteMonoFrame(t, f.image, simulator->mono_camera()).ok());
      ASSERT_TRUE(
          (*bag)->WriteTransform(t, "world", BagWriter::kMonoFrameId, f.world_from_camera).ok());
    }
    for (const TimedPose& p : simulator->ArmPoses().poses()) {
      ASSERT_TRUE(
          (*bag)
              ->WriteTransform(kEpochS + p.time_s, "base_link", "end_effector", p.world_from_sensor)
              .ok());
    }
    ASSERT_TRUE((*bag)->Close().ok());
  }
  StatusOr<std::vector<TrueButton>> buttons = ReadTrueButtons(dir + "/folder/buttons.csv");
  ASSERT_TRUE(buttons.ok()) << buttons.status().ToString();
  std::string tap;
  for (const TrueButton& b : *buttons) {
    if (b.id == 5) {
      tap = "button.run.tap=" + std::to_string(b.pixel[0].x() + 2) + "," +
            std::to_string(b.pixel[0].y() - 2) + "@0";
    }
  }
  ASSERT_FALSE(tap.empty());
  StatusOr<RunReport> folder = RunOn("button", dir + "/folder", dir + "/out_folder", {tap});
  ASSERT_TRUE(folder.ok()) << folder.status().ToString();
  StatusOr<RunReport> bag = RunOn("button", dir + "/bag/panel.bag", dir + "/out_bag", {tap});
  ASSERT_TRUE(bag.ok()) << bag.status().ToString();
  const std::map<std::string, double> x = testing::RunFigures(*folder),
                                      y = testing::RunFigures(*bag);
  for (const char* key : {"accuracy/final_error_mm", "accuracy/scale_ml", "accuracy/scale_true",
                          "accuracy/targets_sent"}) {
    ASSERT_EQ(x.count(key), 1u) << key;
    ASSERT_EQ(y.count(key), 1u) << key;
  }
  EXPECT_EQ(y.at("counts/metric_from_arm_stream"), 0);
  EXPECT_GT(y.at("accuracy/targets_sent"), 0);
  EXPECT_EQ(y.at("accuracy/targets_sent"), x.at("accuracy/targets_sent"));
  // The folder's run is within 3 mm of the true button; the bag's target within 0.5 mm of it.
  EXPECT_LT(x.at("accuracy/final_error_mm"), 3.0);
  EXPECT_LT(y.at("accuracy/final_error_mm"), 3.0);
  EXPECT_NEAR(y.at("accuracy/final_error_mm"), x.at("accuracy/final_error_mm"), 0.5);
  EXPECT_NEAR(y.at("accuracy/scale_ml") / x.at("accuracy/scale_ml"), 1.0, 1e-3);
  EXPECT_NEAR(y.at("accuracy/scale_true"), x.at("accuracy/scale_true"),
              1e-3 * x.at("accuracy/scale_true"));
}

// A live source (ros://) has no odometry when the pipeline opens: mapping takes each frame's
// pose from the source's odometry as it grows (RosLive.OdometryAndArmPosesFromTfAtTheFrameStamps
// shows the source extending it at each frame's stamp).
TEST(BagTf, MappingTakesALiveSourcesOdometryFrameByFrame) {
  auto live = std::make_shared<Trajectory>();
  PipelineSource source;
  source.info.live = true;
  source.info.path = "ros://?image=/c/image&depth=/c/depth";
  PinholeCamera camera;
  camera.width = 8, camera.height = 6, camera.fx = camera.fy = 5, camera.cx = 4, camera.cy = 3;
  RgbdCalibration rgbd;
  rgbd.color = camera;
  source.info.rgbd = rgbd;
  source.live_odometry = [live] { return live->empty() ? nullptr : live.get(); };
  StatusOr<MappingRecording> recording = LoadMappingRecording(source, MappingRunOptions());
  ASSERT_TRUE(recording.ok()) << recording.status().ToString();
  ASSERT_FALSE(recording->odometry.has_value());
  EXPECT_TRUE(Contains(recording->log_lines.front(), "live source's odometry"));
  RgbdFrame frame;
  frame.stamp.sensor_time_s = 30.0;
  frame.depth_m = cv::Mat(6, 8, CV_32FC1, cv::Scalar(1));
  EXPECT_FALSE(recording->MakeInput(frame, 0.02).odometry.has_value());  // Nothing yet.
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.translation() = Eigen::Vector3d(1.5, -2, 0);
  pose.linear() = Eigen::AngleAxisd(0.4, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  live->Add(30.0, pose);  // The source's pose at this frame's stamp, added by its Retrieve.
  const std::optional<Pose2d> odometry = recording->MakeInput(frame, 0.02).odometry;
  ASSERT_TRUE(odometry.has_value());
  const double forward = recording->camera_forward_m;
  EXPECT_NEAR(odometry->x, 1.5 + forward * std::cos(0.4), 1e-9);
  EXPECT_NEAR(odometry->y, -2 + forward * std::sin(0.4), 1e-9);
  EXPECT_NEAR(odometry->heading_rad, 0.4, 1e-9);
}

}  // namespace
}  // namespace sightline
