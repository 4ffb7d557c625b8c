#include "core/sim/observations.h"

#include <algorithm>
#include <cmath>

namespace sightline::sim {

std::vector<ButtonObservation> ObserveButtons(const Scene& scene, const PinholeCamera& camera,
                                              const Eigen::Isometry3d& world_from_camera,
                                              const RenderedView& view, int frame) {
  std::vector<ButtonObservation> out;
  const Eigen::Isometry3d camera_from_world = world_from_camera.inverse();
  for (const ButtonSpec& button : scene.buttons) {
    ButtonObservation o;
    o.frame = frame;
    o.button = button.id;
    o.center_in_world = button.center;
    const Eigen::Vector3d x = camera_from_world * button.center;
    if (x.z() > 0) {
      o.pixel = camera.Project(x);
      const int u = static_cast<int>(std::lround(o.pixel.x()));
      const int v = static_cast<int>(std::lround(o.pixel.y()));
      o.visible = u >= 0 && v >= 0 && u < view.object.cols && v < view.object.rows &&
                  view.object.at<int32_t>(v, u) == button.object;
    } else {
      o.pixel = Eigen::Vector2d::Constant(std::nan(""));
    }
    out.push_back(o);
  }
  return out;
}

std::vector<PersonObservation> ObservePeople(const Scene& scene, const RenderedView& view,
                                             int frame) {
  std::vector<PersonObservation> out;
  if (scene.people.empty()) return out;
  std::vector<int> slot_of_object(scene.objects().size(), -1);
  for (size_t i = 0; i < scene.people.size(); ++i) {
    const int object = scene.people[i].object;
    if (object >= 0 && object < static_cast<int>(slot_of_object.size())) {
      slot_of_object[object] = static_cast<int>(i);
    }
    PersonObservation o;
    o.frame = frame;
    o.person = scene.people[i].id;
    o.u0 = view.object.cols, o.v0 = view.object.rows;
    out.push_back(o);
  }
  for (int v = 0; v < view.object.rows; ++v) {
    const int32_t* row = view.object.ptr<int32_t>(v);
    for (int u = 0; u < view.object.cols; ++u) {
      const int32_t object = row[u];
      if (object < 0 || object >= static_cast<int32_t>(slot_of_object.size())) continue;
      const int slot = slot_of_object[object];
      if (slot < 0) continue;
      PersonObservation& o = out[slot];
      o.u0 = std::min(o.u0, u), o.u1 = std::max(o.u1, u);
      o.v0 = std::min(o.v0, v), o.v1 = std::max(o.v1, v);
      ++o.pixels;
    }
  }
  for (PersonObservation& o : out) {
    if (o.pixels == 0) o.u0 = o.v0 = 0, o.u1 = o.v1 = -1;
  }
  return out;
}

}  // namespace sightline::sim
