#include "core/eval/alignment.h"

#include <gtest/gtest.h>

#include "tests/core/eval/eval_test_util.h"

namespace sightline {
namespace {

std::vector<Eigen::Vector3d> Positions(const Trajectory& t) {
  std::vector<Eigen::Vector3d> points;
  for (const TimedPose& p : t.poses()) points.push_back(p.world_from_sensor.translation());
  return points;
}

Eigen::Isometry3d SomeTransform() {
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  t.linear() = (Eigen::AngleAxisd(0.7, Eigen::Vector3d::UnitZ()) *
                Eigen::AngleAxisd(-0.3, Eigen::Vector3d::UnitY()))
                   .toRotationMatrix();
  t.translation() = Eigen::Vector3d(1.5, -2.0, 0.25);
  return t;
}

TEST(Alignment, Se3RecoversTheRigidTransformBetweenWorldFrames) {
  const Trajectory gt = testing::Helix(60);
  const Eigen::Isometry3d gt_from_est = SomeTransform();
  const Trajectory est = testing::Transformed(gt, gt_from_est.inverse());
  StatusOr<Similarity3> s = AlignUmeyama(Positions(est), Positions(gt), AlignmentMode::kSe3);
  ASSERT_TRUE(s.ok()) << s.status().ToString();
  EXPECT_TRUE(s->rotation.isApprox(gt_from_est.linear(), 1e-12));
  EXPECT_TRUE(s->translation.isApprox(gt_from_est.translation(), 1e-12));
  EXPECT_DOUBLE_EQ(s->scale, 1.0);
  const Eigen::Isometry3d aligned = s->Apply(est.poses()[17].world_from_sensor);
  EXPECT_TRUE(aligned.isApprox(gt.poses()[17].world_from_sensor, 1e-12));
}

TEST(Alignment, Sim3ScaleIsTheFactorAppliedToTheEstimate) {
  const Trajectory gt = testing::Helix(60);
  const Trajectory est = testing::Transformed(testing::Scaled(gt, 2.0), SomeTransform());
  StatusOr<Similarity3> s = AlignUmeyama(Positions(est), Positions(gt), AlignmentMode::kSim3);
  ASSERT_TRUE(s.ok()) << s.status().ToString();
  EXPECT_NEAR(s->scale, 0.5, 1e-12);  // The estimate is twice too large.
  for (size_t i = 0; i < gt.size(); ++i) {
    EXPECT_LT((s->Apply(Eigen::Vector3d(est.poses()[i].world_from_sensor.translation())) -
               gt.poses()[i].world_from_sensor.translation())
                  .norm(),
              1e-12);
  }
}

TEST(Alignment, NeverReturnsAReflection) {
  const Trajectory gt = testing::Helix(40);
  std::vector<Eigen::Vector3d> mirrored = Positions(gt);
  for (Eigen::Vector3d& p : mirrored) p.x() = -p.x();
  StatusOr<Similarity3> s = AlignUmeyama(mirrored, Positions(gt), AlignmentMode::kSe3);
  ASSERT_TRUE(s.ok());
  EXPECT_NEAR(s->rotation.determinant(), 1.0, 1e-12);
}

TEST(Alignment, NoneIsTheIdentity) {
  const Trajectory gt = testing::Helix(10);
  StatusOr<Similarity3> s =
      AlignUmeyama(Positions(testing::Scaled(gt, 3)), Positions(gt), AlignmentMode::kNone);
  ASSERT_TRUE(s.ok());
  EXPECT_TRUE(s->rotation.isIdentity());
  EXPECT_TRUE(s->translation.isZero());
  EXPECT_EQ(s->scale, 1.0);
}

TEST(Alignment, DegenerateInputsFailWithAReason) {
  const std::vector<Eigen::Vector3d> two = {Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitX()};
  StatusOr<Similarity3> s = AlignUmeyama(two, two, AlignmentMode::kSe3);
  ASSERT_FALSE(s.ok());
  EXPECT_NE(s.status().message().find("at least 3"), std::string::npos) << s.status().message();

  const std::vector<Eigen::Vector3d> same(5, Eigen::Vector3d(1, 2, 3));
  s = AlignUmeyama(same, same, AlignmentMode::kSim3);
  ASSERT_FALSE(s.ok());
  EXPECT_NE(s.status().message().find("coincide"), std::string::npos) << s.status().message();

  s = AlignUmeyama(same, two, AlignmentMode::kNone);
  ASSERT_FALSE(s.ok());
  EXPECT_NE(s.status().message().find("5 estimated vs 2"), std::string::npos);
}

TEST(Alignment, ParsesModeNames) {
  EXPECT_EQ(*ParseAlignmentMode("sim3"), AlignmentMode::kSim3);
  EXPECT_EQ(*ParseAlignmentMode("se3"), AlignmentMode::kSe3);
  EXPECT_EQ(*ParseAlignmentMode("none"), AlignmentMode::kNone);
  StatusOr<AlignmentMode> bad = ParseAlignmentMode("SE3");
  ASSERT_FALSE(bad.ok());
  EXPECT_NE(bad.status().message().find("se3, sim3 or none"), std::string::npos);
}

}  // namespace
}  // namespace sightline
