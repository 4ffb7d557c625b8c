#include "core/stereo/disparity_offset.h"

#include <gtest/gtest.h>

#include <numeric>
#include <random>

#include "core/stereo/motion_refiner.h"
#include "stereo_test_util.h"

namespace sightline {
namespace {

using testing::TranslationErrorM;

// 3 m forward with a small turn: parallax of about a fifth of the points' depth.
Eigen::Isometry3d FastMotion() {
  Eigen::Isometry3d m = Eigen::Isometry3d::Identity();
  m.linear() = Eigen::AngleAxisd(0.04, Eigen::Vector3d::UnitY()).toRotationMatrix();
  m.translation() = Eigen::Vector3d(0.1, 0.0, -3.0);
  return m;
}

// Correspondences whose measured disparities are all `offset_px` too small.
std::vector<StereoCorrespondence> Biased(const std::vector<StereoCorrespondence>& exact,
                                         double offset_px) {
  std::vector<StereoCorrespondence> out = exact;
  for (StereoCorrespondence& c : out) {
    c.previous.u_right += offset_px;
    c.current.u_right += offset_px;
  }
  return out;
}

// Applies the estimator's offset, refines the motion from the truth and measures the offset.
Eigen::Isometry3d Step(const RectifiedStereoCamera& camera,
                       const std::vector<StereoCorrespondence>& measured,
                       const Eigen::Isometry3d& truth, DisparityOffsetEstimator* estimator) {
  std::vector<StereoCorrespondence> c = measured;
  for (StereoCorrespondence& x : c) {
    estimator->Apply(&x);
    Triangulate(camera, &x);
  }
  std::vector<int> all(c.size());
  std::iota(all.begin(), all.end(), 0);
  Eigen::Isometry3d motion = truth;
  MotionRefiner().Refine(camera, c, all, &motion);
  estimator->Update(MeasureDisparityOffset(camera, c, all, motion, estimator->options()));
  return motion;
}

TEST(DisparityOffset, RecoversAConstantOffsetFromFastMotionAndFixesTheTranslation) {
  const RectifiedStereoCamera camera = testing::TestCamera();
  const Eigen::Isometry3d truth = FastMotion();
  const auto exact = testing::SyntheticCorrespondences(camera, truth, 300, 0, 0.2, 11);
  const auto measured = Biased(exact, 0.3);
  DisparityOffsetOptions options;
  options.prior_sigma_px = 1.0;
  DisparityOffsetEstimator estimator(options);
  estimator.Reset();
  const Eigen::Isometry3d first = Step(camera, measured, truth, &estimator);
  Eigen::Isometry3d last = first;
  for (int i = 0; i < 5; ++i) last = Step(camera, measured, truth, &estimator);
  EXPECT_NEAR(estimator.offset_px(), 0.3, 0.05);
  // Uncorrected, the translation comes out too long; corrected, the error shrinks.
  EXPECT_GT(first.translation().norm(), truth.translation().norm() + 0.02);
  EXPECT_LT(TranslationErrorM(last, truth), TranslationErrorM(first, truth) / 3);
}

TEST(DisparityOffset, StaysAtZeroWithoutParallaxAndWithoutOffset) {
  const RectifiedStereoCamera camera = testing::TestCamera();
  // Standing still: nothing to measure.
  DisparityOffsetEstimator still;
  still.Reset();
  const auto static_pairs =
      testing::SyntheticCorrespondences(camera, Eigen::Isometry3d::Identity(), 200, 0, 0.2, 12);
  for (int i = 0; i < 3; ++i)
    Step(camera, Biased(static_pairs, 0.3), Eigen::Isometry3d::Identity(), &still);
  EXPECT_EQ(still.offset_px(), 0.0);
  // Fast motion, exact disparities: the estimate stays near zero.
  DisparityOffsetEstimator exact_rig;
  exact_rig.Reset();
  const auto exact = testing::SyntheticCorrespondences(camera, FastMotion(), 300, 0, 0.2, 13);
  for (int i = 0; i < 5; ++i) Step(camera, exact, FastMotion(), &exact_rig);
  EXPECT_NEAR(exact_rig.offset_px(), 0.0, 0.05);
  // Disabled: never applied.
  DisparityOffsetOptions off;
  off.enabled = false;
  DisparityOffsetEstimator disabled(off);
  disabled.Reset();
  for (int i = 0; i < 3; ++i) Step(camera, Biased(exact, 0.3), FastMotion(), &disabled);
  EXPECT_EQ(disabled.offset_px(), 0.0);
}

// Tracks of fixed world points seen from a camera moving 0.3 m forward per frame (too little
// parallax for one frame pair), their disparities `offset_px` too small.
std::vector<OffsetTrack> TracksAt(const RectifiedStereoCamera& camera,
                                  const Eigen::Isometry3d& world_from_camera, double offset_px,
                                  unsigned seed) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> depth(4, 30), side(-1, 1);
  std::mt19937 noise_rng(seed);
  std::normal_distribution<double> noise(0, 0.1);
  std::vector<OffsetTrack> tracks;
  for (int i = 0; i < 400; ++i) {
    const double z = depth(rng);
    const Eigen::Vector3d world(side(rng) * 0.5 * z, side(rng) * 0.3 * z, z);
    const Eigen::Vector3d x = world_from_camera.inverse() * world;
    if (!(x.z() > 1)) continue;
    const Eigen::Vector2d l = camera.ProjectLeft(x), r = camera.ProjectRight(x);
    if (l.x() < 0 || l.y() < 0 || r.x() < 0 || l.x() >= camera.width || l.y() >= camera.height)
      continue;
    OffsetTrack t;
    t.id = i;
    t.observation = {l.x() + noise(noise_rng), l.y(), r.x() + offset_px + noise(noise_rng)};
    tracks.push_back(t);
  }
  return tracks;
}

TEST(DisparityOffset, SlowMotionIsMeasuredAcrossSeveralFrames) {
  const RectifiedStereoCamera camera = testing::TestCamera();
  const MotionRefiner refiner;
  DisparityOffsetOptions options;
  options.prior_sigma_px = 1.0;
  DisparityOffsetEstimator moving(options), still(options);
  for (int n = 0; n < 30; ++n) {
    Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
    pose.translation().z() = 0.3 * n;
    moving.Observe(camera, refiner, 1.0, TracksAt(camera, pose, 0.3, n), pose, true);
    still.Observe(camera, refiner, 1.0, TracksAt(camera, Eigen::Isometry3d::Identity(), 0.3, n),
                  Eigen::Isometry3d::Identity(), true);
  }
  EXPECT_NEAR(moving.offset_px(), 0.3, 0.05);
  EXPECT_EQ(still.offset_px(), 0.0);
  EXPECT_EQ(still.estimate_px(), 0.0);
}

}  // namespace
}  // namespace sightline
