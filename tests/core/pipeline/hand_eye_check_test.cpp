// The online hand-eye check on synthetic keyframes: a true mount agrees with the map's motion, a
// mount rotated by 3 deg shows as about 3 deg, a wrong mount translation is seen only when the arm
// rotates (and then its size is recovered), and the note says when it could not be seen.
#include "core/pipeline/hand_eye_check.h"

#include <gtest/gtest.h>

#include <cmath>

#include "core/io/hand_eye_file.h"

namespace sightline {
namespace {

constexpr double kLambda = 2.5;  // Map units per metre.

Eigen::Isometry3d Pose(const Eigen::Vector3d& t, const Eigen::Vector3d& rotation_vector) {
  Eigen::Isometry3d p = Eigen::Isometry3d::Identity();
  if (rotation_vector.norm() > 0) {
    p.linear() =
        Eigen::AngleAxisd(rotation_vector.norm(), rotation_vector.normalized()).toRotationMatrix();
  }
  p.translation() = t;
  return p;
}

// Keyframes of a camera moving sideways then forward (optionally turning about y), the map at
// scale kLambda with its origin elsewhere; the arm's camera poses use `mount_error` (true camera
// = measured end effector * true mount; measured camera = end effector * true mount * error).
void Make(const Eigen::Isometry3d& mount_error, double turn_deg, MapSnapshot* map,
          Trajectory* measured) {
  const Eigen::Isometry3d map_from_base = Pose({1, 2, 3}, {0, 0.3, 0});
  for (int k = 0; k < 12; ++k) {
    const Eigen::Vector3d t = k < 6 ? Eigen::Vector3d(0.03 * k, 0, 0)
                                    : Eigen::Vector3d(0.15, 0.01 * (k - 6), 0.06 * (k - 5));
    const double turn = (k % 2 ? 1 : -1) * turn_deg * M_PI / 180.0;
    const Eigen::Isometry3d base_from_camera = Pose(t, {0, turn, 0});
    MapSnapshot::Frame f;
    f.id = k;
    f.frame_index = k;
    f.time_s = 0.1 * k;
    Eigen::Isometry3d m = map_from_base * base_from_camera;
    m.translation() *= kLambda;
    f.map_from_camera = m;
    map->keyframes.push_back(f);
    measured->Add(f.time_s, base_from_camera * mount_error);
  }
}

HandEyeCheck Check(const Eigen::Isometry3d& mount_error, double turn_deg) {
  MapSnapshot map;
  Trajectory measured;
  Make(mount_error, turn_deg, &map, &measured);
  ScaleEstimatorOptions noise;
  noise.sigma_map = 1e-5;
  noise.sigma_metric_m = 1e-5;
  return CheckHandEye(map, measured, 0.01, kLambda, noise, 5.0, 0.05);
}

TEST(HandEyeCheck, ATrueMountAgreesWithTheMapsMotion) {
  const HandEyeCheck c = Check(Eigen::Isometry3d::Identity(), 0);
  EXPECT_GT(c.pairs, 20);
  EXPECT_LT(c.direction_deg, 0.01);
  EXPECT_FALSE(c.translation_observable);
  EXPECT_NE(c.Describe().find("cannot be seen"), std::string::npos) << c.Describe();
}

TEST(HandEyeCheck, AMountRotatedByThreeDegreesShowsInTheDirections) {
  const HandEyeCheck c = Check(Pose({0, 0, 0}, {0, 3 * M_PI / 180, 0}), 0);
  EXPECT_GT(c.direction_deg, 2.0);
  EXPECT_LT(c.direction_deg, 3.2);
  const HandEyeCheck x = Check(Pose({0, 0, 0}, {3 * M_PI / 180, 0, 0}), 0);
  EXPECT_GT(x.direction_deg, 1.5);  // About x: seen on the forward pairs only.
}

TEST(HandEyeCheck, AWrongMountTranslationIsSeenOnlyWhenTheArmRotates) {
  const Eigen::Isometry3d offset = Pose({0.03, 0, 0.02}, {0, 0, 0});
  const HandEyeCheck still = Check(offset, 0);
  EXPECT_FALSE(still.translation_observable);
  EXPECT_LT(still.direction_deg, 0.01);  // The same offset on every pose: invisible.
  const HandEyeCheck turning = Check(offset, 10);
  EXPECT_TRUE(turning.translation_observable);
  EXPECT_NEAR(turning.arm_rotation_deg, 20, 0.5);
  EXPECT_GT(turning.translation_m, 0.02);
  EXPECT_LT(turning.translation_m, 0.05);
  const HandEyeCheck right = Check(Eigen::Isometry3d::Identity(), 10);
  EXPECT_LT(right.translation_m, 1e-6);
}

TEST(HandEyeCheck, StatedSigmasRiseToTheFilesResiduals) {
  const std::string path = testing::TempDir() + "hand_eye_check_fit.yaml";
  HandEye he;
  he.fit = HandEyeFit{"tsai", 12, 40, 0.4, 0.015};
  ASSERT_TRUE(WriteHandEyeFile(he, path).ok());
  double m = 0.001, deg = 0.1;
  StatusOr<std::string> note = StateHandEyeSigmas(path, &m, &deg);
  ASSERT_TRUE(note.ok()) << note.status().ToString();
  EXPECT_DOUBLE_EQ(m, 0.015);
  EXPECT_DOUBLE_EQ(deg, 0.4);
  EXPECT_NE(note->find("residuals"), std::string::npos) << *note;
  he.fit.reset();
  ASSERT_TRUE(WriteHandEyeFile(he, path).ok());
  m = 0.001, deg = 0.1;
  note = StateHandEyeSigmas(path, &m, &deg);
  ASSERT_TRUE(note.ok());
  EXPECT_DOUBLE_EQ(m, 0.001);
  EXPECT_NE(note->find("no calibration residuals"), std::string::npos) << *note;
  EXPECT_FALSE(StateHandEyeSigmas(path + ".missing", &m, &deg).ok());
}

}  // namespace
}  // namespace sightline
