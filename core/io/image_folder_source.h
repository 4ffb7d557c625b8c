// Reader for a plain folder of images (png, jpg, ...) as a monocular recording.
#pragma once

#include <string>
#include <vector>

#include "core/io/recorded_source.h"

namespace sightline {

// A folder of images, in natural name order ("img2" before "img10"), as mono frames (CV_8UC1
// for grey images, CV_8UC3 BGR for colour ones).
//
// Timestamps come from times.txt or timestamps.txt beside the images: either one time per line
// (one line per image, in name order) or "time filename" lines, which then also define the frames
// and their order. Without such a file, time = index / rate, with rate_hz from camera.yaml or
// the constructor's default, and info().notes says so. camera.yaml (see camera_yaml.h) gives the
// intrinsics; without it info().camera is empty.
// Images may differ in size (a folder of photos); info().width/height is the first image's.
//
//   ImageFolderSource source("../shared/data/button_panels/test_panels");
//   if (Status s = source.Open(); !s.ok()) return s;
//   while (source.Grab().ok()) auto frame = source.Retrieve();  // MonoFrame
class ImageFolderSource : public RecordedSource {
 public:
  // `default_rate_hz` is used to synthesize times when the folder has none.
  explicit ImageFolderSource(std::string folder, double default_rate_hz = 30.0)
      : folder_(std::move(folder)), default_rate_hz_(default_rate_hz) {}

  // File readers need no driver: always Ok.
  static Status Available() { return Status::Ok(); }

  // Lists the images, reads times and camera.yaml, decodes the first image.
  Status Open() override;

  // Full paths of the frames' images, in frame order.
  const std::vector<std::string>& files() const { return files_; }

 protected:
  // Decodes frame `index`.
  StatusOr<Frame> Load(int64_t index) override;
  std::string FrameFile(int64_t index) const override;

 private:
  std::string folder_;
  double default_rate_hz_;
  std::vector<std::string> files_;
};

}  // namespace sightline
