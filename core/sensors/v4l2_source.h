// USB webcams through OpenCV's V4L2 backend (opencv_videoio only; never highgui).
#pragma once

#include <chrono>
#include <memory>
#include <string>
#include <vector>

#include "core/options/option_table.h"
#include "core/sensors/device_info.h"
#include "core/sensors/live_source.h"

namespace cv {
class VideoCapture;
}

namespace sightline {

// Webcam settings, keys `sensors.v4l2.*`. Zero keeps the camera's current value.
struct V4l2Options {
  int width = 0;           // Requested width [px].
  int height = 0;          // Requested height [px].
  double fps = 0;          // Requested frame rate [Hz].
  std::string fourcc;      // Pixel format, e.g. "MJPG" or "YUYV"; "" keeps the camera's.
  LiveSourceOptions live;  // Queueing and reconnects.

  bool IsValid(std::string* error) const;
  static OptionTable<V4l2Options> Describe();
};

// A V4L2 capture device (URI "v4l2:///dev/video0" or "v4l2://0"). Frames are MonoFrames with
// BGR images as OpenCV decodes them. What the camera actually accepted (size, rate, format) is
// listed in info().notes, since V4L2 picks the nearest mode instead of refusing. A camera that
// stops without unplugging blocks the capture thread for OpenCV's select timeout (10 s, set by
// OPENCV_VIDEOIO_V4L_SELECT_TIMEOUT), so Close() can take that long; an unplugged one fails at
// once.
//
//   V4l2Source webcam("/dev/video0", V4l2Options());
//   if (Status s = webcam.Open(); !s.ok()) return s;  // kUnavailable names the device
class V4l2Source : public LiveSource {
 public:
  // `device` is a device node ("/dev/video2") or an index ("2").
  V4l2Source(const std::string& device, V4l2Options options);
  ~V4l2Source() override;

  // Ok when at least one /dev/video* node exists; else kUnavailable saying so.
  static Status Available();
  // The /dev/video* nodes, as "v4l2:///dev/videoN" URIs with the driver's card name if known.
  static std::vector<DeviceInfo> Enumerate();
  // "/dev/video2" for "2", the input unchanged otherwise.
  static std::string DevicePath(const std::string& device);

 protected:
  Status Connect(SourceInfo* info) override;
  StatusOr<std::optional<CapturedFrame>> ReadFrame(std::chrono::milliseconds timeout) override;
  void Disconnect(bool device_lost) override;
  std::string DeviceLabel() const override;

 private:
  const std::string path_;
  const V4l2Options options_;
  std::unique_ptr<cv::VideoCapture> capture_;
};

}  // namespace sightline
