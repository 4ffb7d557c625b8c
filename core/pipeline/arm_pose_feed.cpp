#include "core/pipeline/arm_pose_feed.h"

#include <chrono>

#include "core/common/pose_board.h"

namespace sightline {

void ArmPoseFeed::Add(const ArmPoseMessage& pose) {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    if (!buffer_.Add(pose)) return;
    ++received_;
  }
  PoseBoard::Global().Post("arm", pose.stamp_s, pose.base_from_end_effector);
  arrived_.notify_all();
}

std::optional<Eigen::Isometry3d> ArmPoseFeed::At(double camera_stamp_s, bool* waited) {
  std::unique_lock<std::mutex> lock(mutex_);
  const ArmPoseStreamOptions& options = buffer_.options();
  const double arm_stamp_s = camera_stamp_s + options.clock_offset_s;
  const auto covered = [&] {
    const std::optional<double> newest = buffer_.newest_stamp();
    return newest && *newest >= arm_stamp_s - kStampResolutionS;
  };
  const bool wait = received_ > 0 && !covered();  // Before any pose: no arm to wait for.
  if (waited) *waited = wait;
  if (wait) {
    // Live-device guard by the host clock: the pose for this frame may still be on its way.
    arrived_.wait_for(lock, std::chrono::duration<double>(options.wait_s), covered);
  }
  return buffer_.At(camera_stamp_s);
}

int64_t ArmPoseFeed::received() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return received_;
}

}  // namespace sightline
