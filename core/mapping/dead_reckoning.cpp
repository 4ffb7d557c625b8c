#include "core/mapping/dead_reckoning.h"

#include <cmath>

namespace sightline {

OdometryIncrement DeadReckoning::Update(const std::optional<Pose2d>& world_from_base) {
  OdometryIncrement step;
  if (!world_from_base) {
    last_.reset();
    return step;
  }
  if (last_) {
    const double c = std::cos(last_->heading_rad), s = std::sin(last_->heading_rad);
    const Eigen::Vector2d delta = world_from_base->position() - last_->position();
    step.translation_in_previous_base =
        Eigen::Vector2d(c * delta.x() + s * delta.y(), -s * delta.x() + c * delta.y());
    step.heading_change_rad = WrapAngle(world_from_base->heading_rad - last_->heading_rad);
    step.valid = true;
  }
  last_ = world_from_base;
  return step;
}

}  // namespace sightline
