// Indoor mapping from the command line as a user runs it: simulate a corridor, calibrate the
// floor, run the mapping pipeline, check its files and metrics.json.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>

#include "tests/app/process.h"
#include "tests/support/test_data.h"

namespace sightline {
namespace {

const std::string kCli = std::string(SIGHTLINE_BIN_DIR) + "/sightline-cli";

testing::ProcessResult Cli(const std::string& args) {
  return testing::RunProcess(kCli + " " + args);
}

bool Contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

// A 100-frame corridor drive (20 m at 1 m/s, 5 Hz, the first left turn included) at 320x240
// with wheel odometry drifting 2 deg/m, simulated once for all tests.
class MappingCli : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = new std::string(testing::TempDir("mapping_cli") + "/corridor");
    const auto r =
        Cli("simulate corridor --out " + *dir_ +
            " --frames 100 --seed 3 --sensors rgbd --quiet"
            " --set sim.rgbd.resolution=320x240 --set sim.rate_hz=5"
            " --set sim.motion.speed_mps=1 --set sim.odometry.heading_drift_deg_per_m=2");
    ASSERT_EQ(r.exit_code, 0) << r.out;
  }
  static void TearDownTestSuite() {
    delete dir_;
    dir_ = nullptr;
  }
  static std::string* dir_;
};

std::string* MappingCli::dir_ = nullptr;

TEST_F(MappingCli, RunWritesTrajectoryLinesMapAndMetrics) {
  const std::string out = testing::TempDir("mapping_cli_run");
  const auto r = Cli("run mapping " + *dir_ + " --out " + out);
  ASSERT_EQ(r.exit_code, 0) << r.out;
  EXPECT_TRUE(Contains(r.out, "mapping on")) << r.out;
  EXPECT_TRUE(Contains(r.out, "accuracy.heading_error_deg_max")) << r.out;
  for (const char* file : {"trajectory.txt", "lines.csv", "map.pgm", "map.yaml", "map.png",
                           "floor.yaml", "mapping_log.txt", "metrics.json"}) {
    EXPECT_TRUE(std::filesystem::exists(out + "/" + file)) << file;
  }
  const std::string metrics = testing::ReadTextFile(out + "/metrics.json");
  EXPECT_TRUE(Contains(metrics, "\"pipeline\": \"mapping\"")) << metrics;
  EXPECT_TRUE(Contains(metrics, "\"frames\": 100")) << metrics;
  for (const char* stage : {"occupancy", "scan", "lines", "rotation", "stitch", "total"}) {
    const auto median = testing::JsonNumber(metrics, stage, "median");
    const auto p95 = testing::JsonNumber(metrics, stage, "p95");
    ASSERT_TRUE(median && p95) << stage;
    EXPECT_GE(*median, 0) << stage;
    EXPECT_GE(*p95, *median) << stage;
  }
  const auto value = [&](const char* key) { return testing::JsonNumber(metrics, "accuracy", key); };
  ASSERT_TRUE(value("heading_error_deg_mean") && value("heading_error_deg_max") &&
              value("wall_angle_error_deg_median") && value("ate_rmse_m") && value("map_iou"))
      << metrics;
  // 20 m with odometry drifting 2 deg/m (40 deg uncorrected).
  EXPECT_LT(*value("heading_error_deg_max"), 1.5);
  EXPECT_LT(*value("heading_error_deg_mean"), 0.5);
  EXPECT_LT(*value("wall_angle_error_deg_median"), 0.5);
  EXPECT_LT(*value("ate_rmse_m"), 0.3);  // The simulator's odometry is 1 % long.
  EXPECT_GT(*value("map_iou"), 0.5);
  EXPECT_LE(*value("map_iou"), 1.0);
  EXPECT_EQ(testing::JsonNumber(metrics, "counts", "resets").value_or(-1), 0);

  // lines.csv: header, then frame, time, line id, end points, angle, inliers, ...
  std::ifstream lines(out + "/lines.csv");
  std::string header, first;
  std::getline(lines, header);
  std::getline(lines, first);
  EXPECT_TRUE(Contains(header, "frame,time_s,line,x1_m,y1_m,x2_m,y2_m,angle_deg,inliers"))
      << header;
  EXPECT_EQ(std::count(first.begin(), first.end(), ','), 10) << first;
  // map.yaml in the ROS map_server convention.
  const std::string yaml = testing::ReadTextFile(out + "/map.yaml");
  EXPECT_TRUE(Contains(yaml, "image: map.pgm")) << yaml;
  EXPECT_TRUE(Contains(yaml, "resolution: 0.05")) << yaml;
  // trajectory.txt: one TUM pose per frame.
  std::ifstream trajectory(out + "/trajectory.txt");
  int poses = 0;
  for (std::string line; std::getline(trajectory, line);) poses += !line.empty() && line[0] != '#';
  EXPECT_EQ(poses, 100);
}

TEST_F(MappingCli, WithoutManhattanCorrectionTheHeadingDrifts) {
  const std::string out = testing::TempDir("mapping_cli_off");
  const auto r = Cli("run mapping " + *dir_ + " --out " + out +
                     " --set mapping.rotation.enabled=false --set mapping.run.max_frames=60");
  ASSERT_EQ(r.exit_code, 0) << r.out;
  const std::string metrics = testing::ReadTextFile(out + "/metrics.json");
  const auto max = testing::JsonNumber(metrics, "accuracy", "heading_error_deg_max");
  ASSERT_TRUE(max);
  EXPECT_GT(*max, 10.0);  // 12 m at 2 deg/m.
}

TEST_F(MappingCli, FloorCalibrationFileIsWrittenAndUsed) {
  const std::string out = testing::TempDir("mapping_cli_floor");
  const auto floor = Cli("floor " + *dir_ + " --out " + out + "/floor.yaml --frames 3");
  ASSERT_EQ(floor.exit_code, 0) << floor.out;
  EXPECT_TRUE(Contains(floor.out, "camera 0.80")) << floor.out;  // The robot's Kinect at 0.8 m.
  const std::string yaml = testing::ReadTextFile(out + "/floor.yaml");
  EXPECT_TRUE(Contains(yaml, "camera_height_m: 0.80")) << yaml;
  EXPECT_TRUE(Contains(yaml, "pitch_down_deg: 10.0")) << yaml;  // Tilted 10 deg down.
  const auto run = Cli("run mapping " + *dir_ + " --out " + out +
                       "/run --set mapping.run.max_frames=10"
                       " --set mapping.run.floor_file=" +
                       out + "/floor.yaml");
  ASSERT_EQ(run.exit_code, 0) << run.out;
  EXPECT_TRUE(Contains(testing::ReadTextFile(out + "/run/mapping_log.txt"),
                       "floor: " + out + "/floor.yaml"));
}

// The same drive without odometry.txt: the translation comes from RGB-D odometry on the frames
// (asked for, or by auto), the log and metrics.json say so and time it, and the trajectory and
// map are as good as with the wheel odometry. Asking for the recording's odometry is an error.
TEST_F(MappingCli, WithoutOdometryTxtRgbdOdometryGivesTheTranslation) {
  namespace fs = std::filesystem;
  const std::string copy = testing::TempDir("mapping_cli_no_odometry") + "/corridor";
  fs::copy(*dir_, copy, fs::copy_options::recursive);
  ASSERT_TRUE(fs::remove(copy + "/odometry.txt"));
  const std::string out_wheel = testing::TempDir("mapping_cli_wheel_run");
  const std::string out_rgbd = testing::TempDir("mapping_cli_rgbd_run");
  const std::string out_auto = testing::TempDir("mapping_cli_auto_run");
  const auto wheel = Cli("run mapping " + *dir_ + " --out " + out_wheel);
  const auto rgbd =
      Cli("run mapping " + copy + " --out " + out_rgbd + " --set mapping.pose.source=rgbd");
  const auto automatic = Cli("run mapping " + copy + " --out " + out_auto);
  ASSERT_EQ(wheel.exit_code, 0) << wheel.out;
  ASSERT_EQ(rgbd.exit_code, 0) << rgbd.out;
  ASSERT_EQ(automatic.exit_code, 0) << automatic.out;
  EXPECT_TRUE(Contains(rgbd.out,
                       "pose source used: rgbd in 100 frame(s), 0 failed odometry "
                       "step(s) (mapping.pose.source=rgbd)"))
      << rgbd.out;
  const std::string log = testing::ReadTextFile(out_rgbd + "/mapping_log.txt");
  EXPECT_TRUE(Contains(log, "pose source: RGB-D odometry on the frames")) << log;
  EXPECT_TRUE(Contains(log, "pose source used: rgbd in 100 frame(s)")) << log;
  const std::string auto_log = testing::ReadTextFile(out_auto + "/mapping_log.txt");
  EXPECT_TRUE(Contains(auto_log, "pose source used: rgbd in 100 frame(s)")) << auto_log;
  const std::string wheel_log = testing::ReadTextFile(out_wheel + "/mapping_log.txt");
  EXPECT_TRUE(Contains(wheel_log, "pose source used: recording in 100 frame(s)")) << wheel_log;

  const std::string a = testing::ReadTextFile(out_wheel + "/metrics.json");
  const std::string b = testing::ReadTextFile(out_rgbd + "/metrics.json");
  EXPECT_TRUE(Contains(b, "\"odometry\": {")) << b;  // timing_ms.odometry
  EXPECT_FALSE(Contains(a, "\"odometry\": {")) << a;
  EXPECT_EQ(testing::JsonNumber(b, "counts", "odometry_failures"), 0.0) << b;
  EXPECT_EQ(testing::JsonNumber(b, "counts", "frames_pose_rgbd"), 100.0) << b;
  const auto value = [](const std::string& m, const char* key) {
    return testing::JsonNumber(m, "accuracy", key);
  };
  ASSERT_TRUE(value(a, "ate_rmse_m") && value(b, "ate_rmse_m") && value(b, "map_iou")) << b;
  // 20 m with a turn: without any translation the ATE would be metres.
  EXPECT_LT(*value(b, "ate_rmse_m"), 0.1);
  EXPECT_LT(*value(b, "ate_rmse_m"), *value(a, "ate_rmse_m") + 0.05);
  EXPECT_GT(*value(b, "map_iou"), *value(a, "map_iou") - 0.06);

  const auto missing =
      Cli("run mapping " + copy + " --out " + testing::TempDir("mapping_cli_recording_run") +
          " --set mapping.pose.source=recording");
  EXPECT_NE(missing.exit_code, 0);
  EXPECT_TRUE(Contains(missing.out, "mapping.pose.source=recording, but")) << missing.out;
}

TEST(MappingCliErrors, ClearMessages) {
  const auto help = Cli("floor --help");
  EXPECT_EQ(help.exit_code, 0);
  EXPECT_TRUE(Contains(help.out, "usage: sightline-cli floor PATH --out FILE")) << help.out;
  EXPECT_TRUE(Contains(Cli("--help").out, "floor PATH"));
  const std::string dir = testing::TempDir("mapping_cli_errors");
  const auto missing = Cli("floor " + dir + "/absent --out " + dir + "/floor.yaml");
  EXPECT_NE(missing.exit_code, 0);
  EXPECT_TRUE(Contains(missing.out, "absent")) << missing.out;
  const auto bad_key = Cli("floor " + dir + " --out x.yaml --set mapping.floor.nope=1");
  EXPECT_NE(bad_key.exit_code, 0);
  EXPECT_TRUE(Contains(bad_key.out, "mapping.floor.nope")) << bad_key.out;
  const auto bad_file = Cli("run mapping " + dir + "/absent --out " + dir + "/run");
  EXPECT_NE(bad_file.exit_code, 0);
  EXPECT_TRUE(Contains(bad_file.out, "absent")) << bad_file.out;
}

TEST(MappingCliRealData, FloorOfAPcdCloud) {
  SIGHTLINE_REQUIRE_DATA(path, "pcl_clouds/milk_cartoon_all_small_clorox.pcd");
  const std::string out = testing::TempDir("mapping_cli_pcd") + "/floor.yaml";
  const auto r = Cli("floor " + path + " --out " + out);
  ASSERT_EQ(r.exit_code, 0) << r.out;
  EXPECT_TRUE(Contains(r.out, "camera 0.4")) << r.out;  // SOURCES.txt: about 0.47 m.
}

#ifdef SIGHTLINE_HAVE_ROS
// The same drive written as a ROS bag (wheel odometry on /odom): the mapping pipeline takes its
// translation from the bag's odometry as it does from odometry.txt, and maps as well.
TEST_F(MappingCli, ABagsOdometryTopicGivesTheTranslationAsOdometryTxtDoes) {
  const std::string dir = testing::TempDir("mapping_cli_bag");
  const auto sim =
      Cli("simulate corridor --out " + dir +
          " --frames 100 --seed 3 --sensors rgbd --quiet --format bag"
          " --set sim.rgbd.resolution=320x240 --set sim.rate_hz=5"
          " --set sim.motion.speed_mps=1 --set sim.odometry.heading_drift_deg_per_m=2");
  ASSERT_EQ(sim.exit_code, 0) << sim.out;
  const std::string out_bag = testing::TempDir("mapping_cli_bag_run");
  const std::string out_folder = testing::TempDir("mapping_cli_folder_run");
  const auto bag = Cli("run mapping " + dir + "/corridor.bag --out " + out_bag);
  const auto folder = Cli("run mapping " + *dir_ + " --out " + out_folder);
  ASSERT_EQ(bag.exit_code, 0) << bag.out;
  ASSERT_EQ(folder.exit_code, 0) << folder.out;
  const std::string log = testing::ReadTextFile(out_bag + "/mapping_log.txt");
  EXPECT_TRUE(Contains(log, "pose source: the recording's odometry (100 poses)")) << log;
  const std::string a = testing::ReadTextFile(out_folder + "/metrics.json");
  const std::string b = testing::ReadTextFile(out_bag + "/metrics.json");
  const auto value = [](const std::string& m, const char* key) {
    return testing::JsonNumber(m, "accuracy", key);
  };
  ASSERT_TRUE(value(b, "ate_rmse_m") && value(b, "heading_error_deg_max")) << b;
  // Without the odometry's translation the 20 m drive would stay at the start (ATE of metres).
  EXPECT_LT(*value(b, "ate_rmse_m"), 0.3);
  EXPECT_LT(*value(b, "heading_error_deg_max"), 1.5);
  // The bag carries no people.csv: frames the folder's run skips as blocked by people are
  // mapped from the bag, so the figures are close, not equal.
  EXPECT_NEAR(*value(b, "ate_rmse_m"), *value(a, "ate_rmse_m"), 0.1);
}
// info --json of a bag: the source's keys, the bag's topics and what each pipeline reads; when
// the frames cannot be read, the error beside the topics (exit 1).
TEST(BagInfoCli, JsonListsTheTopicsAndWhatEachPipelineReads) {
  const std::string dir = testing::TempDir("bag_info_json");
  const auto sim = Cli("simulate corridor --out " + dir +
                       " --frames 3 --sensors rgbd,stereo --quiet --format bag"
                       " --set sim.rgbd.resolution=320x240");
  ASSERT_EQ(sim.exit_code, 0) << sim.out;
  const std::string bag = dir + "/corridor.bag";
  const auto info = Cli("info --json " + bag);
  ASSERT_EQ(info.exit_code, 0) << info.out;
  for (const char* part :
       {"\"kind\": \"RGB-D\"", "\"frames\": 3", "\"compression\": \"none\"",
        "\"name\": \"/odom\",\n        \"type\": \"nav_msgs/Odometry\",\n        \"messages\": 3",
        "\"name\": \"/camera/depth/image\",\n        \"type\": \"sensor_msgs/Image\",\n"
        "        \"messages\": 3,\n        \"encoding\": \"32FC1\"",
        "\"stereo-vo\": {\n      \"reads\": \"stereo pairs from /stereo/left/image_raw (left) + "
        "/stereo/right/image_raw (right)\",\n      \"set\": \"io.rosbag.kind=stereo\"",
        "\"mapping\": {\n      \"reads\": \"RGB-D frames from /camera/rgb/image_color (colour) + "
        "/camera/depth/image (depth)\",\n      \"set\": null"}) {
    EXPECT_TRUE(Contains(info.out, part)) << part << "\n" << info.out;
  }
  const auto broken = Cli("info --json " + bag + " --set io.rosbag.image_topic=/nope");
  EXPECT_EQ(broken.exit_code, 1) << broken.out;
  EXPECT_TRUE(Contains(broken.out, "\"error\": \"invalid argument: " + bag +
                                       ": io.rosbag.image_topic '/nope' is not a topic"))
      << broken.out;
  EXPECT_TRUE(Contains(broken.out, "\"name\": \"/stereo/right/image_raw\"")) << broken.out;
}
#endif  // SIGHTLINE_HAVE_ROS

}  // namespace
}  // namespace sightline
