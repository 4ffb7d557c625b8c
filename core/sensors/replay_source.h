// A recording played as a live camera: frames paced at the recorded (or a chosen) rate through
// LiveSource's capture thread and drop-oldest queue, exactly as a real device delivers them.
#pragma once

#include <chrono>
#include <memory>
#include <optional>
#include <string>

#include "core/options/option_table.h"
#include "core/sensors/live_source.h"

namespace sightline {

// Settings of replayed recordings, keys `sensors.replay.*`; a URI's query (?fps=30&loop=1)
// overrides them for one source.
struct ReplayOptions {
  double fps = 0;     // Delivery rate [Hz]; 0 = the recording's own timestamps.
  bool loop = false;  // Start again at the end (times keep increasing) instead of ending.
  // Queueing; no stall detection (a starved machine reads slowly, and a reconnect would start
  // the recording over).
  LiveSourceOptions live = [] {
    LiveSourceOptions o;
    o.stall_timeout_ms = 0;
    return o;
  }();

  bool IsValid(std::string* error) const;
  static OptionTable<ReplayOptions> Describe();
};

// Any dataset or recording folder OpenDataset() reads, as a live source (URI
// "replay://PATH?fps=30&loop=1"). info().live is true, frames carry the recording's sensor
// times (shifted by whole loops when looping) and fresh sequence ids and host times; a consumer
// slower than the rate loses the oldest frames, counted in stats(). Without looping, Grab()
// returns kOutOfRange once the last frame has been handed out.
//
//   ReplaySource camera("/data/corridor", ReplayOptions{.fps = 30});
//   if (Status s = camera.Open(); !s.ok()) return s;
//   while (camera.Grab().ok()) Show(*camera.Retrieve());
class ReplaySource : public LiveSource {
 public:
  ReplaySource(std::string path, ReplayOptions options);
  ~ReplaySource() override;

  // Always Ok: replaying needs no driver.
  static Status Available() { return Status::Ok(); }
  // Splits "PATH?fps=30&loop=1" (scheme already removed) into the path and the options
  // overridden by the query. InvalidArgument naming an unknown key or a bad value.
  static StatusOr<std::pair<std::string, ReplayOptions>> ParseUri(const std::string& rest,
                                                                  ReplayOptions defaults);

 protected:
  Status Connect(SourceInfo* info) override;
  StatusOr<std::optional<CapturedFrame>> ReadFrame(std::chrono::milliseconds timeout) override;
  void Disconnect(bool device_lost) override;
  std::string DeviceLabel() const override;

 private:
  using Clock = std::chrono::steady_clock;
  // Reads the next frame of the recording into pending_ (looping if asked).
  Status ReadNext(bool* looped);

  const std::string path_;
  const ReplayOptions options_;
  std::unique_ptr<Source> recording_;
  std::optional<Frame> pending_;
  Clock::time_point due_;
  Clock::time_point start_;
  double first_time_s_ = 0;
  double loop_offset_s_ = 0;
  double last_time_s_ = 0;  // Sensor time of the last delivered frame.
  double period_s_ = 0;     // One frame at the nominal rate, for loop offsets.
  int64_t delivered_ = 0;
};

}  // namespace sightline
