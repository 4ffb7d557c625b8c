// Revisits of mapped space: the similarity that bends a drifted map onto the old one, and a
// robot driving a small corridor loop 1.3 times, whose second pass must track the first pass's
// map instead of mapping the corridor again.
#include "core/mono/loop_closer.h"

#include <gtest/gtest.h>

#include <iostream>

#include "core/eval/evaluation.h"
#include "core/mono/mono_slam.h"
#include "tests/core/mono/mono_test_util.h"

namespace sightline {
namespace {

MapCorrection SomeCorrection() {
  MapCorrection c;
  c.scale = 1.3;
  c.rotation = Eigen::AngleAxisd(0.2, Eigen::Vector3d(0.3, 1, 0.1).normalized()).toRotationMatrix();
  c.translation = Eigen::Vector3d(0.5, -0.2, 1.0);
  return c;
}

TEST(MapCorrection, CorrectedCameraSeesTheCorrectedPointScaled) {
  const MapCorrection c = SomeCorrection();
  Eigen::Isometry3d camera_from_map = Eigen::Isometry3d::Identity();
  camera_from_map.linear() = Eigen::AngleAxisd(0.7, Eigen::Vector3d::UnitY()).toRotationMatrix();
  camera_from_map.translation() = Eigen::Vector3d(0.1, 0.2, 2.0);
  const Eigen::Vector3d x(0.4, -0.3, 1.5);
  const Eigen::Vector3d seen = camera_from_map * x;
  const Eigen::Vector3d corrected = c.CorrectPose(camera_from_map) * c.Apply(x);
  EXPECT_LT((corrected - c.scale * seen).norm(), 1e-12);
}

TEST(MapCorrection, PartialCorrectionRunsFromNothingToAll) {
  const MapCorrection c = SomeCorrection();
  const Eigen::Vector3d centre(1, 2, 3), x(1.5, 2.5, 2.0);
  EXPECT_LT((c.Partial(0, centre).Apply(x) - x).norm(), 1e-12);
  EXPECT_LT((c.Partial(1, centre).Apply(x) - c.Apply(x)).norm(), 1e-9);
  const MapCorrection half = c.Partial(0.5, centre);
  EXPECT_NEAR(half.scale, std::sqrt(c.scale), 1e-12);
  EXPECT_LT((half.Apply(centre) - (centre + 0.5 * (c.Apply(centre) - centre))).norm(), 1e-12);
}

// Sim(3) ATE of the map's keyframes against the ground truth, as a percentage of the path.
double KeyFrameAtePercent(const MapSnapshot& map, const Trajectory& ground_truth) {
  Trajectory keyframes;
  for (const MapSnapshot::Frame& k : map.keyframes) keyframes.Add(k.time_s, k.map_from_camera);
  EvaluationOptions eval;
  eval.align = "sim3";
  StatusOr<TrajectoryErrors> errors = EvaluateTrajectory(keyframes, ground_truth, eval);
  if (!errors.ok() || errors->ground_truth_length_m <= 0) return 1e9;
  return 100 * errors->ate.rmse / errors->ground_truth_length_m;
}

// A 6 m x 6 m loop (23 m round) at 1 m/s, 320x240 at 30 Hz, 900 frames: 1.3 laps. Without the
// revisit the second pass maps the corridor again (44 keyframes against 155 in the first lap)
// and the keyframes drift 3.3 % of the path (1.0 m).
TEST(LoopCloser, SecondPassOfACorridorLoopTracksTheFirstPassMap) {
  testing::CorridorLoop loop;
  loop.width = 320;
  loop.height = 240;
  loop.loop_length_m = 6;
  loop.loop_width_m = 6;
  loop.frames = 900;
  StatusOr<testing::MonoSequence> drive = testing::RenderCorridorLoop(loop);
  ASSERT_TRUE(drive.ok()) << drive.status().ToString();
  const int lap_end = testing::FirstLapEnd(drive->ground_truth);
  ASSERT_GT(lap_end, 600);
  ASSERT_LT(lap_end, 800);
  MonoSlam slam;
  ASSERT_TRUE(slam.Configure(drive->camera).ok());
  Trajectory estimate;
  int first_lap_keyframes = 0;
  for (size_t i = 0; i < drive->frames.size(); ++i) {
    StatusOr<std::shared_ptr<const MonoSlamResult>> r = slam.Process(drive->frames[i]);
    ASSERT_TRUE(r.ok());
    if ((*r)->tracked) estimate.Add((*r)->stamp.sensor_time_s, (*r)->map_from_camera);
    if (static_cast<int>(i) == lap_end) first_lap_keyframes = (*r)->stats.keyframes;
  }
  slam.Stop();
  const int keyframes = static_cast<int>(slam.Snapshot()->keyframes.size());
  const int second_lap_keyframes = keyframes - first_lap_keyframes;
  const double keyframe_ate = KeyFrameAtePercent(*slam.Snapshot(), drive->ground_truth);
  const IdleBundleTotals idle = slam.idle_bundle();
  std::cout << "  keyframes first lap = " << first_lap_keyframes
            << ", second = " << second_lap_keyframes << ", revisits = " << slam.revisits()
            << ", keyframe ATE = " << keyframe_ate << " % of path, lost = " << slam.lost_frames()
            << ", idle slices = " << idle.slices << "\n";
  EXPECT_GE(slam.revisits(), 1);
  EXPECT_LT(second_lap_keyframes, 0.1 * first_lap_keyframes);
  EXPECT_LT(keyframe_ate, 1.5);
  EXPECT_EQ(slam.lost_frames(), 0);
  EXPECT_GE(estimate.size(), drive->frames.size() - 10);
  EXPECT_GT(idle.slices, 0);  // The second pass left idle time, and it was used.
  EXPECT_GT(idle.keyframes_adjusted, 0);
}

}  // namespace
}  // namespace sightline
