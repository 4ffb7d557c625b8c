// The mobility map from the command line as a user runs it: office1.pcd (real) and simulated
// terrain; the files, segments.csv and metrics.json.
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

TEST(MobilityCli, Office1WritesScoredCloudSegmentsAndTiming) {
  SIGHTLINE_REQUIRE_DATA(path, "pcl_clouds/office1.pcd");
  const std::string out = testing::TempDir("mobility_office1");
  const auto r = Cli("run mobility " + path + " --out " + out);
  ASSERT_EQ(r.exit_code, 0) << r.out;
  for (const char* file : {"000000_cloud.pcd", "000000_projection.png", "000000_topview.png",
                           "segments.csv", "metrics.json", "mobility_log.txt"}) {
    EXPECT_TRUE(std::filesystem::exists(out + "/" + file)) << file;
  }
  const std::string csv = testing::ReadTextFile(out + "/segments.csv");
  EXPECT_EQ(csv.rfind("frame,segment,is_ground,points,slope_deg,roughness,area_m2,height_m,"
                      "score_rule,score_gpr\n",
                      0),
            0u);
  EXPECT_NE(csv.find("\n0,0,1,"), std::string::npos) << "the ground is row 0";
  const std::string metrics = testing::ReadTextFile(out + "/metrics.json");
  const auto height = testing::JsonNumber(metrics, "accuracy", "ground_height_m");
  ASSERT_TRUE(height.has_value());
  EXPECT_NEAR(*height, 1.32, 0.05);
  for (const char* stage : {"downsample", "range_cut", "denoise", "normals", "rgbn", "ground",
                            "segmentation", "surface", "mobility", "maps"}) {
    EXPECT_TRUE(testing::JsonNumber(metrics, stage, "median").has_value()) << stage;
    EXPECT_TRUE(testing::JsonNumber(metrics, "counts", std::string("points_") + stage).has_value())
        << stage;
  }
}

TEST(MobilityCli, TerrainReportsSlopeAndRoughnessAccuracy) {
  const std::string dir = testing::TempDir("mobility_terrain") + "/terrain";
  ASSERT_EQ(Cli("simulate terrain --out " + dir + " --frames 3 --quiet").exit_code, 0);
  const std::string out = dir + "_run";
  const auto r =
      Cli("run mobility " + dir + " --out " + out + " --set mobility.run.cloud_format=ply");
  ASSERT_EQ(r.exit_code, 0) << r.out;
  EXPECT_TRUE(std::filesystem::exists(out + "/000002_cloud.ply"));
  const std::string metrics = testing::ReadTextFile(out + "/metrics.json");
  const auto slope = testing::JsonNumber(metrics, "accuracy", "slope_error_deg_max");
  const auto rough = testing::JsonNumber(metrics, "accuracy", "flat_roughness");
  const auto height = testing::JsonNumber(metrics, "accuracy", "ground_height_m");
  ASSERT_TRUE(slope && rough && height) << metrics;
  EXPECT_LT(*slope, 1.0);
  EXPECT_NEAR(*rough, 1.0, 0.02);
  EXPECT_NEAR(*height, 1.0, 0.02);  // The simulated camera is 1.0 m above the floor.
}

// No frame of the recording shows the floor: the run writes its files but achieved nothing, so
// it exits 3 saying so, and metrics.json states the failure.
TEST(MobilityCli, OniRecordingWithoutVisibleFloorSaysSoPerFrame) {
  SIGHTLINE_REQUIRE_DATA(path, "oni_livingroom/test.oni");
  const std::string out = testing::TempDir("mobility_oni");
  const auto r =
      Cli("run mobility " + path + " --out " + out + " --set mobility.run.cloud_format=none");
  ASSERT_EQ(r.exit_code, 3) << r.out;
  EXPECT_NE(r.out.find("achieved nothing: no ground found in any of the 12 frame(s)"),
            std::string::npos)
      << r.out;
  const std::string metrics = testing::ReadTextFile(out + "/metrics.json");
  EXPECT_NE(metrics.find("\"failure\""), std::string::npos) << metrics;
  EXPECT_EQ(testing::JsonNumber(metrics, "counts", "frames_without_map").value_or(-1), 12);
  EXPECT_NE(testing::ReadTextFile(out + "/mobility_log.txt").find("no ground plane"),
            std::string::npos);
}

TEST(MobilityCli, BadInputSaysWhy) {
  const auto missing =
      Cli("run mobility /nonexistent/cloud.pcd --out " + testing::TempDir("mobility_bad"));
  EXPECT_NE(missing.exit_code, 0);
  const auto bad_option = Cli("run mobility /nonexistent --out " +
                              testing::TempDir("mobility_bad2") + " --set mobility.grid_stride=0");
  EXPECT_NE(bad_option.exit_code, 0);
}

}  // namespace
}  // namespace sightline
