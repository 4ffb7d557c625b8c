#include "core/record/recorder.h"

#include "core/common/timing.h"

namespace sightline {

bool RecorderOptions::IsValid(std::string* error) const {
  auto fail = [&](const std::string& m) {
    if (error) *error = m;
    return false;
  };
  if (queue_capacity < 1) return fail("record.queue_capacity must be >= 1");
  if (png_compression < 0 || png_compression > 9) {
    return fail("record.png_compression must be in [0, 9]");
  }
  return true;
}

OptionTable<RecorderOptions> RecorderOptions::Describe() {
  return OptionTable<RecorderOptions>("record")
      .Int("queue_capacity", &RecorderOptions::queue_capacity, "frames", 1, 4096, 1,
           "Frames buffered between the camera and the disk; when full the oldest is dropped "
           "and counted.")
      .Bool("block_when_full", &RecorderOptions::block_when_full,
            "Wait for the disk instead of dropping frames (for recorded sources, which can "
            "wait).")
      .Int("png_compression", &RecorderOptions::png_compression, "", 0, 9, 1,
           "PNG zlib level: 0 is fastest and largest, 9 smallest and slowest.")
      .Bool("sync", &RecorderOptions::sync,
            "fsync every image and index line, so that a pulled plug loses at most the frame "
            "being written.");
}

StatusOr<std::unique_ptr<Recorder>> Recorder::Start(
    const std::string& dir, const SourceInfo& info, const RecorderOptions& options,
    std::function<void(const WrittenFrame&)> on_written) {
  std::string error;
  if (!options.IsValid(&error)) return InvalidArgument(error);
  FrameWriterSettings settings;
  settings.png_compression = options.png_compression;
  settings.sync = options.sync;
  StatusOr<std::unique_ptr<FrameWriter>> writer = CreateFrameWriter(dir, info, settings);
  if (!writer.ok()) return writer.status();
  std::unique_ptr<Recorder> recorder(new Recorder());
  recorder->options_ = options;
  recorder->writer_ = std::move(*writer);
  recorder->on_written_ = std::move(on_written);
  recorder->queue_ = std::make_unique<BoundedQueue<Frame>>(
      "recorder", static_cast<size_t>(options.queue_capacity),
      options.block_when_full ? QueuePolicy::kBlockWhenFull : QueuePolicy::kDropOldest);
  recorder->start_s_ = HostTimeS();
  recorder->thread_ = std::thread(&Recorder::WriterLoop, recorder.get());
  return recorder;
}

Recorder::~Recorder() { (void)Stop(); }

bool Recorder::Push(Frame frame) {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    ++stats_.frames_offered;
    const double t = StampOf(frame).sensor_time_s;
    const bool in_order = !have_time_ || t > last_time_s_;
    if (!in_order) {
      // Index files and readers need increasing times (EuRoC names files by them).
      ++stats_.frames_out_of_order;
      return false;
    }
    if (!status_.ok()) {
      ++rejected_;
      return false;
    }
    last_time_s_ = t;
    have_time_ = true;
  }
  if (queue_->Push(std::move(frame))) return true;
  std::lock_guard<std::mutex> lock(mutex_);
  ++rejected_;
  return false;
}

void Recorder::WriterLoop() {
  int64_t index = 0;
  while (std::optional<Frame> frame = queue_->Pop()) {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      if (!status_.ok()) {
        ++lost_on_error_;
        continue;
      }
    }
    const Status written = writer_->Write(*frame, index);
    {
      std::lock_guard<std::mutex> lock(mutex_);
      stats_.bytes_written = writer_->bytes_written();
      if (!written.ok()) {
        status_ = written;
        ++lost_on_error_;
        queue_->Shutdown();  // Refuse further frames; the ones queued are counted as lost.
        continue;
      }
      ++stats_.frames_written;
    }
    if (on_written_) on_written_(WrittenFrame{index, StampOf(*frame)});
    ++index;
  }
}

Status Recorder::Stop() {
  if (thread_.joinable()) {
    queue_->Shutdown();
    thread_.join();
    std::lock_guard<std::mutex> lock(mutex_);
    stop_s_ = HostTimeS();
  }
  return status();
}

Status Recorder::status() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return status_;
}

RecorderStats Recorder::stats() const {
  std::lock_guard<std::mutex> lock(mutex_);
  RecorderStats s = stats_;
  s.frames_dropped = queue_->dropped() + rejected_ + lost_on_error_ + s.frames_out_of_order;
  s.elapsed_s = (stop_s_ > 0 ? stop_s_ : HostTimeS()) - start_s_;
  s.write_mb_per_s = s.elapsed_s > 0 ? static_cast<double>(s.bytes_written) / s.elapsed_s / 1e6 : 0;
  s.failed = !status_.ok();
  return s;
}

}  // namespace sightline
