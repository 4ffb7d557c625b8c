#include "core/record/recorder.h"

#include <algorithm>
#include <filesystem>

#include "core/common/timing.h"
#include "core/record/bag_frame_writer.h"

namespace sightline {
namespace {

// Checks that `dir` may receive a recording of `kind`: absent or an empty folder, or with
// `overwrite` any folder, whose sensor folder is then removed (no image of the old recording may
// stay beside the new index files).
// `replaced`: what overwrite removes, the sensor folder or the bag.
Status PrepareRecordingFolder(const std::string& dir, const std::string& replaced, bool overwrite) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::file_status status = fs::status(dir, ec);
  if (!fs::exists(status)) return Status::Ok();
  if (!fs::is_directory(status)) {
    return FailedPrecondition("cannot record into " + dir + ": it is a file, not a folder");
  }
  std::vector<std::string> names;
  for (const fs::directory_entry& entry : fs::directory_iterator(dir, ec)) {
    names.push_back(entry.path().filename().string());
  }
  if (ec) return Unavailable("cannot record into " + dir + ": " + ec.message());
  if (names.empty()) return Status::Ok();
  const fs::path sensor = fs::path(dir) / replaced;
  if (!overwrite) {
    std::sort(names.begin(), names.end());
    return FailedPrecondition(
        "cannot record into " + dir + ": the folder already holds " + std::to_string(names.size()) +
        " file(s) or folder(s) (e.g. '" + names.front() +
        "'); recording there would truncate or mix with what is there. Choose a new or empty "
        "folder, or overwrite (record.overwrite=true, sightline-cli record --overwrite) to "
        "replace " +
        sensor.string());
  }
  fs::remove_all(sensor, ec);
  if (ec) return Unavailable("cannot replace " + sensor.string() + ": " + ec.message());
  return Status::Ok();
}

}  // namespace

bool RecorderOptions::IsValid(std::string* error) const {
  auto fail = [&](const std::string& m) {
    if (error) *error = m;
    return false;
  };
  if (queue_capacity < 1) return fail("record.queue_capacity must be >= 1");
  if (png_compression < 0 || png_compression > 9) {
    return fail("record.png_compression must be in [0, 9]");
  }
  if (format != "folders" && format != "bag") {
    return fail("record.format must be folders or bag, not '" + format + "'");
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
            "being written.")
      .Bool("overwrite", &RecorderOptions::overwrite,
            "Record into a folder that already holds files; its sensor folder (rgbd/, stereo/ "
            "or mono/) is replaced as a whole, other files stay. Off: such a folder is refused.")
      .Choice("format", &RecorderOptions::format, {"folders", "bag"},
              "folders: one sensor folder in the readers' layouts (TUM RGB-D, EuRoC, image "
              "folder), every listed frame complete on disk; bag: one ROS 1 bag, "
              "recording.bag (lz4), indexed when the recording ends.");
}

StatusOr<std::unique_ptr<Recorder>> Recorder::Start(
    const std::string& dir, const SourceInfo& info, const RecorderOptions& options,
    std::function<void(const WrittenFrame&)> on_written) {
  std::string error;
  if (!options.IsValid(&error)) return InvalidArgument(error);
  if (info.kind != SourceKind::kCloud) {  // Point clouds are refused by CreateFrameWriter.
    const bool bag = options.format == "bag";
    SIGHTLINE_RETURN_IF_ERROR(PrepareRecordingFolder(
        dir, bag ? kRecordingBagName : SensorFolderName(info.kind), options.overwrite));
  }
  FrameWriterSettings settings;
  settings.png_compression = options.png_compression;
  settings.sync = options.sync;
  StatusOr<std::unique_ptr<FrameWriter>> writer = options.format == "bag"
                                                      ? CreateBagFrameWriter(dir, info)
                                                      : CreateFrameWriter(dir, info, settings);
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
    const Status finished = writer_->Finish();
    std::lock_guard<std::mutex> lock(mutex_);
    if (status_.ok() && !finished.ok()) status_ = finished;
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
