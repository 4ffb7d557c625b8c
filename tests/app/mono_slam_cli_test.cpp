// `sightline-cli run mono-slam` as a user runs it.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "tests/app/process.h"
#include "tests/support/button_csv.h"
#include "tests/support/test_data.h"

namespace sightline {
namespace {

const std::string kCli = std::string(SIGHTLINE_BIN_DIR) + "/sightline-cli";

TEST(MonoSlamCli, RunWritesTrajectoryMapKeyframesScaleAndMetrics) {
  SIGHTLINE_REQUIRE_DATA(kitti, "kitti_clip1");
  const std::string out = testing::TempDir("mono_slam_cli_run");
  const testing::ProcessResult r =
      testing::RunProcess(kCli + " run mono-slam " + kitti + " --out " + out +
                          " --set mono.run.metric_source=ground_truth");
  ASSERT_EQ(r.exit_code, 0) << r.out;
  EXPECT_NE(r.out.find("accuracy.ate_rmse_pct_of_path"), std::string::npos) << r.out;
  const std::string metrics = testing::ReadTextFile(out + "/metrics.json");
  for (const char* key : {"\"tracking\"", "\"mapping\"", "\"bundle_adjustment\"", "\"lost_frames\"",
                          "\"relocalisations\"", "\"ate_rmse_m\"", "\"ate_rmse_pct_of_path\"",
                          "\"ate_metric_rmse_m\"", "\"scale_error_pct_ml\"",
                          "\"scale_error_pct_single\"", "\"mono.init.baseline\""}) {
    EXPECT_NE(metrics.find(key), std::string::npos) << key;
  }
  const std::string ply = testing::ReadTextFile(out + "/map.ply");
  EXPECT_EQ(ply.rfind("ply\n", 0), 0u);
  EXPECT_NE(ply.find("element vertex"), std::string::npos);
  const std::string scale = testing::ReadTextFile(out + "/scale.csv");
  EXPECT_EQ(scale.rfind("sample,single_ratio,ml_estimate", 0), 0u);
  EXPECT_GT(std::count(scale.begin(), scale.end(), '\n'), 5);
  const std::string keyframes = testing::ReadTextFile(out + "/keyframes.txt");
  EXPECT_GT(std::count(keyframes.begin(), keyframes.end(), '\n'), 5);
  const std::string trajectory = testing::ReadTextFile(out + "/trajectory.txt");
  EXPECT_GT(std::count(trajectory.begin(), trajectory.end(), '\n'), 40);
}

// frames.csv's rows and how many of them were tracked.
void CountFrames(const std::string& csv_path, int* rows, int* tracked) {
  const testing::CsvColumns csv = testing::ReadCsvColumns(csv_path);
  *rows = static_cast<int>(csv.rows);
  *tracked = 0;
  for (size_t i = 0; i < csv.rows; ++i) *tracked += csv.At("tracked", i) == 1;
}

// An RGB-D recording's colour images are a monocular sequence: a simulated orbit recorded as
// RGB-D is tracked as its mono images are (0.09 % of the path), and the real office
// recording's 9 colour frames are read and initialised on.
TEST(MonoSlamCli, RunsOnTheColourImagesOfAnRgbdRecording) {
  const std::string sim = testing::TempDir("mono_slam_cli_rgbd_orbit");
  ASSERT_EQ(testing::RunProcess(kCli + " simulate terrain --out " + sim +
                                " --set sim.motion.kind=orbit --set sim.sensors=rgbd --set "
                                "sim.frames=150 --quiet")
                .exit_code,
            0);
  const std::string out = testing::TempDir("mono_slam_cli_rgbd_orbit_run");
  testing::ProcessResult r =
      testing::RunProcess(kCli + " run mono-slam " + sim + "/rgbd --out " + out);
  ASSERT_EQ(r.exit_code, 0) << r.out;
  int rows = 0, tracked = 0;
  CountFrames(out + "/frames.csv", &rows, &tracked);
  EXPECT_EQ(rows, 150);
  EXPECT_GE(tracked, 0.9 * rows);
  EXPECT_LT(testing::JsonNumber(testing::ReadTextFile(out + "/metrics.json"), "accuracy",
                                "ate_rmse_pct_of_path")
                .value_or(1e9),
            0.5);

  SIGHTLINE_REQUIRE_DATA(tum, "tum_fr1_desk");
  const std::string real = testing::TempDir("mono_slam_cli_tum_colour");
  r = testing::RunProcess(kCli + " run mono-slam " + tum + " --out " + real);
  ASSERT_EQ(r.exit_code, 0) << r.out;
  CountFrames(real + "/frames.csv", &rows, &tracked);
  EXPECT_EQ(rows, 9);
  EXPECT_GE(tracked, 1);  // The clip is 0.27 s long: initialised on its 8th frame.
}

TEST(MonoSlamCli, FailuresAreOneLine) {
  testing::ProcessResult r = testing::RunProcess(kCli + " run mono-slam /nonexistent --out /tmp/x");
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.out.find("/nonexistent"), std::string::npos) << r.out;
  r = testing::RunProcess(
      kCli + " run mono-slam /nonexistent --out /tmp/x --set mono.run.metric_source=ruler");
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.out.find("metric_source"), std::string::npos) << r.out;
}

}  // namespace
}  // namespace sightline
