// sightline-cli simulate as a user runs it: writes recordings that `info` reads, fails with one
// line naming the bad option.
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
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

TEST(SimulateCli, HelpListsTheScenes) {
  const auto r = Cli("simulate --help");
  EXPECT_EQ(r.exit_code, 0) << r.out;
  EXPECT_TRUE(Contains(r.out, "usage: sightline-cli simulate SCENE")) << r.out;
  EXPECT_TRUE(Contains(r.out, "corridor") && Contains(r.out, "terrain") &&
              Contains(r.out, "panel"));
  EXPECT_TRUE(Contains(Cli("--help").out, "simulate SCENE"));
}

TEST(SimulateCli, WritesARecordingThatInfoReads) {
  const std::string out = testing::TempDir("sim_cli") + "/corridor";
  const auto r = Cli("simulate corridor --out " + out +
                     " --frames 3 --seed 4 --noise kinect --sensors rgbd,stereo"
                     " --set sim.rgbd.resolution=320x240");
  ASSERT_EQ(r.exit_code, 0) << r.out;
  EXPECT_TRUE(Contains(r.out, "3 frames of rgbd, stereo")) << r.out;
  EXPECT_TRUE(Contains(r.out, "frames/s")) << r.out;
  EXPECT_TRUE(Contains(r.out, "walls.csv")) << r.out;
  const auto info = Cli("info " + out);
  ASSERT_EQ(info.exit_code, 0) << info.out;
  EXPECT_TRUE(Contains(info.out, "TUM RGB-D")) << info.out;
  EXPECT_TRUE(Contains(info.out, "320x240")) << info.out;
  const auto stereo = Cli("info " + out + "/stereo");
  ASSERT_EQ(stereo.exit_code, 0) << stereo.out;
  EXPECT_TRUE(Contains(stereo.out, "KITTI")) << stereo.out;
}

TEST(SimulateCli, PanelRecordingIsAnImageFolder) {
  const std::string out = testing::TempDir("sim_cli_panel") + "/panel";
  const auto r = Cli("simulate panel --out " + out + " --frames 2 --quiet");
  ASSERT_EQ(r.exit_code, 0) << r.out;
  EXPECT_TRUE(r.out.empty()) << r.out;
  const auto info = Cli("info " + out);
  ASSERT_EQ(info.exit_code, 0) << info.out;
  EXPECT_TRUE(Contains(info.out, "image folder")) << info.out;
  std::ifstream buttons(out + "/buttons.csv");
  EXPECT_TRUE(buttons.good());
}

TEST(SimulateCli, BadOptionsFailWithOneLineNamingTheKey) {
  for (const auto& [args, key] : std::vector<std::pair<std::string, std::string>>{
           {"corridor --out /tmp/x --frames 0", "sim.frames"},
           {"corridor --out /tmp/x --set sim.stereo.baseline_m=-0.1", "sim.stereo.baseline_m"},
           {"corridor --out /tmp/x --noise loud", "sim.noise.profile"},
           {"garden --out /tmp/x", "unknown scene 'garden'"},
           {"corridor --out /tmp/x --set sim.mono.width=100000", "sim.mono.width"}}) {
    const auto r = Cli("simulate " + args);
    EXPECT_NE(r.exit_code, 0) << args;
    EXPECT_EQ(std::count(r.out.begin(), r.out.end(), '\n'), 1) << r.out;
    EXPECT_TRUE(Contains(r.out, key)) << args << ": " << r.out;
  }
}

TEST(SimulateCli, OptionsListsEverySimKey) {
  const auto r = Cli("simulate terrain --options");
  ASSERT_EQ(r.exit_code, 0) << r.out;
  EXPECT_TRUE(Contains(r.out, "sim.terrain.ramp_slope_deg")) << r.out;
  EXPECT_TRUE(Contains(r.out, "sim.noise.profile"));
}

}  // namespace
}  // namespace sightline
