// A process-wide board of the newest pose per named channel, for a device that must follow
// another one live in the same process: the button pipeline posts the arm poses it receives on
// "arm" (base_from_end_effector, arm clock), and the simulated eye-in-hand camera (sim://panel)
// renders from the newest one. Thread-safe. A reader sees only the newest pose and its stamp;
// nothing is queued.
#pragma once

#include <Eigen/Geometry>
#include <cstdint>
#include <map>
#include <mutex>
#include <optional>
#include <string>

namespace sightline {

struct BoardPose {
  double stamp_s = 0;  // On the poster's clock.
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  int64_t count = 0;  // Poses posted on the channel so far (this one included).
};

class PoseBoard {
 public:
  // The one board of the process.
  static PoseBoard& Global();

  // Replaces the channel's pose.
  void Post(const std::string& channel, double stamp_s, const Eigen::Isometry3d& pose);
  // The channel's newest pose; nullopt when nothing was posted since the last Clear.
  std::optional<BoardPose> Latest(const std::string& channel) const;
  void Clear(const std::string& channel);

 private:
  mutable std::mutex mutex_;
  std::map<std::string, BoardPose> poses_;
};

}  // namespace sightline
