// sightline-cli as a user runs it: exit codes, one-line reasons, outputs.
#include <gtest/gtest.h>

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

std::string ReadAll(const std::string& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

TEST(Cli, HelpOnEveryCommand) {
  for (const std::string command : {"--help", "info --help", "run --help", "options --help"}) {
    const auto r = Cli(command);
    EXPECT_EQ(r.exit_code, 0) << command << "\n" << r.out;
    EXPECT_NE(r.out.find("usage: sightline-cli"), std::string::npos) << command;
  }
}

TEST(Cli, VersionPrintsTheVersionAndTheGitCommit) {
  const auto r = Cli("--version");
  EXPECT_EQ(r.exit_code, 0) << r.out;
  EXPECT_EQ(r.out.rfind("sightline-cli 0.", 0), 0u) << r.out;
  EXPECT_NE(r.out.find("(commit "), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("(commit unknown"), std::string::npos) << "built outside git? " << r.out;
}

TEST(Cli, RunPipelineHelpListsThatPipelinesOptions) {
  const auto r = Cli("run stereo-vo --help");
  EXPECT_EQ(r.exit_code, 0) << r.out;
  EXPECT_NE(r.out.find("usage: sightline-cli run"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("Options of stereo-vo"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("stereo.subsample"), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("mapping.run.floor_file"), std::string::npos) << "another pipeline's";
  // And the files it writes.
  EXPECT_NE(r.out.find("Files stereo-vo writes"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("trajectory.txt"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("metrics.json"), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("map.pgm"), std::string::npos) << "another pipeline's file";
}

// The desktop application answers --help and --version on a machine without a display (a
// server, a CI job, ssh without X forwarding) instead of aborting in Qt's platform plugin.
TEST(SightlineExecutable, HelpAndVersionWorkWithoutADisplay) {
  const std::string gui = std::string(SIGHTLINE_BIN_DIR) + "/sightline";
  const std::string no_display = "env -u DISPLAY -u WAYLAND_DISPLAY -u QT_QPA_PLATFORM ";
  const auto help = testing::RunProcess(no_display + gui + " --help");
  EXPECT_EQ(help.exit_code, 0) << help.out;
  EXPECT_NE(help.out.find("--open"), std::string::npos) << help.out;
  EXPECT_NE(help.out.find("--pipeline"), std::string::npos) << help.out;
  const auto version = testing::RunProcess(no_display + gui + " --version");
  EXPECT_EQ(version.exit_code, 0) << version.out;
  EXPECT_NE(version.out.find("(commit "), std::string::npos) << version.out;
}

TEST(Cli, UnknownCommandFailsWithOneLine) {
  const auto r = Cli("frobnicate");
  EXPECT_NE(r.exit_code, 0);
  EXPECT_EQ(std::count(r.out.begin(), r.out.end(), '\n'), 1) << r.out;
  EXPECT_NE(r.out.find("unknown command 'frobnicate'"), std::string::npos);
}

TEST(Cli, InfoOnKittiPrintsStereoPairsAndGroundTruth) {
  SIGHTLINE_REQUIRE_DATA(dir, "kitti_clip1");
  const auto r = Cli("info " + dir);
  ASSERT_EQ(r.exit_code, 0) << r.out;
  EXPECT_NE(r.out.find("KITTI"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("51 stereo pairs"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("ground truth: yes"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("1226x370"), std::string::npos) << r.out;
}

TEST(Cli, InfoJsonIsMachineReadable) {
  SIGHTLINE_REQUIRE_DATA(dir, "tum_fr1_desk");
  const auto r = Cli("info --json " + dir);
  ASSERT_EQ(r.exit_code, 0) << r.out;
  EXPECT_EQ(r.out.front(), '{');
  EXPECT_NE(r.out.find("\"frames\": 9"), std::string::npos) << r.out;
}

TEST(Cli, InfoOnMissingPathFailsWithOneLineNamingIt) {
  const auto r = Cli("info /nonexistent/dataset");
  EXPECT_NE(r.exit_code, 0);
  EXPECT_EQ(std::count(r.out.begin(), r.out.end(), '\n'), 1) << r.out;
  EXPECT_NE(r.out.find("/nonexistent/dataset"), std::string::npos) << r.out;
}

TEST(Cli, RunInspectWritesMetricsJson) {
  SIGHTLINE_REQUIRE_DATA(dir, "euroc_v1_01_static");
  const std::string out = testing::TempDir("cli") + "/run";
  const auto r = Cli("run inspect " + dir + " --out " + out + " --set inspect.max_frames=7");
  ASSERT_EQ(r.exit_code, 0) << r.out;
  const std::string json = ReadAll(out + "/metrics.json");
  EXPECT_NE(json.find("\"frames\": 7"), std::string::npos) << json;
  EXPECT_NE(json.find("\"timing_ms\""), std::string::npos);
  EXPECT_NE(json.find("\"inspect.max_frames\": 7"), std::string::npos);
  // The run names every file it wrote, and each one exists.
  for (const char* file : {"frames.csv", "metrics.json"}) {
    const std::string path = out + "/" + file;
    EXPECT_NE(r.out.find("wrote " + path + "\n"), std::string::npos) << file << "\n" << r.out;
    EXPECT_FALSE(ReadAll(path).empty()) << path;
  }
}

TEST(Cli, RunWithOutOfRangeOptionFailsNamingTheKey) {
  const auto r = Cli("run inspect /tmp --out /tmp/x --set inspect.max_depth_m=1000");
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.out.find("inspect.max_depth_m"), std::string::npos) << r.out;
}

TEST(Cli, RunWithoutOutFails) {
  const auto r = Cli("run inspect /tmp");
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.out.find("--out"), std::string::npos) << r.out;
}

TEST(Cli, OptionsListsDescribeTable) {
  const auto r = Cli("options inspect");
  ASSERT_EQ(r.exit_code, 0) << r.out;
  EXPECT_NE(r.out.find("inspect.max_depth_m"), std::string::npos);
  EXPECT_NE(r.out.find("[0.1, 100]"), std::string::npos) << r.out;
}

}  // namespace
}  // namespace sightline

namespace sightline {
namespace {

TEST(Cli, InfoPlaysAnOniRecordingThroughOpenNi2) {
  SIGHTLINE_REQUIRE_DATA(oni, "oni_livingroom/test.oni");
  const auto r = Cli("info " + oni);
  ASSERT_EQ(r.exit_code, 0) << r.out;
  EXPECT_NE(r.out.find("12 RGB-D frames"), std::string::npos) << r.out;
}

// Real Kinect frames with no one in them: tum_fr1_desk's desk with its monitors (top 1.17 m,
// 0.9 m away) stands on the floor with a person's height. Depth alone took it for a person in 3
// of its 9 frames; the height-to-length rule and HOG on the registered colour each reject it.
TEST(Cli, MappingFindsNoPersonInARealOfficeWithoutPeople) {
  SIGHTLINE_REQUIRE_DATA(desk, "tum_fr1_desk");
  const std::string out = testing::TempDir("cli") + "/people";
  struct Case {
    std::string set, source;
    int boxes;
  };
  for (const Case& c :
       std::vector<Case>{{"", "depth+hog", 0},
                         {" --set mapping.people.depth_hog_check=false", "depth", 0},
                         {" --set mapping.people.depth_min_height_to_length=0", "depth+hog", 0},
                         {" --set mapping.people.depth_min_height_to_length=0"
                          " --set mapping.people.depth_hog_check=false",
                          "depth", 3}}) {
    const auto r = Cli("run mapping " + desk + " --out " + out + c.set);
    ASSERT_EQ(r.exit_code, 0) << r.out;
    const std::string log = ReadAll(out + "/mapping_log.txt");
    EXPECT_NE(log.find("person boxes used: " + c.source + " in 9 frame(s), " +
                       std::to_string(c.boxes) + " box(es)"),
              std::string::npos)
        << c.set << "\n"
        << log;
  }
}

TEST(Cli, InfoOnAnAbsentSensorFailsWithOneLine) {
  const auto r = Cli("info v4l2:///dev/video99");
  EXPECT_NE(r.exit_code, 0);
  EXPECT_EQ(std::count(r.out.begin(), r.out.end(), '\n'), 1) << r.out;
  EXPECT_NE(r.out.find("/dev/video99"), std::string::npos) << r.out;
}

}  // namespace
}  // namespace sightline
