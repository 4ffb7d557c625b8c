#include "tests/core/button/panel_sim_util.h"

#include <gtest/gtest.h>

#include "core/sim/simulator.h"

namespace sightline::testing {

Eigen::Vector2d PanelApproach::Project(int frame, int button) const {
  const Eigen::Vector3d x = frames[frame].world_from_camera.inverse() * buttons[button].center;
  return camera.Project(x);
}

double PanelApproach::RadiusPx(int frame, int button) const {
  const Eigen::Vector3d x = frames[frame].world_from_camera.inverse() * buttons[button].center;
  return camera.fx * buttons[button].radius_m / x.z();
}

PanelApproach RenderPanelApproach(int frames, int step, int seed) {
  PanelApproach out;
  sim::SimulationOptions options = sim::SimulationOptions::ForScene("panel");
  options.seed = seed;
  auto simulator = sim::Simulator::Create(options);
  if (!simulator.ok()) {
    ADD_FAILURE() << simulator.status().ToString();
    return out;
  }
  out.camera = simulator->mono_camera();
  out.buttons = simulator->scene().buttons;
  out.target_button = simulator->scene().hints.target_button;
  out.world_from_base = simulator->motion().world_from_arm_base;
  const int n = frames > 0 ? std::min(frames, simulator->frames()) : simulator->frames();
  for (int i = 0; i < n; i += step) {
    sim::SimulatedMono mono;
    const Status s = simulator->RenderMono(i, &mono);
    if (!s.ok()) {
      ADD_FAILURE() << s.ToString();
      return out;
    }
    out.frames.push_back({mono.image, mono.view.depth_m, mono.world_from_camera});
  }
  return out;
}

}  // namespace sightline::testing
