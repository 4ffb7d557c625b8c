// End-to-end accuracy on the simulator's corridor: a 100 m loop (30 m x 20 m, four 90 deg left
// turns) driven at 1 m/s, 320x240 Kinect depth with the "kinect" noise profile (Khoshelham and
// Elberink: sigma_z = 1.425e-3 z^2, disparity quantised to 1/8 px), two walking people with
// ground-truth boxes, boxes, bins and recessed doors along the walls.
//
// Wheel odometry drifts 2 deg/m in heading (the figure the mapping targets). Its distance is
// unbiased (scale_error = 0, the simulator's default distance noise kept): translation comes from
// dead reckoning alone (seed 000), so a distance scale error bends the stitched map whatever the
// heading; OdometryScaleErrorBendsTheMap shows that separately.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "tests/core/mapping/corridor_run.h"

namespace sightline {
namespace {

using testing::CorridorScore;

constexpr double kMetres = 100.0;
constexpr double kRateHz = 5.0;  // 0.2 m between frames at 1 m/s.
constexpr double kSpeedMps = 1.0;
constexpr double kDriftDegPerM = 2.0;

// One run of the corridor with three mapping configurations (the Manhattan correction, dead
// reckoning alone, split-and-merge instead of RANSAC); all checks in one test because the run
// takes a few seconds and ctest starts every test in its own process.
TEST(CorridorAccuracy, OneHundredMetreLoopWithFourTurns) {
  sim::SimulationOptions simulation =
      testing::CorridorSimulation(kMetres, kRateHz, kSpeedMps, kDriftDegPerM);
  simulation.odometry.scale_error = 0.0;
  MappingOptions manhattan_options;
  MappingOptions dead_reckoning_options = manhattan_options;
  dead_reckoning_options.rotation.enabled = false;
  MappingOptions split_options = manhattan_options;
  split_options.extractor = "split_and_merge";
  StatusOr<std::vector<CorridorScore>> run =
      testing::RunCorridor(simulation, {manhattan_options, dead_reckoning_options, split_options});
  ASSERT_TRUE(run.ok()) << run.status().ToString();
  const char* names[] = {"manhattan", "dead reckoning", "split-and-merge"};
  for (size_t i = 0; i < run->size(); ++i) {
    const CorridorScore& s = (*run)[i];
    std::printf(
        "[ corridor ] %-16s heading mean %.3f max %.3f deg | wall angle median %.3f deg "
        "(%zu lines) | walls found %d / %d | map IoU %.3f (walls only %.3f) | "
        "resets %d\n",
        names[i], s.heading.mean_deg, s.heading.max_deg, s.wall_angle_error_deg_median,
        s.wall_angle_errors_deg.size(), s.found_walls, s.visible_walls, s.map_all_obstacles.iou,
        s.map.iou, s.resets);
  }
  const CorridorScore& manhattan = run->at(0);
  const CorridorScore& dead_reckoning = run->at(1);
  const CorridorScore& split = run->at(2);
  ASSERT_EQ(manhattan.frames, static_cast<int>(kMetres / kSpeedMps * kRateHz) + 1);
  {
    SCOPED_TRACE("the Manhattan correction keeps the heading within 1 deg");
    EXPECT_LT(manhattan.heading.max_deg, 1.0);
    EXPECT_LT(manhattan.heading.mean_deg, 0.3);
    EXPECT_EQ(manhattan.resets, 0);
  }
  {
    SCOPED_TRACE("without it the heading error grows");
    // 2 deg/m over 100 m: the dead-reckoned heading drifts far away (wrapped to 180 deg).
    EXPECT_GT(dead_reckoning.heading.max_deg, 90.0);
    EXPECT_GT(dead_reckoning.heading.mean_deg, 20 * manhattan.heading.mean_deg);
    const std::vector<double>& e = dead_reckoning.heading.error_deg;
    double first = 0, last = 0;
    for (size_t i = 0; i < e.size() / 4; ++i) {
      first += e[i];
      last += e[e.size() - 1 - i];
    }
    EXPECT_GT(last, 4 * first);  // The last quarter is worse than the first.
  }
  {
    SCOPED_TRACE("every visible wall is found");
    // A wall is visible in a frame when at least 1 m of it and 20 % of the scan's rays reach
    // it past every obstacle and person (corridor_run.h). A handful of about 900 such (frame,
    // wall) pairs are missed, at corners where a wall barely passes the 20 % (the seed's
    // ratio_min).
    ASSERT_GT(manhattan.visible_walls, 500);
    EXPECT_GE(static_cast<double>(manhattan.found_walls) / manhattan.visible_walls, 0.99)
        << manhattan.found_walls << " of " << manhattan.visible_walls
        << "; first miss: " << (manhattan.missed.empty() ? "" : manhattan.missed.front());
  }
  {
    SCOPED_TRACE("wall angles");
    ASSERT_GT(manhattan.wall_angle_errors_deg.size(), 500u);
    EXPECT_LT(manhattan.wall_angle_error_deg_median, 0.5);
  }
  {
    SCOPED_TRACE("the stitched map matches the true map");
    // Map cells within 2 cells (10 cm) of a true surface count as matching (CompareMapWithWalls):
    // every static obstacle a scan sees (walls, recessed doors, boxes, bins) ...
    EXPECT_GT(manhattan.map_all_obstacles.iou, 0.8);
    // ... and, stricter, the wall faces of walls.csv alone (boxes and doors count against).
    EXPECT_GT(manhattan.map.iou, 0.7);
    EXPECT_LT(dead_reckoning.map_all_obstacles.iou, 0.3);
  }
  {
    SCOPED_TRACE("split-and-merge, for comparison");
    // No refinement step: lines merging a wall with a recessed door stay a little tilted.
    EXPECT_GE(static_cast<double>(split.found_walls) / split.visible_walls, 0.95);
    EXPECT_LT(split.wall_angle_error_deg_median, 1.0);
  }
  {
    SCOPED_TRACE("per-frame time (gross regressions only; bench_mapping measures it)");
    std::vector<double> ms = manhattan.frame_ms;
    std::nth_element(ms.begin(), ms.begin() + ms.size() / 2, ms.end());
    EXPECT_LT(ms[ms.size() / 2], 20.0);
  }
}

// The same loop with the people found in the depth image (mapping.people.source=depth) instead
// of the simulator's boxes, on three seeds (the walking people differ): the people (legs, torso,
// arms, head) 1 to 5.5 m away are found, few other things are taken for a person (the ends of
// walls and the door recesses whose tops are out of view), and the map is as good as with the
// true boxes.
TEST(CorridorPeople, DepthDetectorFindsThePeopleAndKeepsTheMap) {
  int visible = 0, found = 0, detections = 0, false_detections = 0;
  int hog_found = 0, hog_detections = 0, hog_false = 0;
  for (int seed : {1, 2, 3}) {
    sim::SimulationOptions simulation =
        testing::CorridorSimulation(kMetres, kRateHz, kSpeedMps, kDriftDegPerM, seed);
    simulation.odometry.scale_error = 0.0;
    MappingOptions truth;
    truth.people.source = "ground_truth";
    MappingOptions depth = truth;
    depth.people.source = "depth";
    depth.people.depth_hog_check = false;
    MappingOptions checked = depth;
    checked.people.depth_hog_check = true;
    StatusOr<std::vector<CorridorScore>> run =
        testing::RunCorridor(simulation, {truth, depth, checked});
    ASSERT_TRUE(run.ok()) << run.status().ToString();
    const CorridorScore& with_truth = run->at(0);
    const CorridorScore& with_depth = run->at(1);
    const CorridorScore& with_hog = run->at(2);
    std::printf(
        "[ corridor people ] seed %d: depth found %d of %d people in view, %d detections (%d "
        "false) | map IoU %.3f (walls only %.3f), with the true boxes %.3f (%.3f) | depth+hog "
        "found %d, %d detections (%d false), map IoU %.3f\n",
        seed, with_depth.people_found, with_depth.people_visible, with_depth.people_detections,
        with_depth.people_false, with_depth.map_all_obstacles.iou, with_depth.map.iou,
        with_truth.map_all_obstacles.iou, with_truth.map.iou, with_hog.people_found,
        with_hog.people_detections, with_hog.people_false, with_hog.map_all_obstacles.iou);
    for (const std::string& miss : with_depth.people_missed)
      std::printf("  missed %s\n", miss.c_str());
    EXPECT_GE(with_depth.map_all_obstacles.iou, with_truth.map_all_obstacles.iou - 0.03);
    EXPECT_GE(with_depth.map.iou, with_truth.map.iou - 0.03);
    EXPECT_GE(with_hog.map_all_obstacles.iou, with_truth.map_all_obstacles.iou - 0.03);
    visible += with_depth.people_visible;
    found += with_depth.people_found;
    detections += with_depth.people_detections;
    false_detections += with_depth.people_false;
    hog_found += with_hog.people_found;
    hog_detections += with_hog.people_detections;
    hog_false += with_hog.people_false;
  }
  ASSERT_GT(visible, 100);
  EXPECT_GE(static_cast<double>(found) / visible, 0.9) << found << " of " << visible;
  EXPECT_LE(false_detections, 0.2 * detections) << false_detections << " of " << detections;
  // HOG on the colour as a second cue, asked about the whole body where the head is in view: it
  // keeps the recall and removes most false detections (the ends of walls and door recesses).
  EXPECT_GE(static_cast<double>(hog_found) / visible, 0.9) << hog_found << " of " << visible;
  EXPECT_LE(hog_false, 0.08 * hog_detections) << hog_false << " of " << hog_detections;
  EXPECT_LT(hog_false, false_detections / 2);
}

TEST(CorridorOdometry, OdometryScaleErrorBendsTheMap) {
  // The simulator's default wheel odometry is 1 % long. Over the first 30 m corridor that is
  // 0.3 m, which becomes a lateral offset of the second corridor: no heading correction can
  // remove it, and the map matches the truth only within that offset. A short 40 m drive keeps
  // this test quick.
  sim::SimulationOptions simulation = testing::CorridorSimulation(40.0, 5.0, 1.0, 2.0);
  simulation.odometry.scale_error = 0.01;
  StatusOr<std::vector<CorridorScore>> run = testing::RunCorridor(simulation, {MappingOptions()});
  ASSERT_TRUE(run.ok()) << run.status().ToString();
  EXPECT_LT(run->at(0).heading.max_deg, 1.0);  // The heading is still right.
  std::printf(
      "[ corridor ] 40 m with 1 %% odometry scale error: heading max %.3f deg, map IoU "
      "%.3f\n",
      run->at(0).heading.max_deg, run->at(0).map_all_obstacles.iou);
}

}  // namespace
}  // namespace sightline
