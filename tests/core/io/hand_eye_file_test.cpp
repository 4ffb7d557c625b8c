// hand_eye.yaml: what the writer, the simulator and older `calibrate handeye` files hold reads
// back; every check rejects a bad value naming the file, the line and the key.
#include "core/io/hand_eye_file.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <opencv2/core/persistence.hpp>

#include "core/sim/ground_truth_files.h"
#include "core/sim/simulate.h"
#include "core/sim/simulator.h"
#include "tests/core/io/io_test_util.h"
#include "tests/support/test_data.h"

namespace sightline {
namespace {

using ::testing::HasSubstr;
using testing::TempDir;
using testing::WriteText;

Eigen::Isometry3d Mount() {
  return Eigen::Translation3d(0.06, -0.01, -0.03) *
         Eigen::AngleAxisd(1.2, Eigen::Vector3d(1, 2, 3).normalized());
}

TEST(HandEyeFile, WritesAndReadsBackEverything) {
  HandEye file;
  file.end_effector_from_camera = Mount();
  file.world_from_base = Eigen::Isometry3d(Eigen::Translation3d(0.5, 0, 0.75));
  file.fit = HandEyeFit{"park", 9, 41.5, 0.05, 0.0004};
  const std::string path = TempDir("hand_eye_round_trip") + "/hand_eye.yaml";
  ASSERT_TRUE(WriteHandEyeFile(file, path, {{"a header"}, {}}).ok());
  auto read = ReadHandEyeFile(path);
  ASSERT_TRUE(read.ok()) << read.status().ToString();
  EXPECT_TRUE(read->end_effector_from_camera.isApprox(file.end_effector_from_camera, 1e-12));
  ASSERT_TRUE(read->world_from_base.has_value());
  EXPECT_TRUE(read->world_from_base->isApprox(*file.world_from_base, 1e-12));
  ASSERT_TRUE(read->fit.has_value());
  EXPECT_EQ(read->fit->method, "park");
  EXPECT_EQ(read->fit->pairs, 9);
  EXPECT_EQ(read->fit->max_rotation_deg, 41.5);
  EXPECT_EQ(read->fit->board_translation_rms_m, 0.0004);

  cv::FileStorage fs(path, cv::FileStorage::READ);  // OpenCV reads it too.
  ASSERT_TRUE(fs.isOpened());
  std::vector<double> t;
  fs["end_effector_from_camera"]["translation"] >> t;
  ASSERT_EQ(t.size(), 3u);
  EXPECT_DOUBLE_EQ(t[0], 0.06);
  EXPECT_EQ(static_cast<std::string>(fs["method"]), "park");
}

TEST(HandEyeFile, ReadsWhatTheSimulatorWrites) {
  sim::SimulationOptions options = sim::SimulationOptions::ForScene("panel");
  options.frames = 2;
  options.mono.width = 160;
  options.mono.height = 120;
  options.mono.focal_px = 131.25;
  const std::string dir = TempDir("hand_eye_sim");
  auto summary = sim::Simulate(options, dir);
  ASSERT_TRUE(summary.ok()) << summary.status().ToString();
  auto read = ReadHandEyeFile(dir + "/hand_eye.yaml");
  ASSERT_TRUE(read.ok()) << read.status().ToString();
  auto simulator = sim::Simulator::Create(options);
  ASSERT_TRUE(simulator.ok());
  EXPECT_TRUE(read->end_effector_from_camera.isApprox(simulator->motion().body_from_camera, 1e-12));
  ASSERT_TRUE(read->world_from_base.has_value());
  EXPECT_TRUE(read->world_from_base->isApprox(simulator->motion().world_from_arm_base, 1e-12));
  EXPECT_FALSE(read->fit.has_value());
}

// The layout earlier versions wrote: the simulator's (no %YAML line, 9 decimals) and
// `calibrate handeye`'s (cv::FileStorage, with the rotation matrix and the fit's figures).
TEST(HandEyeFile, ReadsTheEarlierLayouts) {
  const std::string dir = TempDir("hand_eye_layouts");
  WriteText(dir + "/sim.yaml",
            "# Hand-eye calibration of the simulated arm (metres).\n"
            "end_effector_from_camera:\n  translation: [0.000000000, 0.000000000, 0.050000000]\n"
            "  quaternion_xyzw: [0.000000000, 0.000000000, 0.707106781, 0.707106781]\n"
            "world_from_base:\n  translation: [0.000000000, 0.000000000, 0.750000000]\n"
            "  quaternion_xyzw: [0.000000000, 0.000000000, 0.000000000, 1.000000000]\n");
  auto sim_file = ReadHandEyeFile(dir + "/sim.yaml");
  ASSERT_TRUE(sim_file.ok()) << sim_file.status().ToString();
  EXPECT_NEAR(sim_file->end_effector_from_camera.linear()(1, 0), 1.0, 1e-9);
  WriteText(dir + "/calib.yaml",
            "%YAML:1.0\n---\n# Sightline hand-eye calibration (tsai, 12 pairs)\n"
            "end_effector_from_camera:\n   translation: [ 1.0e-02, 0., 5.0e-02 ]\n"
            "   quaternion_xyzw: [ 0., 0., 0., 1. ]\n"
            "rotation: !!opencv-matrix\n   rows: 3\n   cols: 3\n   dt: d\n"
            "   data: [ 1., 0., 0., 0., 1., 0., 0., 0., 1. ]\n"
            "method: tsai\npairs: 12\nmax_rotation_deg: 4.0e+01\n"
            "board_rotation_rms_deg: 5.0e-02\nboard_translation_rms_m: 4.0e-04\n");
  auto calib_file = ReadHandEyeFile(dir + "/calib.yaml");
  ASSERT_TRUE(calib_file.ok()) << calib_file.status().ToString();
  EXPECT_EQ(calib_file->end_effector_from_camera.translation().x(), 0.01);
  ASSERT_TRUE(calib_file->fit.has_value());
  EXPECT_EQ(calib_file->fit->method, "tsai");
  EXPECT_EQ(calib_file->fit->pairs, 12);
}

constexpr const char* kMount =
    "end_effector_from_camera:\n  translation: [0.1, 0.2, 0.3]\n"
    "  quaternion_xyzw: [0, 0, 0, 1]\n";

TEST(HandEyeFile, EachRuleRejectsNamingFileLineAndKey) {
  const std::string dir = TempDir("hand_eye_rules");
  struct Case {
    std::string text;
    std::string expected;
  };
  const std::vector<Case> cases = {
      {"end_effector_from_camera:\n  translation: [0.1, 0.2]\n  quaternion_xyzw: [0, 0, 0, 1]\n",
       " line 2: key 'end_effector_from_camera.translation': expected 3 numbers, found 2"},
      {"end_effector_from_camera:\n  translation: [0.1, .nan, 0]\n"
       "  quaternion_xyzw: [0, 0, 0, 1]\n",
       " line 2: key 'end_effector_from_camera.translation': .nan is not finite"},
      {"end_effector_from_camera:\n  translation: [0, 0, 0]\n  quaternion_xyzw: [0, 0, 0, 1.01]\n",
       " line 3: key 'end_effector_from_camera.quaternion_xyzw': has length 1.01, not 1 (within "
       "1e-06)"},
      {"end_effector_from_camera:\n  translation: [0, 0, 0]\n  quaternion_xyzw: [0, 0, 0, 1]\n"
       "  rotation_deg: 3\n",
       " line 4: unknown key 'end_effector_from_camera.rotation_deg'"},
      {"world_from_base:\n  translation: [0, 0, 0.75]\n  quaternion_xyzw: [0, 0, 0, 1]\n",
       ": key 'end_effector_from_camera': missing"},
      {std::string(kMount) + "rotation: [1, 0, 0, 0, 1, 0, 0, 0, -1]\n",
       " line 4: key 'rotation': is not a rotation: its determinant is -1"},
      {std::string(kMount) + "rotation: [0, -1, 0, 1, 0, 0, 0, 0, 1]\n",
       " line 4: key 'rotation': differs from end_effector_from_camera.quaternion_xyzw by 1"},
      {std::string(kMount) + "method: tsai\n", ": key 'pairs': missing"},
      {std::string(kMount) +
           "method: tsai\npairs: 0\nmax_rotation_deg: 1\nboard_rotation_rms_deg: 0\n"
           "board_translation_rms_m: 0\n",
       " line 5: key 'pairs': must be positive"},
      {std::string(kMount) +
           "method: tsai\npairs: 3\nmax_rotation_deg: 1\nboard_rotation_rms_deg: -1\n"
           "board_translation_rms_m: 0\n",
       " line 7: key 'board_rotation_rms_deg': must not be negative"},
      {std::string(kMount) + "scale: 1\n", " line 4: unknown key 'scale'"},
  };
  for (size_t i = 0; i < cases.size(); ++i) {
    const std::string path = dir + "/case" + std::to_string(i) + ".yaml";
    WriteText(path, cases[i].text);
    const Status status = ReadHandEyeFile(path).status();
    EXPECT_EQ(status.code(), StatusCode::kParseError) << path;
    EXPECT_THAT(status.message(), HasSubstr(path + cases[i].expected));
  }
}

TEST(HandEyeFile, WriterRefusesWhatTheReaderWouldReject) {
  const std::string path = TempDir("hand_eye_refuse") + "/hand_eye.yaml";
  HandEye file;
  file.end_effector_from_camera.linear() *= 1.01;
  EXPECT_THAT(WriteHandEyeFile(file, path).message(),
              HasSubstr("end_effector_from_camera rotation is not a rotation"));
  file.end_effector_from_camera = Mount();
  file.fit = HandEyeFit{"tsai", 0, 0, 0, 0};
  EXPECT_THAT(WriteHandEyeFile(file, path).message(), HasSubstr("pairs must be positive"));
  EXPECT_FALSE(std::filesystem::exists(path));
}

}  // namespace
}  // namespace sightline
