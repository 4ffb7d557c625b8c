#include "core/sensors/live_source.h"

namespace sightline {

bool LiveSourceOptions::IsValid(std::string* error) const {
  auto fail = [&](const std::string& m) {
    if (error) *error = m;
    return false;
  };
  if (queue_capacity < 1) return fail("queue_capacity must be >= 1");
  if (grab_timeout_ms < 1) return fail("grab_timeout_ms must be >= 1");
  if (stall_timeout_ms < 0) return fail("stall_timeout_ms must be >= 0 (0 = never)");
  if (reconnect_interval_ms < 10) return fail("reconnect_interval_ms must be >= 10");
  return true;
}

OptionTable<LiveSourceOptions> LiveSourceOptions::Describe() {
  return OptionTable<LiveSourceOptions>("")
      .Int("queue_capacity", &LiveSourceOptions::queue_capacity, "frames", 1, 64, 1,
           "Frames buffered between the capture thread and the consumer; when full the oldest "
           "is dropped, so latency stays bounded.")
      .Bool("latest_only", &LiveSourceOptions::latest_only,
            "Grab() returns the newest frame and skips older queued ones (views); off hands out "
            "every queued frame in order (recording).")
      .Int("grab_timeout_ms", &LiveSourceOptions::grab_timeout_ms, "ms", 1, 60000, 100,
           "How long Grab() waits for a frame before reporting the device as unavailable.")
      .Int("stall_timeout_ms", &LiveSourceOptions::stall_timeout_ms, "ms", 0, 600000, 500,
           "A streaming device that delivers nothing for this long is treated as lost and "
           "reopened; 0 never does (e.g. waiting for rare hardware triggers).")
      .Int("reconnect_interval_ms", &LiveSourceOptions::reconnect_interval_ms, "ms", 10, 60000, 100,
           "Pause between attempts to reopen a lost device.");
}

}  // namespace sightline
