#include "core/pipeline/pipeline.h"

namespace sightline {

const StatisticInfo* FindStatistic(const StatisticTable& table, const std::string& key) {
  for (const StatisticInfo& info : table) {
    if (info.key == key) return &info;
  }
  return nullptr;
}

std::optional<double> PipelineResult::Stat(const std::string& key) const {
  for (const auto& [name, value] : stats) {
    if (name == key) return value;
  }
  return std::nullopt;
}

PipelineSource PipelineSource::From(const Source& source) {
  PipelineSource out;
  out.info = source.info();
  if (const Trajectory* gt = source.ground_truth(); gt != nullptr && !gt->empty()) {
    out.ground_truth = std::make_shared<const Trajectory>(*gt);
  }
  if (const Trajectory* odometry = source.odometry(); odometry != nullptr && !odometry->empty()) {
    out.odometry = std::make_shared<const Trajectory>(*odometry);
  }
  if (const Trajectory* arm = source.arm_poses(); arm != nullptr && !arm->empty()) {
    out.arm_poses = std::make_shared<const Trajectory>(*arm);
  }
  if (out.info.live) {
    out.live_odometry = [&source] { return source.odometry(); };
    out.live_arm_poses = [&source] { return source.arm_poses(); };
  }
  return out;
}

}  // namespace sightline
