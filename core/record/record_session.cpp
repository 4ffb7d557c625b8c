#include "core/record/record_session.h"

#include "core/common/timing.h"
#include "core/sensors/live_source.h"

namespace sightline {

StatusOr<RecordSummary> RecordSource(Source* source, const std::string& dir,
                                     RecorderOptions options, const RecordLimits& limits,
                                     const RecordCallbacks& callbacks) {
  const SourceInfo& info = source->info();
  if (!info.live) options.block_when_full = true;
  StatusOr<std::unique_ptr<Recorder>> started =
      Recorder::Start(dir, info, options, callbacks.written);
  if (!started.ok()) return started.status();
  Recorder& recorder = **started;
  const auto* live = dynamic_cast<const LiveSource*>(source);

  RecordSummary summary;
  summary.folder = recorder.folder();
  summary.format = recorder.format();
  const double start = HostTimeS();
  int64_t taken = 0;
  bool in_outage = false;
  Status failure;
  while (true) {
    if (callbacks.stop && callbacks.stop->load()) {
      summary.end_reason = "stopped";
      break;
    }
    if (limits.max_frames > 0 && taken >= limits.max_frames) {
      summary.end_reason = "frame limit";
      break;
    }
    if (limits.max_seconds > 0 && HostTimeS() - start >= limits.max_seconds) {
      summary.end_reason = "time limit";
      break;
    }
    if (!recorder.status().ok()) {
      summary.end_reason = "write error";
      break;
    }
    const Status grabbed = source->Grab();
    if (grabbed.code() == StatusCode::kOutOfRange) {
      summary.end_reason = "end of recording";
      break;
    }
    if (grabbed.code() == StatusCode::kUnavailable && info.live) {
      if (!in_outage && callbacks.outage) callbacks.outage(grabbed);
      in_outage = true;
      continue;  // The source reconnects by itself.
    }
    if (!grabbed.ok()) {
      failure = grabbed;
      break;
    }
    in_outage = false;
    StatusOr<Frame> frame = source->Retrieve();
    if (!frame.ok()) {
      failure = frame.status();
      break;
    }
    ++taken;
    recorder.Push(std::move(*frame));
  }
  summary.write_status = recorder.Stop();
  if (!summary.write_status.ok()) summary.end_reason = "write error";
  summary.recorder = recorder.stats();
  summary.notes = recorder.notes();
  if (live) summary.sensor = live->stats();
  if (!failure.ok()) return failure;
  return summary;
}

}  // namespace sightline
