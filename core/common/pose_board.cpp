#include "core/common/pose_board.h"

namespace sightline {

PoseBoard& PoseBoard::Global() {
  static PoseBoard* board = new PoseBoard();  // Never destroyed: posters may outlive main().
  return *board;
}

void PoseBoard::Post(const std::string& channel, double stamp_s, const Eigen::Isometry3d& pose) {
  std::lock_guard<std::mutex> lock(mutex_);
  BoardPose& entry = poses_[channel];
  entry.stamp_s = stamp_s;
  entry.pose = pose;
  ++entry.count;
}

std::optional<BoardPose> PoseBoard::Latest(const std::string& channel) const {
  std::lock_guard<std::mutex> lock(mutex_);
  auto it = poses_.find(channel);
  if (it == poses_.end()) return std::nullopt;
  return it->second;
}

void PoseBoard::Clear(const std::string& channel) {
  std::lock_guard<std::mutex> lock(mutex_);
  poses_.erase(channel);
}

}  // namespace sightline
