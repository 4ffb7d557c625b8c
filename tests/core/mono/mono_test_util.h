// Simulated arm approaches and corridor drives rendered in memory for the monocular SLAM tests
// and benchmarks.
#pragma once

#include <vector>

#include "core/common/camera.h"
#include "core/common/frame.h"
#include "core/common/status.h"
#include "core/common/trajectory.h"
#include "core/mono/mono_slam.h"
#include "core/sim/simulation_options.h"

namespace sightline::testing {

// Rendered frames, the camera's true poses, the camera.
struct MonoSequence {
  std::vector<MonoFrame> frames;
  Trajectory ground_truth;  // world_from_camera per frame.
  PinholeCamera camera;
};
using PanelSequence = MonoSequence;  // The panel scene's arm approach.

// Renders the first `frames` frames of the panel scene's 150-frame arm approach (sideways
// amplitude `sideways_m`) in memory.
StatusOr<PanelSequence> RenderPanel(int frames = 150, double sideways_m = 0.12);

// A robot driving the corridor scene's loop more than once, seen by the mono camera.
struct CorridorLoop {
  int width = 640, height = 480;  // Image size (the focal length scales with the width).
  double rate_hz = 30;
  double speed_mps = 1.0;
  double loop_length_m = 16, loop_width_m = 10;  // The scene's defaults (about 51 m round).
  int frames = 2000;
};

// Options of the simulator for `loop` (corridor scene, mono camera only).
sim::SimulationOptions CorridorLoopOptions(const CorridorLoop& loop);

// The first frame back at frame 0's place (the end of the first lap), from the ground truth.
int FirstLapEnd(const Trajectory& ground_truth);

// Renders `loop` in memory: frames, the camera's true poses, the camera.
StatusOr<MonoSequence> RenderCorridorLoop(const CorridorLoop& loop);

// Runs `slam` over `frames` and returns the tracked poses (map units).
Trajectory RunFrames(MonoSlam* slam, const std::vector<MonoFrame>& frames);

// Sim(3)-aligned ATE RMSE of an estimate [m]; infinity when it cannot be evaluated.
double Sim3AteRmse(const Trajectory& estimate, const Trajectory& ground_truth);

}  // namespace sightline::testing
