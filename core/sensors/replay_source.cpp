#include "core/sensors/replay_source.h"

#include <thread>
#include <utility>
#include <variant>

#include "core/io/dataset.h"

namespace sightline {
namespace {

FrameStamp& MutableStamp(Frame& frame) {
  return std::visit([](auto& f) -> FrameStamp& { return f.stamp; }, frame);
}

}  // namespace

ReplaySource::ReplaySource(std::string path, ReplayOptions options)
    : LiveSource(options.live), path_(std::move(path)), options_(std::move(options)) {}

ReplaySource::~ReplaySource() { Close(); }

StatusOr<std::pair<std::string, ReplayOptions>> ReplaySource::ParseUri(const std::string& rest,
                                                                       ReplayOptions options) {
  const size_t question = rest.find('?');
  const std::string path = rest.substr(0, question);
  if (path.empty()) return InvalidArgument("a replay URI names a recording: replay://PATH?fps=30");
  if (question != std::string::npos) {
    std::string query = rest.substr(question + 1);
    size_t begin = 0;
    while (begin <= query.size()) {
      const size_t end = std::min(query.find('&', begin), query.size());
      const std::string item = query.substr(begin, end - begin);
      begin = end + 1;
      if (item.empty()) continue;
      const size_t eq = item.find('=');
      const std::string key = item.substr(0, eq);
      const std::string value = eq == std::string::npos ? "1" : item.substr(eq + 1);
      try {
        if (key == "fps") {
          size_t used = 0;
          options.fps = std::stod(value, &used);
          if (used != value.size()) throw std::invalid_argument(value);
        } else if (key == "loop") {
          if (value != "0" && value != "1" && value != "true" && value != "false") {
            throw std::invalid_argument(value);
          }
          options.loop = value == "1" || value == "true";
        } else {
          return InvalidArgument("replay URI '" + rest + "': unknown key '" + key +
                                 "' (known: fps, loop)");
        }
      } catch (const std::exception&) {
        return InvalidArgument("replay URI '" + rest + "': bad value '" + value + "' for " + key);
      }
    }
  }
  std::string error;
  if (!options.IsValid(&error)) return InvalidArgument("replay URI '" + rest + "': " + error);
  return std::make_pair(path, options);
}

std::string ReplaySource::DeviceLabel() const { return "replayed recording '" + path_ + "'"; }

Status ReplaySource::Connect(SourceInfo* info) {
  StatusOr<std::unique_ptr<Source>> opened = OpenDataset(path_);
  if (!opened.ok()) return opened.status();
  recording_ = std::move(*opened);
  *info = recording_->info();
  // rate_hz keeps describing the timestamps (the recording's); fps only paces delivery.
  const double rate = info->rate_hz;
  info->notes.push_back(
      "replayed as a live camera: " + std::to_string(info->frame_count) + " " + info->format +
      " frames at " +
      (options_.fps > 0 ? std::to_string(options_.fps) + " Hz" : std::string("the recorded rate")) +
      (options_.loop ? ", looping" : ""));
  info->format = "replayed " + info->format;
  info->live = true;
  info->seekable = false;
  info->frame_count = -1;
  info->has_ground_truth = false;
  period_s_ = rate > 0 ? 1.0 / rate : 0.1;
  pending_.reset();
  loop_offset_s_ = 0;
  delivered_ = 0;
  start_ = Clock::now();
  return Status::Ok();
}

Status ReplaySource::ReadNext(bool* looped) {
  Status grabbed = recording_->Grab();
  if (grabbed.code() == StatusCode::kOutOfRange && options_.loop && delivered_ > 0) {
    SIGHTLINE_RETURN_IF_ERROR(recording_->Seek(0));
    grabbed = recording_->Grab();
    *looped = true;
  }
  if (grabbed.code() == StatusCode::kOutOfRange) {
    return OutOfRange("end of " + DeviceLabel() + " after " + std::to_string(delivered_) +
                      " frames");
  }
  SIGHTLINE_RETURN_IF_ERROR(grabbed);
  StatusOr<Frame> frame = recording_->Retrieve();
  if (!frame.ok()) return frame.status();
  pending_ = std::move(*frame);
  return Status::Ok();
}

StatusOr<std::optional<CapturedFrame>> ReplaySource::ReadFrame(std::chrono::milliseconds timeout) {
  if (!recording_) return Unavailable(DeviceLabel() + " is not open");
  if (!pending_) {
    bool looped = false;
    SIGHTLINE_RETURN_IF_ERROR(ReadNext(&looped));
    FrameStamp& stamp = MutableStamp(*pending_);
    if (delivered_ == 0) first_time_s_ = stamp.sensor_time_s;
    // After a loop the clock continues one period after the last delivered frame.
    if (looped) loop_offset_s_ = last_time_s_ + period_s_ - stamp.sensor_time_s;
    stamp.sensor_time_s += loop_offset_s_;
    const double offset_s = options_.fps > 0 ? static_cast<double>(delivered_) / options_.fps
                                             : stamp.sensor_time_s - first_time_s_;
    due_ = start_ +
           std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(offset_s));
  }
  const Clock::time_point now = Clock::now();
  if (due_ - now > timeout) {
    std::this_thread::sleep_for(timeout);
    return std::optional<CapturedFrame>();
  }
  if (due_ > now) std::this_thread::sleep_until(due_);
  CapturedFrame captured;
  captured.frame = std::move(*pending_);
  pending_.reset();
  FrameStamp& stamp = MutableStamp(captured.frame);
  stamp.sequence_id = -1;
  stamp.host_time_s = 0;
  captured.device_frame_id = delivered_;
  last_time_s_ = stamp.sensor_time_s;
  ++delivered_;
  return std::optional<CapturedFrame>(std::move(captured));
}

void ReplaySource::Disconnect(bool) {
  recording_.reset();
  pending_.reset();
}

}  // namespace sightline
