// One interface for every frame source: dataset readers, recordings and live sensors.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/common/camera.h"
#include "core/common/frame.h"
#include "core/common/status.h"
#include "core/common/trajectory.h"

namespace sightline {

// What kind of frames a source yields.
enum class SourceKind { kRgbd, kStereo, kMono, kCloud };
const char* SourceKindName(SourceKind kind);  // "RGB-D", "stereo", "mono", "point cloud".

// What a source is and what it can do; filled by Open().
struct SourceInfo {
  std::string format;  // "TUM RGB-D", "EuRoC MAV", "KITTI odometry", "image folder", "PCD".
  std::string path;    // What was opened.
  SourceKind kind = SourceKind::kMono;
  int64_t frame_count = -1;   // -1 for live sources.
  int width = 0, height = 0;  // Pixels (organized clouds: columns x rows).
  double duration_s = 0;      // Last minus first timestamp.
  double rate_hz = 0;         // Nominal frame rate, 0 = unknown.
  bool live = false;          // A sensor rather than a recording.
  bool seekable = false;
  bool has_ground_truth = false;
  std::vector<std::string>
      notes;  // Facts a user should know, e.g. "timestamps synthesized at 10 Hz".
  std::optional<PinholeCamera> camera;  // Mono sources and the left/colour camera.
  std::optional<StereoRig> stereo;      // Stereo sources.
  std::optional<RgbdCalibration> rgbd;  // RGB-D sources.
  // A live source that reads the arm's pose (base_from_end_effector) at each frame's stamp, so
  // that arm_poses() grows frame by frame: where from, as a user reads it ("tf base_link ->
  // end_effector (ros:// arm_base_frame, end_effector_frame)"); "" for none. Recordings carry
  // their arm poses whole (arm_poses()) and leave it empty.
  std::string arm_pose_channel;
};

// A source of frames, in the OpenCV driver manner: Grab() acquires the next frame cheaply,
// Retrieve() decodes it, so several sources can be triggered together before decoding.
//
//   auto source = OpenDataset("../shared/data/kitti_clip1");
//   if (!source.ok()) { report(source.status()); return; }
//   while ((*source)->Grab().ok()) {
//     StatusOr<Frame> frame = (*source)->Retrieve();
//     ...
//   }
//
// Not thread-safe: one thread drives a source at a time.
class Source {
 public:
  virtual ~Source() = default;

  // Opens the source and fills info(). Fails with a message naming the file or field.
  virtual Status Open() = 0;
  virtual const SourceInfo& info() const = 0;

  // Acquires the next frame. OutOfRange at the end of a recording.
  virtual Status Grab() = 0;
  // Decodes the frame acquired by the last successful Grab().
  virtual StatusOr<Frame> Retrieve() = 0;

  // Index of the frame the next Grab() acquires.
  virtual int64_t Position() const = 0;
  // Moves so that the next Grab() acquires frame `index`. Recordings only.
  virtual Status Seek(int64_t index) {
    return FailedPrecondition(info().format + " source cannot seek");
  }
  // Ground-truth poses of the sensor (left / colour camera) in a world frame, if known.
  virtual const Trajectory* ground_truth() const { return nullptr; }
  // The odometry of the platform the sensor rides on (world_from_base), when the recording
  // carries it beside its frames (a ROS bag's nav_msgs/Odometry topic); null otherwise.
  virtual const Trajectory* odometry() const { return nullptr; }
  // The arm's poses (base_from_end_effector) at the frames' stamps, when the recording carries
  // them (a ROS bag's tf); null otherwise.
  virtual const Trajectory* arm_poses() const { return nullptr; }
  // Releases devices and files. Also done by the destructor.
  virtual void Close() {}
};

}  // namespace sightline
