#include "core/sensors/sensor_stats.h"

namespace sightline {

const char* SensorStateName(SensorState state) {
  switch (state) {
    case SensorState::kClosed:
      return "closed";
    case SensorState::kStreaming:
      return "streaming";
    case SensorState::kDisconnected:
      return "disconnected";
  }
  return "unknown";
}

std::vector<std::pair<std::string, double>> SensorStatValues(const SensorStats& stats) {
  auto d = [](uint64_t v) { return static_cast<double>(v); };
  return {
      {"sensors/streaming", stats.state == SensorState::kStreaming ? 1.0 : 0.0},
      {"sensors/frames_received", d(stats.frames_received)},
      {"sensors/frames_grabbed", d(stats.frames_grabbed)},
      {"sensors/frames_dropped", d(stats.frames_dropped)},
      {"sensors/incomplete_frames", d(stats.incomplete_frames)},
      {"sensors/timeouts", d(stats.timeouts)},
      {"sensors/device_frames_lost", d(stats.device_frames_lost)},
      {"sensors/unpaired_frames", d(stats.unpaired_frames)},
      {"sensors/disconnects", d(stats.disconnects)},
      {"sensors/reconnects", d(stats.reconnects)},
      {"sensors/latency_ms", stats.last_latency_ms},
      {"sensors/mean_latency_ms", stats.mean_latency_ms},
      {"sensors/receive_rate_hz", stats.receive_rate_hz},
  };
}

}  // namespace sightline
