// The simulated button panel approach (camera in the arm's hand) rendered in memory, with the
// true button centres projected into every frame.
#pragma once

#include <Eigen/Geometry>
#include <opencv2/core.hpp>
#include <vector>

#include "core/common/camera.h"
#include "core/sim/scene.h"

namespace sightline::testing {

struct PanelFrame {
  cv::Mat image;    // BGR with the mono sensor's noise.
  cv::Mat depth_m;  // Exact z depth (NaN = nothing).
  Eigen::Isometry3d world_from_camera = Eigen::Isometry3d::Identity();
};

struct PanelApproach {
  PinholeCamera camera;
  std::vector<sim::ButtonSpec> buttons;  // Map frame.
  int target_button = -1;
  std::vector<PanelFrame> frames;
  Eigen::Isometry3d world_from_base = Eigen::Isometry3d::Identity();

  // True pixel of a button's centre in a frame.
  Eigen::Vector2d Project(int frame, int button) const;
  // Apparent radius of a button in a frame [px].
  double RadiusPx(int frame, int button) const;
};

// Renders `frames` frames (0 = all) of the default panel scene with simulator seed `seed`,
// every `step`-th frame. Aborts the test (ADD_FAILURE + empty result) when the simulator fails.
PanelApproach RenderPanelApproach(int frames = 0, int step = 1, int seed = 1);

}  // namespace sightline::testing
