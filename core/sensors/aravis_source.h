// One GigE Vision / USB3 Vision camera through Aravis, as a live mono source.
#pragma once

#include <chrono>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "core/sensors/aravis_camera.h"
#include "core/sensors/aravis_options.h"
#include "core/sensors/device_info.h"
#include "core/sensors/live_source.h"

namespace sightline {

// A machine-vision camera (URI "aravis://DEVICE_ID"; "aravis://" opens the first camera).
// Frames are MonoFrames: CV_8UC1 for mono formats, CV_8UC3 BGR for Bayer and RGB. The stamp's
// sensor time is the camera's timestamp; last_grabbed().device_frame_id its frame id.
//
//   AravisOptions options;
//   options.exposure_us = 5000;
//   AravisSource camera("Basler-21234567", options);
//   if (Status s = camera.Open(); !s.ok()) return s;   // e.g. kInvalidArgument: gain out of range
//   camera.Grab(); auto frame = camera.Retrieve();
class AravisSource : public LiveSource {
 public:
  AravisSource(std::string device_id, AravisOptions options);
  ~AravisSource() override;

  // Ok when Sightline was built with Aravis (cameras may still be absent).
  static Status Available();
  // Cameras Aravis sees now, as "aravis://ID" URIs. Blocks about a second for GigE discovery.
  static std::vector<DeviceInfo> Enumerate(bool include_fake = false);

  // What the camera accepted at the last (re)connect; thread-safe.
  AravisCameraSettings settings() const;

 protected:
  Status Connect(SourceInfo* info) override;
  StatusOr<std::optional<CapturedFrame>> ReadFrame(std::chrono::milliseconds timeout) override;
  void Disconnect(bool device_lost) override;
  std::string DeviceLabel() const override;

 private:
  const std::string device_id_;
  const AravisOptions options_;
  std::unique_ptr<AravisCamera> camera_;
  std::chrono::steady_clock::time_point next_trigger_;
  mutable std::mutex settings_mutex_;
  AravisCameraSettings settings_;
};

// Fills the fields of SourceInfo shared by the Aravis sources from a camera's settings.
void DescribeAravisCamera(const AravisCameraSettings& settings, SourceInfo* info);

}  // namespace sightline
