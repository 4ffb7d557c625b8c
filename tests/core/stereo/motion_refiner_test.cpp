#include "core/stereo/motion_refiner.h"

#include <gtest/gtest.h>

#include <numeric>

#include "core/stereo/motion_estimator.h"
#include "stereo_test_util.h"

namespace sightline {
namespace {

using testing::RotationErrorDeg;
using testing::TranslationErrorM;

TEST(MotionRefiner, ReducesErrorOfAPerturbedSeed) {
  const RectifiedStereoCamera camera = testing::TestCamera();
  const Eigen::Isometry3d truth = testing::TestMotion();
  const auto correspondences = testing::SyntheticCorrespondences(camera, truth, 400, 0, 0.3, 5);
  std::vector<int> all(correspondences.size());
  std::iota(all.begin(), all.end(), 0);
  Eigen::Isometry3d seed = truth;
  seed.translation() += Eigen::Vector3d(0.05, -0.02, 0.08);
  seed.linear() = Eigen::AngleAxisd(0.01, Eigen::Vector3d::UnitX()) * seed.linear();
  Eigen::Isometry3d refined = seed;
  const RefinementSummary s = MotionRefiner().Refine(camera, correspondences, all, &refined);
  EXPECT_LT(s.final_rms_px, s.initial_rms_px);
  // As good as the true motion on noisy data (the least-squares optimum lies next to it).
  EXPECT_LT(s.final_rms_px,
            1.05 * MotionRefiner::RmsReprojectionPx(camera, correspondences, all, truth));
  EXPECT_LT(TranslationErrorM(refined, truth), 0.01);
  EXPECT_LT(RotationErrorDeg(refined, truth), 0.05);
  EXPECT_LT(TranslationErrorM(refined, truth), TranslationErrorM(seed, truth) / 5);
}

TEST(MotionRefiner, BeatsAbsoluteOrientationOnNoisyDepth) {
  // Depth noise grows with Z^2: minimising reprojection error beats 3D point distances.
  const RectifiedStereoCamera camera = testing::TestCamera();
  const Eigen::Isometry3d truth = testing::TestMotion();
  const auto correspondences = testing::SyntheticCorrespondences(camera, truth, 400, 0, 0.5, 6);
  Eigen::Matrix3Xd from(3, correspondences.size()), to(3, correspondences.size());
  std::vector<int> all(correspondences.size());
  for (size_t i = 0; i < correspondences.size(); ++i) {
    from.col(static_cast<Eigen::Index>(i)) = correspondences[i].x_previous;
    to.col(static_cast<Eigen::Index>(i)) = correspondences[i].x_current;
    all[i] = static_cast<int>(i);
  }
  const Eigen::Isometry3d umeyama = AbsoluteOrientation(from, to);
  Eigen::Isometry3d refined = umeyama;
  MotionRefiner().Refine(camera, correspondences, all, &refined);
  EXPECT_LT(TranslationErrorM(refined, truth), TranslationErrorM(umeyama, truth));
}

TEST(MotionRefiner, LeavesMotionUnchangedWithTooFewPoints) {
  const RectifiedStereoCamera camera = testing::TestCamera();
  const auto correspondences =
      testing::SyntheticCorrespondences(camera, testing::TestMotion(), 2, 0, 0, 7);
  Eigen::Isometry3d m = Eigen::Isometry3d::Identity();
  MotionRefiner().Refine(camera, correspondences, {0, 1}, &m);
  EXPECT_TRUE(m.isApprox(Eigen::Isometry3d::Identity()));
}

}  // namespace
}  // namespace sightline
