// Recording an open source until a limit, its end, a stop request or a write error: the loop
// that `sightline-cli record` and the tests run.
#pragma once

#include <atomic>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>

#include "core/common/status.h"
#include "core/io/source.h"
#include "core/record/recorder.h"
#include "core/sensors/sensor_stats.h"

namespace sightline {

// When to stop; zero = no limit.
struct RecordLimits {
  int64_t max_frames = 0;  // Frames taken from the source.
  double max_seconds = 0;  // Wall time [s].
};

// What a recording session did.
struct RecordSummary {
  std::string folder;                 // The sensor folder written, e.g. "DIR/rgbd".
  std::string format;                 // Its reader's format name.
  std::string end_reason;             // "frame limit", "time limit", "end of recording", ...
  RecorderStats recorder;             // Written / dropped by the recorder.
  std::optional<SensorStats> sensor;  // The live source's own counters (its drops included).
  Status write_status;                // Ok, or the write error that stopped the recording.
  std::vector<std::string> notes;     // From the writer (e.g. nominal calibration).

  // Frames lost before the disk: the source's drops plus the recorder's.
  uint64_t TotalDropped() const {
    return recorder.frames_dropped + (sensor ? sensor->frames_dropped : 0);
  }
};

// Optional hooks of a session.
struct RecordCallbacks {
  std::function<void(const WrittenFrame&)> written;  // Writer thread, after each durable frame.
  std::function<void(const Status&)> outage;         // A live source stopped delivering (once
                                                     // per outage; it reconnects by itself).
  const std::atomic<bool>* stop = nullptr;           // Checked between frames.
};

// Records `source` (open) into `dir`. Recorded (non-live) sources never drop: the recorder then
// waits for the disk. Fails only when the recording cannot start (folder, calibration, kind) or
// the source fails for good; a write error ends the session with write_status set and what was
// written readable.
StatusOr<RecordSummary> RecordSource(Source* source, const std::string& dir,
                                     RecorderOptions options, const RecordLimits& limits,
                                     const RecordCallbacks& callbacks = {});

}  // namespace sightline
