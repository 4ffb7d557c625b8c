#include "core/sensors/aravis_source.h"

#include <algorithm>
#include <utility>

namespace sightline {

void DescribeAravisCamera(const AravisCameraSettings& s, SourceInfo* info) {
  info->width = s.width;
  info->height = s.height;
  info->rate_hz = s.frame_rate_hz;
  info->live = true;
  info->seekable = false;
  info->frame_count = -1;
  info->notes.push_back(s.vendor + " " + s.model + ", serial " + s.serial + ", " + s.protocol +
                        ", id " + s.device_id);
  info->notes.push_back(s.pixel_format + " " + std::to_string(s.width) + "x" +
                        std::to_string(s.height) + ", exposure " +
                        std::to_string(static_cast<int>(s.exposure_us)) + " us, gain " +
                        std::to_string(s.gain_db) + " dB, trigger " + s.trigger);
  if (s.packet_size > 0) {
    info->notes.push_back("GigE packet size " + std::to_string(s.packet_size) + " bytes");
  }
  info->notes.push_back("no calibration: intrinsics unknown until the camera is calibrated");
}

AravisSource::AravisSource(std::string device_id, AravisOptions options)
    : LiveSource(options.live), device_id_(std::move(device_id)), options_(std::move(options)) {}

AravisSource::~AravisSource() { Close(); }

Status AravisSource::Available() { return Status::Ok(); }

std::vector<DeviceInfo> AravisSource::Enumerate(bool include_fake) {
  return EnumerateAravisCameras(include_fake);
}

AravisCameraSettings AravisSource::settings() const {
  std::lock_guard<std::mutex> lock(settings_mutex_);
  return settings_;
}

std::string AravisSource::DeviceLabel() const {
  return "Aravis camera '" + (device_id_.empty() ? std::string("(first camera)") : device_id_) +
         "'";
}

Status AravisSource::Connect(SourceInfo* info) {
  std::string error;
  if (!options_.IsValid(&error)) return InvalidArgument(error);
  camera_ = std::make_unique<AravisCamera>();
  SIGHTLINE_RETURN_IF_ERROR(camera_->Open(device_id_, options_));
  {
    std::lock_guard<std::mutex> lock(settings_mutex_);
    settings_ = camera_->settings();
  }
  info->format = "Aravis camera";
  info->path = "aravis://" + camera_->settings().device_id;
  info->kind = SourceKind::kMono;
  DescribeAravisCamera(camera_->settings(), info);
  next_trigger_ = std::chrono::steady_clock::now();
  return Status::Ok();
}

StatusOr<std::optional<CapturedFrame>> AravisSource::ReadFrame(std::chrono::milliseconds timeout) {
  using Clock = std::chrono::steady_clock;
  const Clock::time_point deadline = Clock::now() + timeout;
  while (true) {
    Clock::time_point now = Clock::now();
    Clock::time_point wait_until = deadline;
    if (options_.trigger == "software") {
      if (now >= next_trigger_) {
        Status s = camera_->SoftwareTrigger();
        if (!s.ok()) return s;
        const auto period = std::chrono::duration_cast<Clock::duration>(
            std::chrono::duration<double>(1.0 / options_.frame_rate_hz));
        next_trigger_ = std::max(next_trigger_ + period, now);
      }
      wait_until = std::min(deadline, next_trigger_);
    }
    const auto wait = std::chrono::duration_cast<std::chrono::microseconds>(wait_until - now);
    StatusOr<AravisPop> pop = camera_->Pop(std::max(wait, std::chrono::microseconds(0)));
    if (!pop.ok()) return pop.status();
    if (pop->incomplete > 0) CountIncomplete(pop->incomplete);
    if (pop->buffer_timeouts > 0) CountTimeouts(pop->buffer_timeouts);
    if (pop->device_frames_lost > 0) CountDeviceFramesLost(pop->device_frames_lost);
    if (pop->image) {
      CapturedFrame captured;
      MonoFrame mono;
      mono.stamp.sensor_time_s = pop->image->device_time_s;
      mono.image = std::move(pop->image->image);
      captured.frame = std::move(mono);
      captured.device_frame_id = pop->image->frame_id;
      captured.arrival_host_time_s = pop->image->arrival_host_time_s;
      return std::optional<CapturedFrame>(std::move(captured));
    }
    if (Clock::now() >= deadline) return std::optional<CapturedFrame>();
  }
}

void AravisSource::Disconnect(bool device_lost) {
  if (camera_) camera_->Close(device_lost);
  camera_.reset();
}

}  // namespace sightline
