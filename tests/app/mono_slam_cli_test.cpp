// `sightline-cli run mono-slam` as a user runs it.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "tests/app/process.h"
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
