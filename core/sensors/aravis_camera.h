// One Aravis camera connection used by the Aravis sources' capture threads (internal to
// core/sensors; no Aravis header leaks out of aravis_camera.cpp).
#pragma once

#include <chrono>
#include <cstdint>
#include <memory>
#include <mutex>
#include <opencv2/core.hpp>
#include <optional>
#include <string>
#include <vector>

#include "core/common/status.h"
#include "core/sensors/aravis_options.h"
#include "core/sensors/device_info.h"

namespace sightline {

// What a camera accepted, read back after configuration.
struct AravisCameraSettings {
  std::string device_id;  // As Aravis names the device, e.g. "Aravis-Fake-GV01".
  std::string vendor, model, serial;
  std::string protocol;       // "GigEVision", "USB3Vision", "Fake".
  std::string pixel_format;   // GenICam name.
  int width = 0, height = 0;  // [px]
  double exposure_us = 0;
  double gain_db = 0;
  double frame_rate_hz = 0;
  std::string trigger;       // "free", "software", "hardware:Line1".
  unsigned packet_size = 0;  // GigE only [bytes].
};

// One image taken from the camera's stream.
struct AravisImage {
  cv::Mat image;                   // Converted (see ConvertCameraImage()).
  int64_t frame_id = -1;           // The device's id, unwrapped from 16 bits to a monotonic count.
  double device_time_s = 0;        // Device timestamp.
  double arrival_host_time_s = 0;  // HostTimeS() when Aravis received the frame.
};

// What one Pop() produced.
struct AravisPop {
  std::optional<AravisImage> image;  // Set for a complete frame.
  uint64_t incomplete = 0;           // Buffers with missing packets or other damage.
  uint64_t buffer_timeouts = 0;      // Buffers whose packets stopped arriving.
  uint64_t device_frames_lost = 0;   // Frame ids skipped by the device.
};

// Opens, configures and streams one camera. Not thread-safe: one capture thread uses it.
class AravisCamera {
 public:
  AravisCamera();
  ~AravisCamera();
  AravisCamera(const AravisCamera&) = delete;
  AravisCamera& operator=(const AravisCamera&) = delete;

  // Opens `device_id` ("" = first camera; a device id, serial-based id or IP address), applies
  // `options` with range checks, fills the buffer pool and starts acquisition. Errors:
  // kUnavailable when the camera is absent, kInvalidArgument for settings it refuses.
  Status Open(const std::string& device_id, const AravisOptions& options);
  // Waits at most `timeout` for a buffer. kUnavailable once the camera lost control.
  StatusOr<AravisPop> Pop(std::chrono::microseconds timeout);
  // Fires the software trigger.
  Status SoftwareTrigger();
  // Stops and releases the camera. After a loss it skips the stop command, which would wait
  // for the absent camera's answer. Takes several seconds for a vanished GigE camera.
  void Close(bool device_lost);

  const AravisCameraSettings& settings() const { return settings_; }
  // The device id given to Open(), or the one found for "".
  const std::string& label_id() const { return label_id_; }

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  AravisCameraSettings settings_;
  std::string label_id_;
};

// Serialises calls into Aravis' process-wide device list (arv_update_device_list,
// arv_open_device, arv_enable_interface), which is not thread-safe. Aravis keeps that list in
// the library; this lock is the only process-wide state of the Aravis sources.
std::mutex& AravisSystemMutex();

// Cameras Aravis can see now (GigE discovery takes about a second). `include_fake` enables
// Aravis' in-process "Fake" interface first.
std::vector<DeviceInfo> EnumerateAravisCameras(bool include_fake);

}  // namespace sightline
