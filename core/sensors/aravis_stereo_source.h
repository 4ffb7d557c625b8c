// Two Aravis cameras as one stereo source: frames paired by timestamp within a tolerance.
#pragma once

#include <chrono>
#include <memory>
#include <mutex>
#include <string>

#include "core/sensors/aravis_camera.h"
#include "core/sensors/aravis_options.h"
#include "core/sensors/live_source.h"
#include "core/sensors/timestamp_pairer.h"

namespace sightline {

// A stereo pair of machine-vision cameras (URI "aravis://LEFT_ID,RIGHT_ID"). Both cameras get
// the same AravisOptions; with trigger=software the host triggers both back to back at
// frame_rate_hz, with trigger=hardware both wait for the shared pulse. Left and right frames
// whose timestamps (stereo options: device or host clock) differ by at most pair_tolerance_ms
// form a StereoFrame; the others are dropped and counted in stats().unpaired_frames. When either
// camera is lost (an error, or silent for half the stall timeout while the other streams), the
// status names it, and both are closed and reconnected together.
//
//   AravisStereoSource rig("Basler-1", "Basler-2", camera_options, stereo_options);
//   if (Status s = rig.Open(); !s.ok()) return s;
//   while (rig.Grab().ok()) Use(std::get<StereoFrame>(*rig.Retrieve()));
class AravisStereoSource : public LiveSource {
 public:
  AravisStereoSource(std::string left_id, std::string right_id, AravisOptions camera_options,
                     AravisStereoOptions stereo_options);
  ~AravisStereoSource() override;

  // What each camera accepted at the last (re)connect; thread-safe.
  AravisCameraSettings left_settings() const;
  AravisCameraSettings right_settings() const;

 protected:
  Status Connect(SourceInfo* info) override;
  StatusOr<std::optional<CapturedFrame>> ReadFrame(std::chrono::milliseconds timeout) override;
  void Disconnect(bool device_lost) override;
  std::string DeviceLabel() const override;

 private:
  const std::string left_id_, right_id_;
  const AravisOptions options_;
  const AravisStereoOptions stereo_options_;
  std::unique_ptr<AravisCamera> cameras_[2];
  std::unique_ptr<TimestampPairer<AravisImage>> pairer_;
  uint64_t unpaired_reported_ = 0;
  std::chrono::steady_clock::time_point next_trigger_;
  std::chrono::steady_clock::time_point last_image_[2];  // Per camera, to name a silent one.
  mutable std::mutex settings_mutex_;
  AravisCameraSettings settings_[2];
};

}  // namespace sightline
