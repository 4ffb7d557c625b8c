// `sightline-cli calibrate` as a user runs it: the reference figures of calib_chessboard, the
// files it writes loading back through the readers, hand-eye on the simulator's arm, bad input.
#include <gtest/gtest.h>

#include <cstdlib>
#include <regex>

#include "core/calib/calibration_file.h"
#include "core/io/camera_yaml.h"
#include "core/io/hand_eye_file.h"
#include "core/io/stereo_calibration_file.h"
#include "tests/app/process.h"
#include "tests/core/calib/hand_eye_scene.h"
#include "tests/support/test_data.h"

namespace sightline {
namespace {

const std::string kCli = std::string(SIGHTLINE_BIN_DIR) + "/sightline-cli";

testing::ProcessResult Cli(const std::string& args) {
  return testing::RunProcess(kCli + " " + args);
}

// The number after `label` in `text` (e.g. "RMS left " -> 0.4079), or NaN.
double NumberAfter(const std::string& text, const std::string& label) {
  const size_t at = text.find(label);
  if (at == std::string::npos) return std::nan("");
  return std::strtod(text.c_str() + at + label.size(), nullptr);
}

TEST(CalibrateCli, MonoReproducesTheReferenceAndWritesACameraYaml) {
  SIGHTLINE_REQUIRE_DATA(dir, "calib_chessboard");
  const std::string out = testing::TempDir("cli_calib_mono") + "/left.yaml";
  auto run = Cli("calibrate mono " + dir +
                 " --images 'left*.jpg' --board 9x6 --square 0.025 --out " + out);
  ASSERT_EQ(run.exit_code, 0) << run.out;
  EXPECT_NEAR(NumberAfter(run.out, "\nRMS "), 0.408, 0.01) << run.out;
  EXPECT_NE(run.out.find("board found in 13 of 13 images"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("left02.jpg"), std::string::npos);
  EXPECT_NE(run.out.find("coverage: 13 views; cells"), std::string::npos);
  auto camera = ReadCameraYaml(out);
  ASSERT_TRUE(camera.ok()) << camera.status().ToString();
  EXPECT_NEAR(camera->camera.fx, 536.06, 536.06 * 0.01);
}

TEST(CalibrateCli, StereoReproducesTheReferenceRmsAndBaseline) {
  SIGHTLINE_REQUIRE_DATA(dir, "calib_chessboard");
  const std::string out = testing::TempDir("cli_calib_stereo") + "/rig.yaml";
  auto run = Cli("calibrate stereo " + dir + " --out " + out);
  ASSERT_EQ(run.exit_code, 0) << run.out;
  EXPECT_NEAR(NumberAfter(run.out, "RMS left "), 0.408, 0.01) << run.out;
  EXPECT_NEAR(NumberAfter(run.out, "px, right "), 0.458, 0.01) << run.out;
  EXPECT_NEAR(NumberAfter(run.out, "px, stereo "), 0.447, 0.01) << run.out;
  EXPECT_NEAR(NumberAfter(run.out, "baseline "), 83.6, 0.836) << run.out;
  auto rig = ReadStereoCalibration(out);
  ASSERT_TRUE(rig.ok()) << rig.status().ToString();
  EXPECT_NEAR(rig->BaselineM(), 0.0836, 0.000836);
  EXPECT_TRUE(ReadCameraYaml(StereoCameraFilePath(out, "right")).ok());
}

TEST(CalibrateCli, HandEyeRecoversTheSimulatedArmsCameraMount) {
  const std::string dir = testing::TempDir("cli_calib_handeye");
  auto scene = testing::MakeHandEyeScene(12, ChessboardOptions{});
  ASSERT_TRUE(scene.ok()) << scene.status().ToString();
  ASSERT_TRUE(testing::WriteHandEyeScene(*scene, dir).ok());
  auto run = Cli("calibrate handeye " + dir + "/arm_poses.txt " + dir +
                 "/views --method park --out " + dir + "/hand_eye.yaml");
  ASSERT_EQ(run.exit_code, 0) << run.out;
  EXPECT_NE(run.out.find("board found in 12 of 12 views, 12 paired"), std::string::npos) << run.out;
  auto file = ReadHandEyeFile(dir + "/hand_eye.yaml");
  ASSERT_TRUE(file.ok()) << file.status().ToString();
  const Eigen::Isometry3d& mount = file->end_effector_from_camera;
  const Eigen::Isometry3d& truth = scene->end_effector_from_camera;
  EXPECT_LT((mount.translation() - truth.translation()).norm(), 0.003);
  EXPECT_LT(RotationAngleDeg(mount.linear().transpose() * truth.linear()), 0.5);
}

TEST(CalibrateCli, BadInputFailsWithOneClearLine) {
  SIGHTLINE_REQUIRE_DATA(dir, "calib_chessboard");
  const std::string out = testing::TempDir("cli_calib_bad") + "/x.yaml";
  auto wrong_board =
      Cli("calibrate mono " + dir + " --images 'left0[1-3].jpg' --board 9x7 --out " + out);
  EXPECT_EQ(wrong_board.exit_code, 1);
  EXPECT_NE(wrong_board.out.find("no 9x7 chessboard found in any of 3 images"), std::string::npos)
      << wrong_board.out;
  auto few = Cli("calibrate mono " + dir + " --images 'left0[1-3].jpg' --out " + out);
  EXPECT_EQ(few.exit_code, 1);
  EXPECT_NE(few.out.find("at least 5 needed"), std::string::npos) << few.out;
  auto board = Cli("calibrate mono " + dir + " --board 9by6 --out " + out);
  EXPECT_EQ(board.exit_code, 1);
  EXPECT_NE(board.out.find("'9by6'"), std::string::npos) << board.out;
  auto mode = Cli("calibrate fisheye " + dir + " --out " + out);
  EXPECT_NE(mode.out.find("unknown mode 'fisheye'"), std::string::npos) << mode.out;
  auto key = Cli("calibrate mono " + dir + " --set calib.mono.nonsense=1 --out " + out);
  EXPECT_EQ(key.exit_code, 1);
  EXPECT_NE(key.out.find("calib.mono.nonsense"), std::string::npos) << key.out;
}

TEST(CalibrateCli, MismatchedLeftAndRightFoldersAreRefused) {
  SIGHTLINE_REQUIRE_DATA(dir, "calib_chessboard");
  auto run = Cli("calibrate stereo " + dir + " " + dir + "/middlebury_aloe --out /tmp/never.yaml");
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_NE(run.out.find("right images; stereo calibration needs them in pairs"), std::string::npos)
      << run.out;
}

TEST(CalibrateCli, FloorIsAnAliasOfTheFloorCommand) {
  auto run = Cli("calibrate floor --help");
  EXPECT_EQ(run.exit_code, 0);
  EXPECT_NE(run.out.find("usage: sightline-cli floor"), std::string::npos) << run.out;
}

}  // namespace
}  // namespace sightline
