// Writers that store frames in the layouts Sightline's readers open (core/io/dataset.h), one
// sensor folder inside a recording folder:
//
//   DIR/rgbd/    TUM RGB-D: rgb/NNNNNN.png, depth/NNNNNN.png (16-bit, metres x 5000, 0 = none),
//                rgb.txt, depth.txt, associations.txt, camera.yaml
//   DIR/stereo/  EuRoC MAV: mav0/cam0|cam1/data/<ns>.png, data.csv, sensor.yaml
//   DIR/mono/    image folder: NNNNNN.png, times.txt ("time filename"), camera.yaml
//
// Stereo uses the EuRoC layout rather than KITTI's because its frames are defined by the index
// files alone (KITTI lists image_0/ and needs times.txt to match it exactly), so a recording cut
// between two file operations is still readable. Every image file appears atomically and every
// index line is appended after the images it names, so each listed frame is complete.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "core/common/frame.h"
#include "core/common/status.h"
#include "core/io/source.h"

namespace sightline {

// How frames are stored.
struct FrameWriterSettings {
  int png_compression = 1;  // zlib level 0-9.
  bool sync = true;         // fsync every image and index line (crash safety over speed).
};

// Stores the frames of one sensor. Not thread-safe: one writer thread calls it.
class FrameWriter {
 public:
  virtual ~FrameWriter() = default;
  // Writes frame number `index` (0, 1, 2, ... in recording order) completely: the images, then
  // the index lines. On failure the recording still ends at the previous frame.
  virtual Status Write(const Frame& frame, int64_t index) = 0;
  // Where the frames go, e.g. "DIR/rgbd".
  virtual const std::string& folder() const = 0;
  // The reader's format name ("TUM RGB-D", "EuRoC MAV", "image folder").
  virtual const char* format() const = 0;
  // Completes what is written after the last frame (a bag's index). Folder layouts are
  // complete after every frame. Called once by Recorder::Stop.
  virtual Status Finish() { return Status::Ok(); }
  // Bytes of images and index lines written so far.
  int64_t bytes_written() const { return bytes_; }
  // Facts a user should know, e.g. that a calibration is nominal.
  const std::vector<std::string>& notes() const { return notes_; }

 protected:
  int64_t bytes_ = 0;
  std::vector<std::string> notes_;
};

// The folder name under a recording for a kind of source: "rgbd", "stereo", "mono".
const char* SensorFolderName(SourceKind kind);

// Creates DIR/<sensor>/ with its calibration and empty index files for frames like `info`
// describes (kind, size, calibration). InvalidArgument for point-cloud sources; Unavailable
// (naming the file) when a folder or file cannot be written.
StatusOr<std::unique_ptr<FrameWriter>> CreateFrameWriter(const std::string& dir,
                                                         const SourceInfo& info,
                                                         const FrameWriterSettings& settings);

}  // namespace sightline
