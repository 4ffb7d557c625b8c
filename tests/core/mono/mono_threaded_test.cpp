// Monocular SLAM with mapping on its own thread (mono.mapping.threaded): it stops cleanly, twice,
// and a second system dropped without Stop() joins its thread; accuracy as the inline mode's.
// Linked against the SLAM and the simulator only, for the thread sanitizer's build.
#include <gtest/gtest.h>

#include <iostream>

#include "core/common/timing.h"
#include "core/mono/mono_slam.h"
#include "tests/core/mono/mono_test_util.h"

namespace sightline {
namespace {

TEST(MonoThreaded, MappingStopsCleanlyWithComparableAccuracy) {
  StatusOr<testing::PanelSequence> panel = testing::RenderPanel();
  ASSERT_TRUE(panel.ok()) << panel.status().ToString();
  MonoSlamOptions options;
  options.mapping.threaded = true;
  TimingStats timing;
  MonoSlam slam(options);
  ASSERT_TRUE(slam.Configure(panel->camera, &timing).ok());
  const Trajectory estimate = testing::RunFrames(&slam, panel->frames);
  slam.Stop();
  slam.Stop();  // Idempotent.
  EXPECT_GE(estimate.size(), 130u);
  const double ate = testing::Sim3AteRmse(estimate, panel->ground_truth);
  std::cout << "  threaded_ate_rmse_m = " << ate
            << ", keyframes = " << slam.Snapshot()->keyframes.size() << "\n";
  EXPECT_LT(ate, 0.015);
  EXPECT_GT(slam.Snapshot()->keyframes.size(), 5u);
  EXPECT_GT(timing.Summary("mapping").count, 3u);
  // A second system in the same process, started and dropped without Stop().
  MonoSlam second(options);
  ASSERT_TRUE(second.Configure(panel->camera).ok());
  testing::RunFrames(&second, {panel->frames.begin(), panel->frames.begin() + 40});
}

}  // namespace
}  // namespace sightline
