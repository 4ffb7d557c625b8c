// `sightline-cli run` on inputs a pipeline can read but achieves nothing with: every stereo
// frame gated, a monocular map that never initialises, no ground, no wall line. Such a run must
// not exit 0 as if it had results: it exits 3, says why on its first stderr line, and still
// writes metrics.json stating the "failure". Each input is written by the test.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "tests/app/process.h"
#include "tests/support/test_data.h"

namespace sightline {
namespace {

const std::string kCli = std::string(SIGHTLINE_BIN_DIR) + "/sightline-cli";

void WriteFile(const std::string& path, const std::string& text) {
  std::filesystem::create_directories(std::filesystem::path(path).parent_path());
  std::ofstream(path) << text;
}

void WriteImage(const std::string& path, const cv::Mat& image) {
  std::filesystem::create_directories(std::filesystem::path(path).parent_path());
  ASSERT_TRUE(cv::imwrite(path, image));
}

std::string CameraYaml(int width, int height, bool depth) {
  return "width: " + std::to_string(width) + "\nheight: " + std::to_string(height) +
         "\nfx: 100\nfy: 100\ncx: " + std::to_string(width / 2) +
         "\ncy: " + std::to_string(height / 2) + "\n" + (depth ? "depth_scale: 5000\n" : "");
}

// What a run that achieved nothing printed and wrote.
struct NothingRun {
  int exit_code = -1;
  std::string first_error_line;
  std::string metrics;
  std::string all_errors;
};

NothingRun RunCli(const std::string& pipeline, const std::string& data, const std::string& extra) {
  const std::string out = testing::TempDir("nothing_out");
  const std::string errors = out + "/stderr.txt";
  NothingRun run;
  // A subshell keeps stderr apart: RunProcess merges what is left of it into stdout.
  run.exit_code = testing::RunProcess("(" + kCli + " run " + pipeline + " " + data + " --out " +
                                      out + " --quiet " + extra + " 2>" + errors + ")")
                      .exit_code;
  run.all_errors = testing::ReadTextFile(errors);
  run.first_error_line = run.all_errors.substr(0, run.all_errors.find('\n'));
  run.metrics = testing::ReadTextFile(out + "/metrics.json");
  return run;
}

// Checks the contract of a run that achieved nothing: exit 3, the reason first, metrics.json.
void ExpectNothingAchieved(const NothingRun& run, const std::string& pipeline,
                           const std::string& reason) {
  EXPECT_EQ(run.exit_code, 3) << run.all_errors;
  EXPECT_EQ(run.first_error_line.rfind("sightline-cli: run " + pipeline + " achieved nothing: ", 0),
            0u)
      << run.all_errors;
  EXPECT_NE(run.first_error_line.find(reason), std::string::npos) << run.all_errors;
  EXPECT_NE(run.metrics.find("\"failure\""), std::string::npos) << run.metrics;
  EXPECT_NE(run.metrics.find(reason), std::string::npos) << run.metrics;
}

TEST(NothingAchievedCli, StereoVoOnTexturelessPairsTracksNoFrame) {
  const std::string dir = testing::TempDir("nothing_stereo");
  for (int i = 0; i < 4; ++i) {
    const std::string name = "00000" + std::to_string(i) + ".png";
    WriteImage(dir + "/image_l/" + name, cv::Mat(120, 160, CV_8UC1, cv::Scalar(90)));
    WriteImage(dir + "/image_r/" + name, cv::Mat(120, 160, CV_8UC1, cv::Scalar(90)));
  }
  WriteFile(dir + "/calib.txt",
            "P0: 100 0 80 0 0 100 60 0 0 0 1 0\nP1: 100 0 80 -10 0 100 60 0 0 0 1 0\n");
  ExpectNothingAchieved(RunCli("stereo-vo", dir, ""), "stereo-vo", "no frame tracked");
}

TEST(NothingAchievedCli, MonoSlamOnIdenticalFramesNeverInitialises) {
  const std::string dir = testing::TempDir("nothing_mono");
  cv::Mat texture(240, 320, CV_8UC1);
  cv::randu(texture, 0, 255);
  cv::GaussianBlur(texture, texture, cv::Size(5, 5), 1.5);
  for (int i = 0; i < 6; ++i) WriteImage(dir + "/00000" + std::to_string(i) + ".png", texture);
  WriteFile(dir + "/camera.yaml", CameraYaml(320, 240, false));
  ExpectNothingAchieved(RunCli("mono-slam", dir, ""), "mono-slam", "never initialised");
}

// A TUM RGB-D folder of three frames whose depth images hold no reading at all.
std::string DepthlessRgbd(const std::string& name) {
  const std::string dir = testing::TempDir(name);
  std::string associations;
  for (int i = 0; i < 3; ++i) {
    const std::string t = std::to_string(1 + i), file = std::to_string(i) + ".png";
    WriteImage(dir + "/rgb/" + file, cv::Mat(48, 64, CV_8UC3, cv::Scalar(80, 90, 100)));
    WriteImage(dir + "/depth/" + file, cv::Mat(48, 64, CV_16UC1, cv::Scalar(0)));
    associations += t + " rgb/" + file + " " + t + " depth/" + file + "\n";
  }
  WriteFile(dir + "/associations.txt", associations);
  WriteFile(dir + "/camera.yaml", CameraYaml(64, 48, true));
  return dir;
}

TEST(NothingAchievedCli, MobilityWithoutDepthFindsNoGround) {
  ExpectNothingAchieved(RunCli("mobility", DepthlessRgbd("nothing_mobility"), ""), "mobility",
                        "no ground found in any of the 3 frame(s)");
}

TEST(NothingAchievedCli, MappingWithoutDepthFindsNoWallLine) {
  const std::string dir = DepthlessRgbd("nothing_mapping");
  WriteFile(dir + "/floor.yaml", "a: 0\nb: -1\nc: 0\nd: 0.8\n");
  ExpectNothingAchieved(
      RunCli("mapping", dir, "--set mapping.run.floor_file=" + dir + "/floor.yaml"), "mapping",
      "no wall line found in any of the 3 mapped frame(s)");
}

TEST(NothingAchievedCli, MappingWithoutFloorMapsNothing) {
  // No floor file and no depth reading: the floor cannot be calibrated from any frame.
  const NothingRun run = RunCli("mapping", DepthlessRgbd("nothing_mapping_floor"), "");
  ExpectNothingAchieved(run, "mapping", "no floor found in any of the 3 frame(s)");
  EXPECT_NE(run.first_error_line.find("floor fit:"), std::string::npos) << run.all_errors;
}

}  // namespace
}  // namespace sightline
