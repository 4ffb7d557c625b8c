#include "core/sensors/live_source.h"

#include <algorithm>
#include <utility>
#include <variant>

#include "core/common/timing.h"

namespace sightline {
namespace {

// How long one ReadFrame() call in the capture thread may block; bounds the reaction to Close().
constexpr std::chrono::milliseconds kReadSlice(100);

FrameStamp& MutableStamp(Frame& frame) {
  return std::visit([](auto& f) -> FrameStamp& { return f.stamp; }, frame);
}

std::string Ms(int ms) { return std::to_string(ms) + " ms"; }

}  // namespace

LiveSource::LiveSource(LiveSourceOptions options) : live_options_(std::move(options)) {}

LiveSource::~LiveSource() {
  // Subclasses close in their own destructors; here only the thread may still need stopping,
  // which would call pure virtuals. Fail loudly rather than crash obscurely.
  if (thread_.joinable()) std::terminate();
}

Status LiveSource::Open() {
  Close();
  std::string error;
  if (!live_options_.IsValid(&error)) return InvalidArgument(DeviceLabel() + ": " + error);
  SourceInfo info;
  Status connected = Connect(&info);
  if (!connected.ok()) {
    Disconnect(/*device_lost=*/false);
    SetMessage(SensorState::kClosed, connected.message());
    return connected;
  }
  info_ = std::move(info);
  open_ = true;
  inline_ = !info_.live;
  position_ = 0;
  next_sequence_ = 0;
  latency_sum_ms_ = 0;
  grabbed_.reset();
  grabbed_info_ = GrabbedFrameInfo();
  {
    std::lock_guard<std::mutex> lock(stats_mutex_);
    stats_ = SensorStats();
    skipped_ = 0;
    stats_.state = SensorState::kStreaming;
    stats_.message = inline_ ? "playing" : "streaming";
  }
  last_receive_s_ = 0;
  if (!inline_) {
    auto queue = std::make_unique<BoundedQueue<CapturedFrame>>(
        DeviceLabel(), static_cast<size_t>(live_options_.queue_capacity), QueuePolicy::kDropOldest);
    {
      std::lock_guard<std::mutex> lock(stats_mutex_);  // stats() reads queue_ from any thread.
      queue_ = std::move(queue);
    }
    {
      std::lock_guard<std::mutex> lock(stop_mutex_);
      stop_ = false;
    }
    ended_ = false;
    thread_ = std::thread(&LiveSource::CaptureLoop, this);
  }
  return Status::Ok();
}

void LiveSource::Close() {
  if (thread_.joinable()) {
    {
      std::lock_guard<std::mutex> lock(stop_mutex_);
      stop_ = true;
    }
    stop_cv_.notify_all();
    thread_.join();  // The thread disconnects the device on its way out.
  } else if (open_) {
    Disconnect(/*device_lost=*/false);
  }
  {
    std::lock_guard<std::mutex> lock(stats_mutex_);
    if (queue_) {
      queue_->Shutdown();
      stats_.frames_dropped += queue_->dropped();
      queue_.reset();
    }
    if (open_) {
      stats_.state = SensorState::kClosed;
      stats_.message = "closed";
    }
  }
  open_ = false;
  grabbed_.reset();
}

bool LiveSource::WaitForStop(std::chrono::milliseconds duration) {
  std::unique_lock<std::mutex> lock(stop_mutex_);
  return stop_cv_.wait_for(lock, duration, [&] { return stop_; });
}

void LiveSource::SetMessage(SensorState state, std::string message) {
  std::lock_guard<std::mutex> lock(stats_mutex_);
  stats_.state = state;
  stats_.message = std::move(message);
}

void LiveSource::MarkLost(const std::string& reason) {
  std::lock_guard<std::mutex> lock(stats_mutex_);
  ++stats_.disconnects;
  stats_.state = SensorState::kDisconnected;
  stats_.message = DeviceLabel() + " disconnected: " + reason + "; reconnecting every " +
                   Ms(live_options_.reconnect_interval_ms);
}

void LiveSource::CaptureLoop() {
  using Clock = std::chrono::steady_clock;
  bool connected = true;
  std::string lost_reason;
  Clock::time_point last_frame = Clock::now();
  const auto stall = std::chrono::milliseconds(live_options_.stall_timeout_ms);
  const auto interval = std::chrono::milliseconds(live_options_.reconnect_interval_ms);
  while (true) {
    {
      std::lock_guard<std::mutex> lock(stop_mutex_);
      if (stop_) break;
    }
    if (!connected) {
      if (WaitForStop(interval)) break;
      SourceInfo scratch;  // info() stays as Open() found it.
      Status s = Connect(&scratch);
      if (!s.ok()) {
        Disconnect(/*device_lost=*/false);
        SetMessage(SensorState::kDisconnected, DeviceLabel() + " disconnected: " + lost_reason +
                                                   "; reconnecting every " +
                                                   Ms(live_options_.reconnect_interval_ms) +
                                                   " (last attempt: " + s.message() + ")");
        continue;
      }
      connected = true;
      last_frame = Clock::now();
      std::lock_guard<std::mutex> lock(stats_mutex_);
      ++stats_.reconnects;
      stats_.state = SensorState::kStreaming;
      stats_.message = "streaming (reconnected after: " + lost_reason + ")";
      continue;
    }
    StatusOr<std::optional<CapturedFrame>> read = ReadFrame(kReadSlice);
    if (!read.ok() && read.status().code() == StatusCode::kOutOfRange) {
      // A live-paced recording ended: Grab() hands out what is queued, then kOutOfRange.
      SetMessage(SensorState::kClosed, read.status().message());
      ended_ = true;
      queue_->Shutdown();
      break;
    }
    if (!read.ok() ||
        (!read->has_value() && stall.count() > 0 && Clock::now() - last_frame > stall)) {
      lost_reason = read.ok() ? "no frame for " + Ms(live_options_.stall_timeout_ms)
                              : read.status().message();
      MarkLost(lost_reason);
      Disconnect(/*device_lost=*/true);
      connected = false;
      continue;
    }
    if (!read->has_value()) continue;
    last_frame = Clock::now();
    CapturedFrame captured = std::move(**read);
    Stamp(&captured);
    queue_->Push(std::move(captured));
  }
  if (connected) Disconnect(/*device_lost=*/false);
}

void LiveSource::Stamp(CapturedFrame* captured) {
  const double now = HostTimeS();
  if (captured->arrival_host_time_s <= 0) captured->arrival_host_time_s = now;
  FrameStamp& stamp = MutableStamp(captured->frame);
  if (stamp.sequence_id < 0) stamp.sequence_id = next_sequence_;
  next_sequence_ = stamp.sequence_id + 1;
  if (stamp.host_time_s <= 0) stamp.host_time_s = captured->arrival_host_time_s;
  std::lock_guard<std::mutex> lock(stats_mutex_);
  ++stats_.frames_received;
  stats_.last_device_frame_id = captured->device_frame_id;
  if (last_receive_s_ > 0 && now > last_receive_s_) {
    const double rate = 1.0 / (now - last_receive_s_);
    stats_.receive_rate_hz =
        stats_.receive_rate_hz <= 0 ? rate : 0.9 * stats_.receive_rate_hz + 0.1 * rate;
  }
  last_receive_s_ = now;
}

void LiveSource::Accept(CapturedFrame captured) {
  const double now = HostTimeS();
  grabbed_info_.device_frame_id = captured.device_frame_id;
  grabbed_info_.arrival_host_time_s = captured.arrival_host_time_s;
  grabbed_info_.latency_ms = std::max(0.0, (now - captured.arrival_host_time_s) * 1000.0);
  position_ = inline_ ? StampOf(captured.frame).sequence_id + 1 : position_ + 1;
  grabbed_ = std::move(captured.frame);
  latency_sum_ms_ += grabbed_info_.latency_ms;
  std::lock_guard<std::mutex> lock(stats_mutex_);
  ++stats_.frames_grabbed;
  stats_.last_latency_ms = grabbed_info_.latency_ms;
  stats_.mean_latency_ms = latency_sum_ms_ / static_cast<double>(stats_.frames_grabbed);
}

Status LiveSource::Grab() {
  if (!open_) return FailedPrecondition(DeviceLabel() + " is not open");
  grabbed_.reset();
  const auto timeout = std::chrono::milliseconds(live_options_.grab_timeout_ms);
  if (inline_) {
    StatusOr<std::optional<CapturedFrame>> read = ReadFrame(timeout);
    if (!read.ok()) return read.status();
    if (!read->has_value()) {
      CountTimeouts();
      return Unavailable("no frame from " + DeviceLabel() + " within " +
                         Ms(live_options_.grab_timeout_ms));
    }
    CapturedFrame captured = std::move(**read);
    Stamp(&captured);
    Accept(std::move(captured));
    return Status::Ok();
  }
  std::optional<CapturedFrame> item = queue_->PopFor(timeout);
  if (!item && ended_) {
    std::lock_guard<std::mutex> lock(stats_mutex_);
    return OutOfRange(stats_.message);
  }
  if (!item) {
    std::lock_guard<std::mutex> lock(stats_mutex_);
    ++stats_.timeouts;
    if (stats_.state == SensorState::kDisconnected) return Unavailable(stats_.message);
    return Unavailable("no frame from " + DeviceLabel() + " within " +
                       Ms(live_options_.grab_timeout_ms));
  }
  if (live_options_.latest_only) {
    uint64_t skipped = 0;
    while (std::optional<CapturedFrame> newer = queue_->TryPop()) {
      item = std::move(newer);
      ++skipped;
    }
    if (skipped > 0) {
      std::lock_guard<std::mutex> lock(stats_mutex_);
      skipped_ += skipped;
    }
  }
  Accept(std::move(*item));
  return Status::Ok();
}

StatusOr<Frame> LiveSource::Retrieve() {
  if (!grabbed_)
    return FailedPrecondition(DeviceLabel() + ": Retrieve() without a successful Grab()");
  return *grabbed_;
}

int64_t LiveSource::Position() const { return position_; }

SensorStats LiveSource::stats() const {
  std::lock_guard<std::mutex> lock(stats_mutex_);
  SensorStats copy = stats_;
  copy.frames_dropped += skipped_;
  if (queue_) copy.frames_dropped += queue_->dropped();
  return copy;
}

void LiveSource::CountIncomplete(uint64_t n) {
  std::lock_guard<std::mutex> lock(stats_mutex_);
  stats_.incomplete_frames += n;
}
void LiveSource::CountTimeouts(uint64_t n) {
  std::lock_guard<std::mutex> lock(stats_mutex_);
  stats_.timeouts += n;
}
void LiveSource::CountUnpaired(uint64_t n) {
  std::lock_guard<std::mutex> lock(stats_mutex_);
  stats_.unpaired_frames += n;
}
void LiveSource::CountDeviceFramesLost(uint64_t n) {
  std::lock_guard<std::mutex> lock(stats_mutex_);
  stats_.device_frames_lost += n;
}

}  // namespace sightline
