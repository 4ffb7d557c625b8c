// `sightline --connect-ros URI --screenshot FILE` against a real sightline-node (its own roscore,
// a simulator-written bag): the window shows the node's map in the ROS node dock, checked on the
// screenshot's pixels inside the map view; a bad URI and an absent master are named. Runs the
// real executables under X (Xvfb in CI).
#include <gtest/gtest.h>

#include <filesystem>
#include <opencv2/imgcodecs.hpp>
#include <regex>

#include "tests/app/process.h"
#include "tests/ros/roscore_fixture.h"
#include "tests/support/test_data.h"

namespace sightline {
namespace {

using testing::ChildProcess;
using testing::RoscoreFixture;

std::string Bin(const std::string& name) { return std::string(SIGHTLINE_BIN_DIR) + "/" + name; }

// The GUI with its own settings (no saved layout or language from elsewhere).
std::string Gui(const std::string& args) {
  const std::string home = testing::TempDir("ros_gui_home");
  return "env HOME=" + home + " XDG_CONFIG_HOME=" + home + "/config " + Bin("sightline") + " " +
         args + " 2>&1";
}

TEST(RosGui, ScreenshotShowsTheMapOfARunningNode) {
  const std::string sim = testing::TempDir("ros_gui_bag");
  const auto made = testing::RunProcess(
      Bin("sightline-cli") + " simulate corridor --format bag --out " + sim +
      " --frames 30 --seed 3 --sensors rgbd --quiet --set sim.rgbd.resolution=320x240"
      " --set sim.rate_hz=5 --set sim.motion.speed_mps=1");
  ASSERT_EQ(made.exit_code, 0) << made.out;
  RoscoreFixture master;
  const std::string error = master.Start();
  ASSERT_TRUE(error.empty()) << error;
  const std::string out = testing::TempDir("ros_gui_node");
  const std::string log = out + "/node.log";
  ChildProcess node;
  ASSERT_TRUE(node.Start(master.Env() + Bin("sightline-node") + " --pipeline mapping --source " +
                             sim + "/corridor.bag --out " + out + "/run --rate max --linger -1",
                         log));
  const std::string shot = out + "/window.png";
  const auto gui =
      testing::RunProcess(master.Env() + Gui("--connect-ros " + master.uri() + " --screenshot " +
                                             shot + " --timeout 120"));
  ASSERT_EQ(gui.exit_code, 0) << gui.out << testing::ReadTextFile(log);
  std::smatch m;
  ASSERT_TRUE(std::regex_search(gui.out, m,
                                std::regex(R"(map (\d+)x(\d+) from the ROS node; map view at )"
                                           R"((\d+),(\d+) (\d+)x(\d+))")))
      << gui.out;
  const cv::Rect view(std::stoi(m[3]), std::stoi(m[4]), std::stoi(m[5]), std::stoi(m[6]));
  const cv::Mat image = cv::imread(shot, cv::IMREAD_GRAYSCALE);
  ASSERT_FALSE(image.empty()) << shot;
  ASSERT_TRUE((view & cv::Rect(0, 0, image.cols, image.rows)) == view) << gui.out;
  ASSERT_GT(view.area(), 100 * 100);
  // Free cells are white (254), occupied ones black, unknown grey (205): the map fills a good
  // part of the view with free space bounded by walls.
  const cv::Mat map_view = image(view);
  int free_px = 0, occupied_px = 0;
  for (int r = 0; r < map_view.rows; ++r) {
    for (int c = 0; c < map_view.cols; ++c) {
      const int v = map_view.at<uint8_t>(r, c);
      free_px += v >= 250;
      occupied_px += v <= 10;
    }
  }
  EXPECT_GT(free_px, view.area() / 50) << "free " << free_px << " of " << view.area();
  EXPECT_GT(occupied_px, 50) << "occupied " << occupied_px;
  // The status bar said so too (the window's text is in the picture; the run's output names
  // the URI in its line).
  EXPECT_NE(gui.out.find("from the ROS node"), std::string::npos);
}

TEST(RosGui, BadUriIsNamed) {
  const auto gui = testing::RunProcess(
      Gui("--connect-ros robot:11311 --screenshot " + testing::TempDir("ros_gui_bad") + "/x.png"));
  EXPECT_EQ(gui.exit_code, 2) << gui.out;
  EXPECT_NE(gui.out.find("'robot:11311'"), std::string::npos) << gui.out;
  EXPECT_NE(gui.out.find("http://"), std::string::npos) << gui.out;
  const auto ns =
      testing::RunProcess(Gui("--connect-ros http://127.0.0.1:11311 --ros-namespace "
                              "'/a b' --screenshot " +
                              testing::TempDir("ros_gui_bad_ns") + "/x.png"));
  EXPECT_EQ(ns.exit_code, 2) << ns.out;
  EXPECT_NE(ns.out.find("'/a b'"), std::string::npos) << ns.out;
}

TEST(RosGui, AbsentMasterIsReportedAsReconnecting) {
  const int port = testing::FreeLoopbackPort();
  const std::string uri = "http://127.0.0.1:" + std::to_string(port);
  const auto gui = testing::RunProcess("env ROS_IP=127.0.0.1 " +
                                       Gui("--connect-ros " + uri + " --timeout 5 --screenshot " +
                                           testing::TempDir("ros_gui_absent") + "/x.png"));
  EXPECT_EQ(gui.exit_code, 1) << gui.out;
  EXPECT_NE(gui.out.find("ROS: disconnected — reconnecting to " + uri), std::string::npos)
      << gui.out;
  EXPECT_FALSE(std::filesystem::exists(testing::TempDir("ros_gui_absent") + "/x.png"));
}

}  // namespace
}  // namespace sightline
