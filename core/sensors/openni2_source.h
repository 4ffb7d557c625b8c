// OpenNI2 RGB-D cameras (Kinect, Xtion, Carmine, ...) and their .oni recordings, through one
// class: the live device and the recording share the stream setup, pairing and conversion.
#pragma once

#include <chrono>
#include <memory>
#include <string>
#include <vector>

#include "core/sensors/device_info.h"
#include "core/sensors/live_source.h"
#include "core/sensors/openni2_options.h"

namespace sightline {

// An OpenNI2 device (URI = the device's OpenNI URI, "" = first device) or an .oni file (a path
// ending in .oni). Depth and colour streams are started together, registered (depth to colour)
// and synchronised when the device can, and paired into RgbdFrames: colour CV_8UC3 BGR, depth
// CV_32FC1 metres with NaN where the sensor saw nothing, resized to the colour size if needed.
// Intrinsics come from the streams' fields of view.
//
// Devices stream on a capture thread (LiveSource); a device that reports a disconnect or stops
// delivering frames gives a kUnavailable Grab() whose message names the device, and is reopened
// every reconnect_interval_ms until it returns. Recordings play inline: every frame in order,
// OutOfRange at the end (or from the start again with loop), Seek() by frame index.
//
//   OpenNi2Source oni("../shared/data/oni_livingroom/test.oni", OpenNi2Options());
//   if (Status s = oni.Open(); !s.ok()) return s;
//   while (oni.Grab().ok()) Use(std::get<RgbdFrame>(*oni.Retrieve()));
class OpenNi2Source : public LiveSource {
 public:
  OpenNi2Source(std::string uri, OpenNi2Options options);
  ~OpenNi2Source() override;

  // Ok when OpenNI2 initialises (devices may still be absent); else kUnavailable with OpenNI's
  // reason.
  static Status Available();
  // Attached devices as "openni2://URI" entries; empty when OpenNI2 is unavailable.
  static std::vector<DeviceInfo> Enumerate();
  // True for paths ending in ".oni" (any case).
  static bool IsRecordingPath(const std::string& uri);

  // Recordings: the next Grab() delivers frame `index` (0 <= index <= frame_count). Re-opens
  // the file and skips frames, because PlaybackControl::seek crashes Debian's OniFile driver
  // (2.2.0.33). FailedPrecondition for devices.
  Status Seek(int64_t index) override;
  // Also releases this source's hold on the OpenNI2 runtime (kept across reconnects, so that
  // OpenNI2 and its drivers stay loaded while a lost device is awaited).
  void Close() override;

  // Devices: records the open streams to an .oni file with openni::Recorder until
  // StopRecording(), Close() or a disconnect. Callable from the consumer thread while the
  // capture thread runs.
  Status StartRecording(const std::string& oni_path);
  void StopRecording();
  bool recording() const;

 protected:
  Status Connect(SourceInfo* info) override;
  StatusOr<std::optional<CapturedFrame>> ReadFrame(std::chrono::milliseconds timeout) override;
  void Disconnect(bool device_lost) override;
  std::string DeviceLabel() const override;

 private:
  struct Impl;
  static void WaitForPlayerThread(Impl& m);
  const std::string uri_;
  const OpenNi2Options options_;
  const bool is_file_;
  std::unique_ptr<Impl> impl_;
};

}  // namespace sightline
