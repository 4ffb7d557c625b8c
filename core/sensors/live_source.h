// The base of every sensor source: a capture thread per device feeding a drop-oldest queue,
// disconnect detection with periodic reconnects, and thread-safe health statistics.
#pragma once

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>

#include "core/common/bounded_queue.h"
#include "core/common/frame.h"
#include "core/common/status.h"
#include "core/io/source.h"
#include "core/options/option_table.h"
#include "core/sensors/sensor_stats.h"

namespace sightline {

// Queueing and reconnect behaviour shared by all live sources. Each driver's options include
// these fields under its own prefix, e.g. `sensors.aravis.queue_capacity`.
struct LiveSourceOptions {
  int queue_capacity = 2;            // Frames buffered between capture thread and consumer.
  bool latest_only = true;           // Grab() returns the newest frame, skipping older queued ones.
  int grab_timeout_ms = 1000;        // How long Grab() waits for a frame [ms].
  int stall_timeout_ms = 3000;       // No frame for this long = device lost; 0 = never [ms].
  int reconnect_interval_ms = 1000;  // Pause between reconnect attempts [ms].

  bool IsValid(std::string* error) const;
  // Keys relative to the including driver's prefix (the table's own prefix is empty).
  static OptionTable<LiveSourceOptions> Describe();
};

// One frame as a driver delivered it to the capture thread.
struct CapturedFrame {
  Frame frame;                     // stamp.sensor_time_s set by the driver. sequence_id < 0 and
                                   // host_time_s == 0 are filled by LiveSource.
  int64_t device_frame_id = -1;    // The device's own frame counter, -1 if it has none.
  double arrival_host_time_s = 0;  // HostTimeS() when the driver received it; 0 = now.
};

// Device-side facts about the frame acquired by the last successful Grab().
struct GrabbedFrameInfo {
  int64_t device_frame_id = -1;
  double arrival_host_time_s = 0;  // HostTimeS() when the driver received the frame.
  double latency_ms = 0;           // From driver arrival to Grab() [ms].
};

// A sensor behind the Source interface. Subclasses implement Connect / ReadFrame / Disconnect
// for one device; LiveSource runs them:
//  - live devices (info().live): Open() connects in the caller's thread (so a missing device
//    fails Open() with a clear status), then a capture thread reads frames into a drop-oldest
//    BoundedQueue. Grab() pops from it, waiting at most grab_timeout_ms, and returns kUnavailable
//    with a message naming the device on timeout or while the device is gone. A device that
//    errors or delivers nothing for stall_timeout_ms is disconnected and reconnected every
//    reconnect_interval_ms until it returns; nothing throws, and the consumer keeps calling Grab().
//    A live source whose ReadFrame() returns kOutOfRange (a recording paced as a live camera)
//    ends: Grab() hands out the queued frames, then returns kOutOfRange.
//  - recordings a driver plays (info().live == false, e.g. .oni files): ReadFrame() runs inline
//    in Grab(), nothing is dropped and kOutOfRange ends the stream.
//
//   auto source = std::make_unique<AravisSource>("Fake_1", options);
//   if (Status s = source->Open(); !s.ok()) return s;
//   while (running) {
//     Status s = source->Grab();
//     if (s.code() == StatusCode::kUnavailable) { ShowStatus(source->stats().message); continue; }
//     if (!s.ok()) break;
//     Show(*source->Retrieve());
//   }
//
// Like every Source, Grab/Retrieve/Seek/Close belong to one consumer thread; stats() may be
// called from any thread. Subclass destructors must call Close() (the capture thread calls
// their virtual functions).
class LiveSource : public Source {
 public:
  explicit LiveSource(LiveSourceOptions options);
  ~LiveSource() override;
  LiveSource(const LiveSource&) = delete;
  LiveSource& operator=(const LiveSource&) = delete;

  // Connects to the device and, for live devices, starts the capture thread. Re-opening closes
  // first.
  Status Open() final;
  const SourceInfo& info() const override { return info_; }
  Status Grab() override;
  StatusOr<Frame> Retrieve() override;
  // Live: frames grabbed so far. Recordings: index of the next frame.
  int64_t Position() const override;
  // Stops the capture thread and releases the device.
  void Close() override;

  // A snapshot of state and counters; thread-safe.
  SensorStats stats() const;
  // About the frame of the last successful Grab().
  const GrabbedFrameInfo& last_grabbed() const { return grabbed_info_; }
  // The queueing and reconnect settings given at construction.
  const LiveSourceOptions& live_options() const { return live_options_; }
  // True between a successful Open() and Close().
  bool is_open() const { return open_; }

 protected:
  // Opens the device (again, after a disconnect) and describes it in *info. Called from Open()
  // in the consumer's thread and for reconnects in the capture thread.
  virtual Status Connect(SourceInfo* info) = 0;
  // Waits at most `timeout` for the next frame: a frame, nullopt when none came, kUnavailable
  // when the device is gone, kOutOfRange at the end of a recording.
  virtual StatusOr<std::optional<CapturedFrame>> ReadFrame(std::chrono::milliseconds timeout) = 0;
  // Releases the device; must be safe after a failed Connect(). `device_lost` says the device
  // stopped answering (skip commands that would wait for it).
  virtual void Disconnect(bool device_lost) = 0;
  // Names the device in messages, e.g. "Aravis camera 'Fake_1'".
  virtual std::string DeviceLabel() const = 0;

  // Counters for subclasses (capture thread or inline).
  void CountIncomplete(uint64_t n = 1);
  void CountTimeouts(uint64_t n = 1);
  void CountUnpaired(uint64_t n = 1);
  void CountDeviceFramesLost(uint64_t n);
  // Recordings: the index the next Grab() acquires (after a subclass's Seek()).
  void SetPosition(int64_t next) { position_ = next; }
  // Recordings: ends the current frame so that Retrieve() fails until the next Grab().
  void ForgetGrabbed() { grabbed_.reset(); }

 private:
  void CaptureLoop();
  // Fills sequence id and host time, updates receive counters.
  void Stamp(CapturedFrame* captured);
  void Accept(CapturedFrame captured);
  void MarkLost(const std::string& reason);
  // Waits for Close() up to `duration`; true when a stop was requested.
  bool WaitForStop(std::chrono::milliseconds duration);
  void SetMessage(SensorState state, std::string message);

  const LiveSourceOptions live_options_;
  SourceInfo info_;
  bool open_ = false;
  bool inline_ = false;  // A recording: ReadFrame() runs in Grab().
  // Swapped only under stats_mutex_ while no capture thread runs; stats() reads it locked.
  std::unique_ptr<BoundedQueue<CapturedFrame>> queue_;
  std::thread thread_;
  std::mutex stop_mutex_;
  std::condition_variable stop_cv_;
  bool stop_ = false;               // Guarded by stop_mutex_.
  std::atomic<bool> ended_{false};  // The capture thread saw kOutOfRange (a paced recording).

  mutable std::mutex stats_mutex_;
  SensorStats stats_;          // Guarded by stats_mutex_ (queue drops are added on read).
  uint64_t skipped_ = 0;       // Latest-only skips; guarded by stats_mutex_.
  double last_receive_s_ = 0;  // Capture side only.
  int64_t next_sequence_ = 0;  // Capture side (or inline) only.

  std::optional<Frame> grabbed_;
  GrabbedFrameInfo grabbed_info_;
  int64_t position_ = 0;
  double latency_sum_ms_ = 0;
};

}  // namespace sightline
