// hand_eye.yaml as the simulator writes it reads back exactly; malformed files name the line.
#include "core/button/hand_eye.h"

#include <gtest/gtest.h>

#include <fstream>

#include "core/sim/ground_truth_files.h"
#include "tests/support/test_data.h"

namespace sightline {
namespace {

TEST(HandEye, ReadsWhatTheSimulatorWrites) {
  Eigen::Isometry3d ee_from_camera = Eigen::Isometry3d::Identity();
  ee_from_camera.linear() =
      Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  ee_from_camera.translation() = Eigen::Vector3d(0.06, 0.0, -0.03);
  Eigen::Isometry3d world_from_base = Eigen::Isometry3d::Identity();
  world_from_base.translation() = Eigen::Vector3d(0, 0, 0.75);
  const std::string path = testing::TempDir("hand_eye") + "/hand_eye.yaml";
  ASSERT_TRUE(sim::WriteHandEyeYaml(ee_from_camera, world_from_base, path).ok());
  auto read = ReadHandEyeFile(path);
  ASSERT_TRUE(read.ok()) << read.status().ToString();
  EXPECT_TRUE(read->end_effector_from_camera.isApprox(ee_from_camera, 1e-8));
  ASSERT_TRUE(read->world_from_base.has_value());
  EXPECT_TRUE(read->world_from_base->isApprox(world_from_base, 1e-8));
}

TEST(HandEye, MalformedFilesNameTheProblem) {
  EXPECT_EQ(ReadHandEyeFile("/nonexistent/hand_eye.yaml").status().code(), StatusCode::kNotFound);
  const std::string path = testing::TempDir("hand_eye_bad") + "/bad.yaml";
  std::ofstream(path) << "end_effector_from_camera:\n  translation: [0.1, 0.2]\n";
  auto bad = ReadHandEyeFile(path);
  ASSERT_FALSE(bad.ok());
  EXPECT_NE(bad.status().message().find("line 2"), std::string::npos) << bad.status().message();
  std::ofstream(path)
      << "world_from_base:\n  translation: [0, 0, 0.75]\n  quaternion_xyzw: [0, 0, 0, 1]\n";
  auto missing = ReadHandEyeFile(path);
  ASSERT_FALSE(missing.ok());
  EXPECT_NE(missing.status().message().find("end_effector_from_camera"), std::string::npos);
}

}  // namespace
}  // namespace sightline
