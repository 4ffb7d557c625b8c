// The arm's poses as the button pipeline receives them live from the arm-target server
// (`arm_pose` lines, PROTOCOL.md): a thread-safe ArmPoseBuffer that the server's I/O thread fills
// and the pipeline reads at each camera frame's stamp. A frame newer than the newest pose waits
// a bounded time (button.arm_pose.wait_s, host clock: the live-device guard) for the pose that
// covers its stamp; what it gets depends only on the poses received, not on the machine's load.
// Every pose received is also posted on PoseBoard::Global()'s "arm" channel (arm clock,
// base_from_end_effector) for a simulated camera that follows the arm.
#pragma once

#include <Eigen/Geometry>
#include <condition_variable>
#include <cstdint>
#include <mutex>
#include <optional>

#include "core/button/arm_pose_stream.h"

namespace sightline {

// Thread-safe.
class ArmPoseFeed {
 public:
  explicit ArmPoseFeed(ArmPoseStreamOptions options) : buffer_(options) {}

  // The server's sink: buffers the pose, posts it on the board, wakes a waiting frame. Quick.
  void Add(const ArmPoseMessage& pose);
  // base_from_end_effector at camera time `camera_stamp_s` (ArmPoseBuffer::At, clock offset
  // applied). When no pose at or after that time (arm clock) has arrived yet, waits up to
  // wait_s for one, unless no pose at all has arrived (no arm streams: a run without an arm
  // does not slow down); *waited says whether it had to.
  std::optional<Eigen::Isometry3d> At(double camera_stamp_s, bool* waited = nullptr);
  int64_t received() const;

 private:
  mutable std::mutex mutex_;
  std::condition_variable arrived_;
  ArmPoseBuffer buffer_;  // Guarded by mutex_.
  int64_t received_ = 0;  // Guarded by mutex_.
};

}  // namespace sightline
