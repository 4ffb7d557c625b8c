// Hand-eye calibration on the simulator's arm: the panel scene's camera mount is the truth
// (hand_eye.yaml), chessboard images rendered through its mono camera from arm poses with the
// simulator's pose noise; corners detected, board poses by PnP, then cv::calibrateHandEye.
#include "core/calib/hand_eye.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "core/calib/board_detection.h"
#include "core/calib/calibration_file.h"
#include "core/io/hand_eye_file.h"
#include "core/sim/simulate.h"
#include "core/sim/simulator.h"
#include "hand_eye_scene.h"
#include "tests/support/test_data.h"

namespace sightline {
namespace {

using ::sightline::testing::HandEyeScene;
using ::sightline::testing::MakeHandEyeScene;

double AngleBetweenDeg(const Eigen::Isometry3d& a, const Eigen::Isometry3d& b) {
  return RotationAngleDeg(a.linear().transpose() * b.linear());
}

class HandEyeOnSimulatedArm : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    auto scene = MakeHandEyeScene(15, ChessboardOptions{});
    ASSERT_TRUE(scene.ok()) << scene.status().ToString();
    scene_ = new HandEyeScene(std::move(*scene));
  }
  static void TearDownTestSuite() {
    delete scene_;
    scene_ = nullptr;
  }
  // Detected corners -> PnP board poses.
  static std::vector<Eigen::Isometry3d> DetectedBoardPoses() {
    std::vector<BoardView> views;
    for (size_t i = 0; i < scene_->images.size(); ++i) {
      BoardView view{"view " + std::to_string(i), scene_->images[i].size(), {}, scene_->times_s[i]};
      EXPECT_TRUE(FindChessboard(scene_->images[i], ChessboardOptions{}, &view.corners)) << i;
      views.push_back(view);
    }
    std::vector<double> rms;
    auto poses = BoardPoses(views, scene_->camera, ChessboardOptions{}, &rms);
    EXPECT_TRUE(poses.ok()) << poses.status().ToString();
    for (double e : rms) EXPECT_LT(e, 0.3);  // Pixel noise 2 grey levels: sub-pixel corners.
    return poses.ok() ? *poses : std::vector<Eigen::Isometry3d>{};
  }
  static std::vector<Eigen::Isometry3d> ArmPoses() {
    std::vector<Eigen::Isometry3d> poses;
    for (const TimedPose& p : scene_->base_from_end_effector.poses()) {
      poses.push_back(p.world_from_sensor);
    }
    return poses;
  }
  static HandEyeScene* scene_;
};

HandEyeScene* HandEyeOnSimulatedArm::scene_ = nullptr;

TEST_F(HandEyeOnSimulatedArm, RecoversTheSimulatorsCameraMountFromImages) {
  const std::vector<Eigen::Isometry3d> boards = DetectedBoardPoses();
  ASSERT_EQ(boards.size(), 15u);
  for (const std::string& method : HandEyeMethodNames()) {
    HandEyeOptions options;
    options.method = method;
    auto result = CalibrateHandEye(ArmPoses(), boards, options);
    ASSERT_TRUE(result.ok()) << method << ": " << result.status().ToString();
    const Eigen::Isometry3d& truth = scene_->end_effector_from_camera;
    std::printf(
        "  %-10s rotation error %.4f deg, translation error %.3f mm\n", method.c_str(),
        AngleBetweenDeg(result->end_effector_from_camera, truth),
        1000 * (result->end_effector_from_camera.translation() - truth.translation()).norm());
    EXPECT_LT(AngleBetweenDeg(result->end_effector_from_camera, truth), 0.5) << method;
    EXPECT_LT((result->end_effector_from_camera.translation() - truth.translation()).norm(), 0.003)
        << method;
    EXPECT_LT(result->board_translation_rms_m, 0.003) << method;
    EXPECT_LT(result->board_rotation_rms_deg, 0.5) << method;
    EXPECT_GT(result->max_rotation_deg, 20.0);
    EXPECT_EQ(result->pairs, 15);
  }
}

TEST_F(HandEyeOnSimulatedArm, PairsArmPosesWithViewsByTime) {
  std::vector<BoardView> views;
  for (double t : {0.0, 0.3, 0.7, 5.0}) views.push_back(BoardView{"v", {640, 480}, {}, t});
  std::vector<int> kept;
  const auto poses = ArmPosesForViews(scene_->base_from_end_effector, views, 0.02, &kept);
  ASSERT_EQ(kept, (std::vector<int>{0, 1, 2}));  // No pose near 5 s.
  EXPECT_TRUE(poses[1].isApprox(scene_->base_from_end_effector.poses()[3].world_from_sensor));
}

TEST(HandEye, ReadsTheSimulatorsHandEyeFileAndRejectsItsTranslationOnlyApproach) {
  const std::string dir = ::sightline::testing::TempDir("handeye_sim");
  sim::SimulationOptions options = sim::SimulationOptions::ForScene("panel");
  options.frames = 6;
  options.mono.width = 320;
  options.mono.height = 240;
  options.mono.focal_px = 262.5;
  auto summary = sim::Simulate(options, dir);
  ASSERT_TRUE(summary.ok()) << summary.status().ToString();
  auto mount = ReadHandEyeFile(dir + "/hand_eye.yaml");
  ASSERT_TRUE(mount.ok()) << mount.status().ToString();
  auto simulator = sim::Simulator::Create(options);
  ASSERT_TRUE(simulator.ok());
  EXPECT_TRUE(mount->end_effector_from_camera.isApprox(simulator->motion().body_from_camera, 1e-6));

  // The simulator's approach only translates: the solver must refuse, saying why.
  auto arm = ReadTumTrajectory(dir + "/arm_poses.txt");
  ASSERT_TRUE(arm.ok()) << arm.status().ToString();
  std::vector<Eigen::Isometry3d> base_from_ee, camera_from_board;
  const Eigen::Isometry3d world_from_board =
      simulator->motion().WorldFromCamera(0) * Eigen::Translation3d(0, 0, 0.5);
  for (size_t i = 0; i < arm->size(); ++i) {
    base_from_ee.push_back(arm->poses()[i].world_from_sensor);
    camera_from_board.push_back(simulator->motion().WorldFromCamera(i).inverse() *
                                world_from_board);
  }
  auto result = CalibrateHandEye(base_from_ee, camera_from_board);
  ASSERT_FALSE(result.ok());
  EXPECT_EQ(result.status().code(), StatusCode::kInvalidArgument);
  EXPECT_NE(result.status().message().find("rotate by at most 0.00 deg"), std::string::npos)
      << result.status().message();
}

TEST(HandEye, WritesAFileItReadsBack) {
  HandEyeResult result;
  result.method = "park";
  result.pairs = 9;
  result.end_effector_from_camera = Eigen::Translation3d(0.06, -0.01, -0.03) *
                                    Eigen::AngleAxisd(1.2, Eigen::Vector3d(1, 2, 3).normalized());
  const std::string path = ::sightline::testing::TempDir("handeye_file") + "/hand_eye.yaml";
  ASSERT_TRUE(SaveHandEyeCalibration(result, path).ok());
  auto read = ReadHandEyeFile(path);
  ASSERT_TRUE(read.ok()) << read.status().ToString();
  EXPECT_TRUE(read->end_effector_from_camera.isApprox(result.end_effector_from_camera, 1e-9));
  ASSERT_TRUE(read->fit.has_value());
  EXPECT_EQ(read->fit->method, "park");
  EXPECT_EQ(read->fit->pairs, 9);
}

TEST(HandEye, BadInputGivesAClearStatus) {
  std::vector<Eigen::Isometry3d> three(3, Eigen::Isometry3d::Identity());
  std::vector<Eigen::Isometry3d> two(2, Eigen::Isometry3d::Identity());
  auto mismatched = CalibrateHandEye(three, two);
  ASSERT_FALSE(mismatched.ok());
  EXPECT_NE(mismatched.status().message().find("3 arm poses but 2 board poses"), std::string::npos);
  auto too_few = CalibrateHandEye(two, two);
  ASSERT_FALSE(too_few.ok());
  EXPECT_NE(too_few.status().message().find("at least 3"), std::string::npos);
  HandEyeOptions options;
  options.method = "magic";
  auto unknown = CalibrateHandEye(three, three, options);
  ASSERT_FALSE(unknown.ok());
  EXPECT_NE(unknown.status().message().find("calib.handeye.method"), std::string::npos);
}

}  // namespace
}  // namespace sightline
