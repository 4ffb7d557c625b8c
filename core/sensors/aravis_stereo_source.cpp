#include "core/sensors/aravis_stereo_source.h"

#include <algorithm>
#include <utility>

#include "core/io/stereo_calibration_file.h"
#include "core/sensors/aravis_source.h"

namespace sightline {
namespace {

// Longest single wait on one camera, so that both streams are served in turn.
constexpr std::chrono::microseconds kSideSlice(10000);

const char* kSideName[2] = {"left", "right"};

}  // namespace

AravisStereoSource::AravisStereoSource(std::string left_id, std::string right_id,
                                       AravisOptions camera_options,
                                       AravisStereoOptions stereo_options)
    : LiveSource(camera_options.live),
      left_id_(std::move(left_id)),
      right_id_(std::move(right_id)),
      options_(std::move(camera_options)),
      stereo_options_(std::move(stereo_options)) {}

AravisStereoSource::~AravisStereoSource() { Close(); }

AravisCameraSettings AravisStereoSource::left_settings() const {
  std::lock_guard<std::mutex> lock(settings_mutex_);
  return settings_[0];
}

AravisCameraSettings AravisStereoSource::right_settings() const {
  std::lock_guard<std::mutex> lock(settings_mutex_);
  return settings_[1];
}

std::string AravisStereoSource::DeviceLabel() const {
  return "Aravis stereo pair '" + left_id_ + "' + '" + right_id_ + "'";
}

Status AravisStereoSource::Connect(SourceInfo* info) {
  std::string error;
  if (!options_.IsValid(&error)) return InvalidArgument(error);
  if (!stereo_options_.IsValid(&error)) return InvalidArgument(error);
  if (left_id_.empty() || right_id_.empty() || left_id_ == right_id_) {
    return InvalidArgument(DeviceLabel() + ": a stereo pair needs two different camera ids");
  }
  std::optional<StereoRig> rig;
  if (!stereo_options_.calibration_file.empty()) {
    StatusOr<StereoRig> read = ReadStereoCalibration(stereo_options_.calibration_file);
    if (!read.ok()) {
      return read.status().WithContext(DeviceLabel() + ", sensors.aravis.stereo.calibration_file");
    }
    rig = *read;
  }
  const std::string ids[2] = {left_id_, right_id_};
  for (int side = 0; side < 2; ++side) {
    cameras_[side] = std::make_unique<AravisCamera>();
    Status s = cameras_[side]->Open(ids[side], options_);
    if (!s.ok()) return s.WithContext(DeviceLabel() + ", " + kSideName[side] + " camera");
  }
  const AravisCameraSettings& l = cameras_[0]->settings();
  const AravisCameraSettings& r = cameras_[1]->settings();
  if (l.width != r.width || l.height != r.height || l.pixel_format != r.pixel_format) {
    return InvalidArgument(DeviceLabel() + ": left streams " + std::to_string(l.width) + "x" +
                           std::to_string(l.height) + " " + l.pixel_format + " but right " +
                           std::to_string(r.width) + "x" + std::to_string(r.height) + " " +
                           r.pixel_format + "; a stereo pair needs equal sizes and formats");
  }
  if (rig && (rig->left.width != static_cast<int>(l.width) ||
              rig->left.height != static_cast<int>(l.height))) {
    return InvalidArgument(DeviceLabel() + ": the calibration " + stereo_options_.calibration_file +
                           " is for " + std::to_string(rig->left.width) + "x" +
                           std::to_string(rig->left.height) + " images but the cameras stream " +
                           std::to_string(l.width) + "x" + std::to_string(l.height));
  }
  {
    std::lock_guard<std::mutex> lock(settings_mutex_);
    settings_[0] = l;
    settings_[1] = r;
  }
  pairer_ = std::make_unique<TimestampPairer<AravisImage>>(
      stereo_options_.pair_tolerance_ms * 1e-3, static_cast<size_t>(options_.buffer_count));
  unpaired_reported_ = 0;
  next_trigger_ = std::chrono::steady_clock::now();
  last_image_[0] = last_image_[1] = next_trigger_;

  info->format = "Aravis stereo pair";
  info->path = "aravis://" + l.device_id + "," + r.device_id;
  info->kind = SourceKind::kStereo;
  DescribeAravisCamera(l, info);
  info->notes.push_back("right: " + r.vendor + " " + r.model + ", serial " + r.serial + ", id " +
                        r.device_id);
  info->notes.push_back("pairs within " + std::to_string(stereo_options_.pair_tolerance_ms) +
                        " ms by " + stereo_options_.pair_clock + " clock");
  if (rig) {
    info->stereo = rig;
    info->notes.push_back("stereo calibration from " + stereo_options_.calibration_file);
  } else {
    info->notes.push_back(
        "no stereo calibration: set sensors.aravis.stereo.calibration_file=FILE or "
        "aravis://LEFT,RIGHT?calibration_file=FILE");
  }
  return Status::Ok();
}

StatusOr<std::optional<CapturedFrame>> AravisStereoSource::ReadFrame(
    std::chrono::milliseconds timeout) {
  using Clock = std::chrono::steady_clock;
  const Clock::time_point deadline = Clock::now() + timeout;
  const bool by_device = stereo_options_.pair_clock == "device";
  int side = 0;
  while (true) {
    const Clock::time_point now = Clock::now();
    if (options_.trigger == "software" && now >= next_trigger_) {
      for (int s = 0; s < 2; ++s) {
        Status fired = cameras_[s]->SoftwareTrigger();
        if (!fired.ok()) return fired.WithContext(DeviceLabel());
      }
      const auto period = std::chrono::duration_cast<Clock::duration>(
          std::chrono::duration<double>(1.0 / options_.frame_rate_hz));
      next_trigger_ = std::max(next_trigger_ + period, now);
    }
    Clock::time_point wait_until = std::min(deadline, now + kSideSlice);
    if (options_.trigger == "software") wait_until = std::min(wait_until, next_trigger_);
    const auto wait =
        std::max(std::chrono::duration_cast<std::chrono::microseconds>(wait_until - now),
                 std::chrono::microseconds(0));
    StatusOr<AravisPop> pop = cameras_[side]->Pop(wait);
    if (!pop.ok()) {
      return Status(pop.status().code(),
                    DeviceLabel() + ": " + kSideName[side] + " camera: " + pop.status().message());
    }
    if (pop->incomplete > 0) CountIncomplete(pop->incomplete);
    if (pop->buffer_timeouts > 0) CountTimeouts(pop->buffer_timeouts);
    if (pop->device_frames_lost > 0) CountDeviceFramesLost(pop->device_frames_lost);
    if (pop->image) last_image_[side] = Clock::now();
    const auto silent_limit = std::chrono::milliseconds(live_options().stall_timeout_ms / 2);
    if (silent_limit.count() > 0) {
      const Clock::time_point after = Clock::now();
      for (int s = 0; s < 2; ++s) {
        if (after - last_image_[s] > silent_limit && after - last_image_[1 - s] < silent_limit) {
          return Unavailable(DeviceLabel() + ": " + kSideName[s] + " camera '" +
                             cameras_[s]->label_id() + "' stopped delivering frames (none for " +
                             std::to_string(silent_limit.count()) +
                             " ms while the other camera streams)");
        }
      }
    }
    if (pop->image) {
      const double time = by_device ? pop->image->device_time_s : pop->image->arrival_host_time_s;
      std::optional<std::pair<AravisImage, AravisImage>> pair =
          pairer_->Add(side, time, std::move(*pop->image));
      if (pairer_->unpaired() > unpaired_reported_) {
        CountUnpaired(pairer_->unpaired() - unpaired_reported_);
        unpaired_reported_ = pairer_->unpaired();
      }
      if (pair) {
        CapturedFrame captured;
        StereoFrame stereo;
        stereo.stamp.sensor_time_s = pair->first.device_time_s;
        stereo.left = std::move(pair->first.image);
        stereo.right = std::move(pair->second.image);
        captured.frame = std::move(stereo);
        captured.device_frame_id = pair->first.frame_id;
        captured.arrival_host_time_s =
            std::max(pair->first.arrival_host_time_s, pair->second.arrival_host_time_s);
        return std::optional<CapturedFrame>(std::move(captured));
      }
    }
    side = 1 - side;
    if (Clock::now() >= deadline) return std::optional<CapturedFrame>();
  }
}

void AravisStereoSource::Disconnect(bool device_lost) {
  for (auto& camera : cameras_) {
    if (camera) camera->Close(device_lost);
    camera.reset();
  }
  pairer_.reset();
}

}  // namespace sightline
