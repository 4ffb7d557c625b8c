// Per-frame ground truth seen by a camera: where each button appears and which pixels each
// person covers (from the rendered object buffer, so occlusion is exact).
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <vector>

#include "core/common/camera.h"
#include "core/sim/renderer.h"
#include "core/sim/scene.h"

namespace sightline::sim {

// A button's centre in one image.
struct ButtonObservation {
  int frame = 0;
  int button = 0;                                             // ButtonSpec::id.
  Eigen::Vector2d pixel = Eigen::Vector2d::Zero();            // Projection (u, v), pixels.
  Eigen::Vector3d center_in_world = Eigen::Vector3d::Zero();  // Map frame, metres.
  bool visible = false;  // In front of the camera, inside the image and not occluded.
};

// A person's image bounding box in one image.
struct PersonObservation {
  int frame = 0;
  int person = 0;        // WalkingPerson::id.
  int u0 = 0, v0 = 0;    // Inclusive top-left pixel.
  int u1 = -1, v1 = -1;  // Inclusive bottom-right pixel.
  int pixels = 0;        // Pixels showing the person (0 = not visible).
};

// Projects every button centre with `camera` at `world_from_camera`; visible when the pixel
// nearest the projection shows the button in `view` (rendered from the same pose).
std::vector<ButtonObservation> ObserveButtons(const Scene& scene, const PinholeCamera& camera,
                                              const Eigen::Isometry3d& world_from_camera,
                                              const RenderedView& view, int frame);

// The bounding box of every person's pixels in `view`; people out of view have pixels = 0.
std::vector<PersonObservation> ObservePeople(const Scene& scene, const RenderedView& view,
                                             int frame);

}  // namespace sightline::sim
