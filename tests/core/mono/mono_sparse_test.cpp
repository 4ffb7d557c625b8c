// Sparse, large-motion input (keyframe-rate sequences): a handheld camera circling objects in
// the simulator's terrain, every 15th and 20th frame of 30 Hz (7.5 and 10 deg around the
// centre between frames), and kitti_clip1's left images every 2nd to 4th frame (2.4-4.8 m
// between frames).
// Each must initialise within a few frames, track nearly every frame and keep the Sim(3) ATE
// within a small share of the path.
#include <gtest/gtest.h>

#include <iostream>
#include <map>

#include "core/mono/features.h"
#include "core/mono/two_view_initializer.h"
#include "core/pipeline/mono_slam_pipeline.h"
#include "core/sim/simulator.h"
#include "tests/core/mono/mono_test_util.h"
#include "tests/support/test_data.h"

namespace sightline {
namespace {

struct SparseFigures {
  int init_frame = -1;  // Index among the frames processed of the first tracked one.
  double tracked_fraction = 0;
  double ate_pct_of_path = 1e9;
};

// Every `stride`-th frame of the 400-frame orbit at 30 Hz, rendered in memory.
StatusOr<testing::PanelSequence> RenderOrbit(int stride) {
  sim::SimulationOptions options = sim::SimulationOptions::ForScene("terrain");
  options.frames = 400;
  options.sensors = "mono";
  options.motion.kind = "orbit";
  StatusOr<sim::Simulator> simulator = sim::Simulator::Create(options);
  if (!simulator.ok()) return simulator.status();
  testing::PanelSequence out;
  out.camera = simulator->mono_camera();
  for (int i = 0; i < options.frames; i += stride) {
    sim::SimulatedMono mono;
    SIGHTLINE_RETURN_IF_ERROR(simulator->RenderMono(i, &mono));
    MonoFrame frame;
    frame.stamp.sequence_id = i;
    frame.stamp.sensor_time_s = simulator->TimeOf(i);
    frame.image = mono.image;
    out.frames.push_back(frame);
    out.ground_truth.Add(frame.stamp.sensor_time_s, mono.world_from_camera);
  }
  return out;
}

SparseFigures RunOrbit(int stride) {
  SparseFigures f;
  StatusOr<testing::PanelSequence> orbit = RenderOrbit(stride);
  EXPECT_TRUE(orbit.ok()) << orbit.status().ToString();
  if (!orbit.ok()) return f;
  MonoSlam slam;
  EXPECT_TRUE(slam.Configure(orbit->camera).ok());
  Trajectory estimate;
  int tracked = 0;
  for (size_t i = 0; i < orbit->frames.size(); ++i) {
    StatusOr<std::shared_ptr<const MonoSlamResult>> r = slam.Process(orbit->frames[i]);
    if (!r.ok() || !(*r)->tracked) continue;
    if (f.init_frame < 0) f.init_frame = static_cast<int>(i);
    ++tracked;
    estimate.Add((*r)->stamp.sensor_time_s, (*r)->map_from_camera);
  }
  slam.Stop();
  f.tracked_fraction = static_cast<double>(tracked) / orbit->frames.size();
  double path = 0;
  const auto& poses = orbit->ground_truth.poses();
  for (size_t i = 1; i < poses.size(); ++i) {
    path +=
        (poses[i].world_from_sensor.translation() - poses[i - 1].world_from_sensor.translation())
            .norm();
  }
  f.ate_pct_of_path = 100.0 * testing::Sim3AteRmse(estimate, orbit->ground_truth) / path;
  std::cout << "  orbit every " << stride << "th frame: " << orbit->frames.size()
            << " frames, initialised at " << f.init_frame << ", tracked "
            << 100 * f.tracked_fraction << " %, ATE " << f.ate_pct_of_path << " % of " << path
            << " m\n";
  return f;
}

TEST(MonoSparse, OrbitEveryFifteenthFrameInitialisesAtOnceAndTracksThrough) {
  // Measured: initialised on the second frame, 26 of 27 tracked, ATE 0.16 % of the path.
  const SparseFigures f = RunOrbit(15);
  EXPECT_LE(f.init_frame, 2);
  EXPECT_GE(f.init_frame, 0);
  EXPECT_GE(f.tracked_fraction, 0.9);
  EXPECT_LT(f.ate_pct_of_path, 0.5);
}

TEST(MonoSparse, OrbitEveryTwentiethFrameInitialisesAtOnceAndTracksThrough) {
  // Measured: initialised on the second frame, 19 of 20 tracked, ATE 0.09 % of the path.
  const SparseFigures f = RunOrbit(20);
  EXPECT_LE(f.init_frame, 2);
  EXPECT_GE(f.init_frame, 0);
  EXPECT_GE(f.tracked_fraction, 0.9);
  EXPECT_LT(f.ate_pct_of_path, 0.5);
}

TEST(MonoSparse, InitialisationTriesEveryCandidateFirstFrameOldestFirst) {
  // Candidates: the orbit's first frame, then an unrelated view (the panel) as the newest. The
  // orbit 7.5 deg on initialises against the oldest; a ring of one has only the panel left.
  StatusOr<testing::PanelSequence> orbit = RenderOrbit(15);
  ASSERT_TRUE(orbit.ok()) << orbit.status().ToString();
  StatusOr<testing::PanelSequence> panel = testing::RenderPanel(1);
  ASSERT_TRUE(panel.ok()) << panel.status().ToString();
  MonoSlamOptions options;
  const FeatureExtractor extractor(options.features, orbit->camera);
  const FrameFeatures first = extractor.Extract(orbit->frames[0].image);
  const FrameFeatures other = extractor.Extract(panel->frames[0].image);
  const FrameFeatures current = extractor.Extract(orbit->frames[1].image);
  FrameStamp other_stamp;
  other_stamp.sequence_id = 1000;
  for (int ring : {2, 1}) {
    SCOPED_TRACE("ring of " + std::to_string(ring));
    options.init.reference_frames = ring;
    TwoViewInitializer init(options.init, orbit->camera, options.features.scale_factor);
    init.SetFirst(first, orbit->frames[0].stamp, 0);
    init.AddReference(other, other_stamp, 1);
    std::string why;
    std::optional<TwoViewResult> result = init.TryInitialize(current, &why);
    EXPECT_LT(init.newest_matches(), options.init.min_matches);  // The panel matches nothing.
    if (ring == 2) {
      ASSERT_TRUE(result) << why;
      EXPECT_EQ(init.reference().stamp.sequence_id, 0);
      EXPECT_GT(result->points.size(), 200u);
    } else {
      EXPECT_FALSE(result);
      EXPECT_NE(why.find("matches with the first frame"), std::string::npos) << why;
    }
  }
}

// kitti_clip1's left images, every `stride`-th frame, with the ground-truth scale.
SparseFigures RunKitti(const std::string& path, int stride, size_t expected_frames) {
  SparseFigures f;
  MonoSlamRunOptions run_options;
  run_options.metric_source = "ground_truth";
  run_options.stride = stride;
  StatusOr<MonoSlamRun> run = RunMonoSlam(path, {}, run_options);
  EXPECT_TRUE(run.ok()) << run.status().ToString();
  if (!run.ok()) return f;
  EXPECT_EQ(run->frames.size(), expected_frames);
  int tracked = 0;
  for (size_t i = 0; i < run->frames.size(); ++i) {
    if (!run->frames[i].tracked) continue;
    if (f.init_frame < 0) f.init_frame = static_cast<int>(i);
    ++tracked;
  }
  f.tracked_fraction = static_cast<double>(tracked) / static_cast<double>(run->frames.size());
  std::vector<std::string> notes;
  for (const auto& [key, value] : MonoSlamAccuracy(*run, 0.02, &notes)) {
    if (key == "ate_rmse_pct_of_path") f.ate_pct_of_path = value;
  }
  std::cout << "  kitti every " << stride << " frames: initialised at " << f.init_frame
            << ", tracked " << tracked << " of " << run->frames.size() << ", ATE "
            << f.ate_pct_of_path << " % of the path\n";
  return f;
}

// Every 2nd, 3rd and 4th frame (2.4, 3.6 and 4.8 m between frames; 0.2 s, 0.3 s and 0.4 s with
// the stamps the KITTI reader synthesises, i / 10 Hz). Measured: initialised on the second
// frame, 25 of 26, 16 of 17 and 12 of 13 tracked, ATE 0.63, 0.61 and 0.38 % of the path. Every
// 2nd frame lies on the low-rate threshold (mono.tracking.low_rate_interval_s, 0.2 s): with
// the step taken frame by frame the stamps' rounding turned the low-rate keyframe rules on and
// off, and 8 of 26 frames were tracked.
TEST(MonoSparse, KittiEverySecondToFourthFrameTracksWithinTwoPercent) {
  SIGHTLINE_REQUIRE_DATA(path, "kitti_clip1");
  for (const auto& [stride, frames] : {std::pair<int, size_t>{2, 26}, {3, 17}, {4, 13}}) {
    SCOPED_TRACE("every " + std::to_string(stride) + " frames");
    const SparseFigures f = RunKitti(path, stride, frames);
    EXPECT_LE(f.init_frame, 2);
    EXPECT_GE(f.init_frame, 0);
    EXPECT_GE(f.tracked_fraction, 0.9);
    EXPECT_LT(f.ate_pct_of_path, 2.0);
  }
}

TEST(MonoSparse, KittiEveryFifthFrameInitialisesOnTheSecondFrameByGuidedMatching) {
  // 6 m between frames: the descriptor matches with the first frame alone are too few (85);
  // the essential matrix fitted to them guides a second matching that initialises. Tracking
  // after that is not yet reliable at this rate (see docs/mono-slam.md), so only the
  // initialisation is asserted.
  SIGHTLINE_REQUIRE_DATA(path, "kitti_clip1");
  MonoSlamRunOptions run_options;
  run_options.metric_source = "ground_truth";
  run_options.stride = 5;
  StatusOr<MonoSlamRun> run = RunMonoSlam(path, {}, run_options);
  ASSERT_TRUE(run.ok()) << run.status().ToString();
  ASSERT_EQ(run->frames.size(), 11u);
  ASSERT_FALSE(run->frames[0].tracked);
  // Measured: initialised on the second frame (the sixth before guided matching).
  ASSERT_TRUE(run->frames[1].tracked) << run->frames[1].stats.status;
  EXPECT_NE(run->frames[1].stats.status.find("guided"), std::string::npos)
      << run->frames[1].stats.status;
}

}  // namespace
}  // namespace sightline
