#include "core/stereo/window_bundle_adjuster.h"

#include <gtest/gtest.h>

#include <random>

#include "stereo_test_util.h"

namespace sightline {
namespace {

using testing::RotationErrorDeg;
using testing::TranslationErrorM;

// A rig driving forward 0.3 m per frame with a slight turn, through a field of points 3..30 m
// ahead; every point is seen in every frame (one track each).
struct Drive {
  std::vector<Eigen::Isometry3d> world_from_camera;
  std::vector<Eigen::Vector3d> points;
};

Drive MakeDrive(int frames, int points, unsigned seed) {
  Drive d;
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  Eigen::Isometry3d step = Eigen::Isometry3d::Identity();
  step.linear() = Eigen::AngleAxisd(0.004, Eigen::Vector3d::UnitY()).toRotationMatrix();
  step.translation() = Eigen::Vector3d(0.01, 0.0, 0.3);
  for (int i = 0; i < frames; ++i) {
    d.world_from_camera.push_back(pose);
    pose = pose * step;
  }
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> depth(3 + 0.3 * frames, 30), lateral(-0.45, 0.45);
  for (int i = 0; i < points; ++i) {
    const double z = depth(rng);
    d.points.emplace_back(lateral(rng) * z, 0.6 * lateral(rng) * z, z);
  }
  return d;
}

std::vector<TrackObservation> Observe(const RectifiedStereoCamera& camera,
                                      const Eigen::Isometry3d& world_from_camera,
                                      const std::vector<Eigen::Vector3d>& points, double noise_px,
                                      std::mt19937* rng) {
  std::normal_distribution<double> noise(0, noise_px);
  std::vector<TrackObservation> out;
  for (size_t i = 0; i < points.size(); ++i) {
    const Eigen::Vector3d x = world_from_camera.inverse() * points[i];
    const Eigen::Vector2d l = camera.ProjectLeft(x), r = camera.ProjectRight(x);
    const double dv = noise(*rng);
    out.push_back({static_cast<int64_t>(i), static_cast<float>(l.x() + noise(*rng)),
                   static_cast<float>(l.y() + dv), static_cast<float>(r.x() + noise(*rng))});
  }
  return out;
}

// A small error of the kind frame-to-frame estimation leaves: 0.1 deg and 2 cm.
Eigen::Isometry3d Perturbed(const Eigen::Isometry3d& pose, int i) {
  Eigen::Isometry3d p = pose;
  p.linear() = p.linear() * Eigen::AngleAxisd(0.1 * M_PI / 180 * (i % 2 ? 1 : -1),
                                              Eigen::Vector3d(0.3, 1, 0.2).normalized())
                                .toRotationMatrix();
  p.translation() += Eigen::Vector3d(0.02, -0.01, 0.015);
  return p;
}

TEST(WindowBundleAdjuster, PullsPerturbedPosesBackToTheTruth) {
  const RectifiedStereoCamera camera = testing::TestCamera();
  const Drive drive = MakeDrive(8, 300, 3);
  WindowBundleOptions options;
  options.frames = 6;
  options.min_parallax = 0;  // Every frame stays.
  WindowBundleAdjuster window(options);
  std::mt19937 rng(7);
  double worst_rotation = 0, worst_translation = 0;
  for (int i = 0; i < 8; ++i) {
    const Eigen::Isometry3d& truth = drive.world_from_camera[static_cast<size_t>(i)];
    // The first frame anchors the window and is given exactly; later ones with an error.
    const Eigen::Isometry3d input = i == 0 ? truth : Perturbed(truth, i);
    WindowBundleSummary summary;
    const Eigen::Isometry3d refined =
        window.Add(camera, input, Observe(camera, truth, drive.points, 0.1, &rng), &summary);
    if (i == 0) {
      EXPECT_FALSE(summary.adjusted);
      continue;
    }
    ASSERT_TRUE(summary.adjusted) << "frame " << i;
    EXPECT_EQ(summary.points, 300);
    EXPECT_EQ(summary.frames, std::min(i + 1, 6));
    EXPECT_EQ(summary.fixed_frames, std::max(0, i + 1 - 6));
    EXPECT_LT(summary.final_rms_px, summary.initial_rms_px);
    // 0.1 px noise on 300 points: the refined pose is many times closer than the input (0.1 deg,
    // 27 mm). Once frame 0 has left the window, the oldest (fixed) frame carries its own
    // refined error of a few millimetres.
    worst_rotation = std::max(worst_rotation, RotationErrorDeg(refined, truth));
    worst_translation = std::max(worst_translation, TranslationErrorM(refined, truth));
    EXPECT_LT(RotationErrorDeg(refined, truth), 0.01) << "frame " << i;
    EXPECT_LT(TranslationErrorM(refined, truth), 0.005) << "frame " << i;
  }
  std::cout << "worst refined error: " << worst_rotation << " deg, " << worst_translation * 1000
            << " mm\n";
}

// Odometry-like use over a long drive: each frame arrives as the last refined pose moved by a
// noisy relative motion, its tracks seen with 0.3 px noise. Frames that left the window but keep
// observing (fixed_frames) tie the window to where those tracks were seen before, so the pose
// drifts less than when only the window's own oldest frame holds it.
double DriftAfterLongDrive(int fixed_frames, unsigned seed) {
  const RectifiedStereoCamera camera = testing::TestCamera();
  const int frames = 40;
  const Drive drive = MakeDrive(frames, 200, seed);
  WindowBundleOptions options;
  options.min_parallax = 0;
  options.fixed_frames = fixed_frames;
  WindowBundleAdjuster window(options);
  std::mt19937 rng(seed + 100);
  std::normal_distribution<double> angle(0, 0.02 * M_PI / 180), shift(0, 0.003);
  Eigen::Isometry3d estimate = drive.world_from_camera[0];
  for (int i = 0; i < frames; ++i) {
    const Eigen::Isometry3d& truth = drive.world_from_camera[static_cast<size_t>(i)];
    if (i > 0) {
      Eigen::Isometry3d noisy =
          drive.world_from_camera[static_cast<size_t>(i - 1)].inverse() * truth;
      noisy.linear() = noisy.linear() *
                       Eigen::AngleAxisd(angle(rng), Eigen::Vector3d::UnitY()).toRotationMatrix() *
                       Eigen::AngleAxisd(angle(rng), Eigen::Vector3d::UnitX()).toRotationMatrix();
      noisy.translation() += Eigen::Vector3d(shift(rng), shift(rng), shift(rng));
      estimate = estimate * noisy;
    }
    estimate = window.Add(camera, estimate, Observe(camera, truth, drive.points, 0.3, &rng));
  }
  return RotationErrorDeg(estimate, drive.world_from_camera.back());
}

TEST(WindowBundleAdjuster, FixedFramesThatStillObserveReduceDrift) {
  double without = 0, with = 0;
  for (unsigned seed = 1; seed <= 4; ++seed) {
    without += DriftAfterLongDrive(0, seed);
    with += DriftAfterLongDrive(6, seed);
  }
  std::cout << "mean rotation drift after 40 frames: " << without / 4 << " deg without, "
            << with / 4 << " deg with 6 fixed frames\n";
  EXPECT_LT(with, 0.8 * without);
}

TEST(WindowBundleAdjuster, DropsAMovingObjectsTracks) {
  const RectifiedStereoCamera camera = testing::TestCamera();
  Drive drive = MakeDrive(6, 300, 5);
  WindowBundleOptions options;
  options.min_parallax = 0;  // Every frame stays.
  WindowBundleAdjuster window(options);
  std::mt19937 rng(9);
  Eigen::Isometry3d refined;
  WindowBundleSummary summary;
  for (int i = 0; i < 6; ++i) {
    // The first 40 points ride on something moving sideways 5 cm per frame.
    std::vector<Eigen::Vector3d> seen = drive.points;
    for (int p = 0; p < 40; ++p) seen[static_cast<size_t>(p)].x() += 0.05 * i;
    const Eigen::Isometry3d& truth = drive.world_from_camera[static_cast<size_t>(i)];
    refined = window.Add(camera, i == 0 ? truth : Perturbed(truth, i),
                         Observe(camera, truth, seen, 0.1, &rng), &summary);
  }
  ASSERT_TRUE(summary.adjusted);
  EXPECT_GT(summary.dropped, 0);  // The mover's observations that disagree most.
  EXPECT_LT(RotationErrorDeg(refined, drive.world_from_camera.back()), 0.02);
  EXPECT_LT(TranslationErrorM(refined, drive.world_from_camera.back()), 0.004);
}

TEST(WindowBundleAdjuster, TooFewSharedTracksLeavesThePoseAsGiven) {
  const RectifiedStereoCamera camera = testing::TestCamera();
  const Drive drive = MakeDrive(2, 10, 11);
  WindowBundleAdjuster window;
  std::mt19937 rng(1);
  window.Add(camera, drive.world_from_camera[0],
             Observe(camera, drive.world_from_camera[0], drive.points, 0.1, &rng));
  const Eigen::Isometry3d input = Perturbed(drive.world_from_camera[1], 1);
  WindowBundleSummary summary;
  const Eigen::Isometry3d out =
      window.Add(camera, input,
                 Observe(camera, drive.world_from_camera[1], drive.points, 0.1, &rng), &summary);
  EXPECT_FALSE(summary.adjusted);
  EXPECT_EQ(summary.points, 10);
  EXPECT_LT(TranslationErrorM(out, input), 1e-12);
  // After a reset the window starts again from the next frame alone.
  window.Reset();
  EXPECT_EQ(window.size(), 0u);
}

TEST(WindowBundleAdjuster, FramesThatBarelyMovedAreReplacedByTheNext) {
  const RectifiedStereoCamera camera = testing::TestCamera();
  const Drive drive = MakeDrive(1, 200, 2);  // Points 3.3..30 m ahead: median depth ~17 m.
  WindowBundleOptions options;
  options.min_parallax = 0.02;  // ~0.33 m to stay.
  WindowBundleAdjuster window(options);
  std::mt19937 rng(4);
  auto add = [&](double z) {
    Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
    pose.translation().z() = z;
    window.Add(camera, pose, Observe(camera, pose, drive.points, 0.05, &rng));
  };
  add(0);
  for (int i = 1; i <= 5; ++i) add(0.02 * i);  // Creeping: each replaces the one before.
  EXPECT_EQ(window.size(), 2u);
  add(0.5);  // 0.5 m from the first frame: stays.
  EXPECT_EQ(window.size(), 2u);
  add(0.52);
  EXPECT_EQ(window.size(), 3u);
}

TEST(WindowBundleOptions, RejectsAbsurdValuesNamingTheKey) {
  std::string error;
  WindowBundleOptions o;
  EXPECT_TRUE(o.IsValid(&error));
  o.frames = 1;
  EXPECT_FALSE(o.IsValid(&error));
  EXPECT_NE(error.find("stereo.window.frames"), std::string::npos);
  o = WindowBundleOptions();
  o.huber_px = 0;
  EXPECT_FALSE(o.IsValid(&error));
  EXPECT_NE(error.find("stereo.window.huber_px"), std::string::npos);
  o = WindowBundleOptions();
  o.min_parallax = -1;
  EXPECT_FALSE(o.IsValid(&error));
  EXPECT_NE(error.find("stereo.window.min_parallax"), std::string::npos);
  o = WindowBundleOptions();
  o.fixed_frames = -1;
  EXPECT_FALSE(o.IsValid(&error));
  EXPECT_NE(error.find("stereo.window.fixed_frames"), std::string::npos);
}

}  // namespace
}  // namespace sightline
