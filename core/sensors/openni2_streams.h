// OpenNI2 stream helpers for OpenNi2Source: video modes, frame conversion and hot-plug events.
// Internal to core/sensors (includes OpenNI.h); compiled only with OpenNI2.
#pragma once

#include <OpenNI.h>

#include <mutex>
#include <opencv2/core.hpp>
#include <string>

#include "core/common/status.h"

namespace sightline {

// Indices of the two streams of an RGB-D device.
inline constexpr int kDepth = 0;
inline constexpr int kColor = 1;
// "depth" or "colour".
const char* StreamName(int stream);

// "640x480@30 DEPTH_1_MM".
std::string VideoModeText(const openni::VideoMode& mode);
// Raw depth units per metre of a depth pixel format (1000 for DEPTH_1_MM); 0 for others.
double DepthUnitsPerMetre(openni::PixelFormat format);
// Whether Sightline converts this pixel format for the depth or colour stream.
bool StreamFormatSupported(int stream, openni::PixelFormat format);

// Selects the mode with the given size and rate (0 = the stream's current value) in a format
// Sightline converts, preferring DEPTH_1_MM / RGB888. InvalidArgument lists the device's modes.
Status SelectVideoMode(openni::VideoStream* stream, int which, int width, int height, int fps,
                       const std::string& who);

// A colour frame (RGB888, GRAY8, YUYV, YUV422) as CV_8UC3 BGR; empty for other formats.
cv::Mat ColorFrameToBgr(const openni::VideoFrameRef& frame);

// Watches OpenNI2's disconnect and error events for one device URI. The callbacks arrive on
// OpenNI2's threads; Gone() may be called from any thread.
class OpenNi2DeviceWatcher : public openni::OpenNI::DeviceDisconnectedListener,
                             public openni::OpenNI::DeviceStateChangedListener {
 public:
  explicit OpenNi2DeviceWatcher(std::string uri) : uri_(std::move(uri)) {}

  void onDeviceDisconnected(const openni::DeviceInfo* info) override;
  void onDeviceStateChanged(const openni::DeviceInfo* info, openni::DeviceState state) override;
  // Why the device is gone, or "" while it is fine.
  std::string Gone() const;

 private:
  void Set(const std::string& reason);
  const std::string uri_;
  mutable std::mutex mutex_;
  std::string reason_;
};

}  // namespace sightline
