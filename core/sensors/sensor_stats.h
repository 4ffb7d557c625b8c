// Live-sensor health: connection state and counters that the GUI plots and the CLI prints.
#pragma once

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace sightline {

// Where a live source stands with its device.
enum class SensorState {
  kClosed,        // Not opened, or closed.
  kStreaming,     // Connected; frames arrive.
  kDisconnected,  // The device went away or stopped delivering; reconnect attempts are running.
};
// "closed", "streaming", "disconnected".
const char* SensorStateName(SensorState state);

// A snapshot of a live source's counters, taken under the source's lock (see LiveSource::stats()).
struct SensorStats {
  SensorState state = SensorState::kClosed;
  std::string message;                // Human status, e.g. "streaming" or why the device is gone.
  uint64_t frames_received = 0;       // Complete frames the capture thread got from the driver.
  uint64_t frames_grabbed = 0;        // Frames handed out by Grab().
  uint64_t frames_dropped = 0;        // Discarded by the drop-oldest queue or by latest-only grabs.
  uint64_t incomplete_frames = 0;     // Driver buffers with missing packets or other errors.
  uint64_t timeouts = 0;              // Driver waits that ended without a frame.
  uint64_t device_frames_lost = 0;    // Gaps in the device's own frame ids (lost before the host).
  uint64_t unpaired_frames = 0;       // Stereo / RGB-D frames dropped for want of a partner.
  uint64_t disconnects = 0;           // Times the device was lost.
  uint64_t reconnects = 0;            // Times it came back.
  int64_t last_device_frame_id = -1;  // The device's id of the newest received frame.
  double last_latency_ms = 0;         // Driver arrival to Grab() of the last grabbed frame [ms].
  double mean_latency_ms = 0;         // Mean of the above over all grabbed frames [ms].
  double receive_rate_hz = 0;         // Frames received per second, smoothed [Hz].
};

// The statistics as named values for plots and tables, keys "sensors/<name>" with units in the
// name where they have one ("sensors/latency_ms", "sensors/frames_dropped", ...).
std::vector<std::pair<std::string, double>> SensorStatValues(const SensorStats& stats);

}  // namespace sightline
