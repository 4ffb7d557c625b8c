// Simulated arm approaches rendered in memory for the monocular SLAM tests.
#pragma once

#include <vector>

#include "core/common/camera.h"
#include "core/common/frame.h"
#include "core/common/status.h"
#include "core/common/trajectory.h"
#include "core/mono/mono_slam.h"

namespace sightline::testing {

// The panel scene's arm approach: frames, the camera's true poses, the camera.
struct PanelSequence {
  std::vector<MonoFrame> frames;
  Trajectory ground_truth;  // world_from_camera per frame.
  PinholeCamera camera;
};

// Renders the first `frames` frames of the panel scene's 150-frame arm approach (sideways
// amplitude `sideways_m`) in memory.
StatusOr<PanelSequence> RenderPanel(int frames = 150, double sideways_m = 0.12);

// Runs `slam` over `frames` and returns the tracked poses (map units).
Trajectory RunFrames(MonoSlam* slam, const std::vector<MonoFrame>& frames);

// Sim(3)-aligned ATE RMSE of an estimate [m]; infinity when it cannot be evaluated.
double Sim3AteRmse(const Trajectory& estimate, const Trajectory& ground_truth);

}  // namespace sightline::testing
