// A live ROS 1 source: `ros://?image=/camera/rgb/image_color&depth=/camera/depth/image` (RGB-D),
// `ros://?left=/stereo/left/image_rect&right=/stereo/right/image_rect` (stereo) or
// `ros://?image=/camera/image_raw` (mono) subscribes to those topics on the running master
// and yields their frames behind the Source interface. Free of ROS headers (the source is a
// pimpl), so C++20 front ends may include it; it needs ros::init done (sightline-node).
//
// Query keys: image, depth, left, right (topics); info, left_info, right_info (CameraInfo
// topics; default: camera_info beside each image topic); sync = approx (default) or exact;
// slop = the largest stamp difference of an approximate pair [s] (default 0.02); queue = the
// frames that wait for the pipeline (default 4; when full the oldest is dropped and counted);
// wait = how long Open waits for the camera info [s] (default 10; a live-device guard by the
// host clock).
// tf: /tf and /tf_static go into a TfBuffer; keys odom_frame (default odom), base_frame
// (base_link), arm_base_frame (base_link), end_effector_frame (end_effector); tf_wait = how long
// Retrieve waits for a transform covering a frame's stamp [s] (default 0.2; only once tf has
// named the frame); tf_gap = the largest time between two samples interpolated between [s]
// (default 0.5). odometry() and arm_poses() then hold the poses at the frames' stamps so far.
#pragma once

#include <cstdint>
#include <memory>
#include <string>

#include "core/common/status.h"
#include "core/io/source.h"

namespace sightline {

struct RosLiveOptions {
  std::string image, depth, left, right;  // Topics.
  std::string info, left_info, right_info;
  bool exact = false;
  double slop_s = 0.02;
  int queue = 4;
  double wait_s = 10;
  std::string odom_frame = "odom", base_frame = "base_link";
  std::string arm_base_frame = "base_link", end_effector_frame = "end_effector";
  double tf_wait_s = 0.2;
  double tf_gap_s = 0.5;

  SourceKind kind() const;  // kRgbd with depth, kStereo with left/right, else kMono.
};

// Whether `uri` is a ros:// URI.
bool IsRosLiveUri(const std::string& uri);
// The options of a ros:// URI. InvalidArgument naming the key for an unknown key, a bad number,
// a sync other than exact/approx, or a topic set that is none of image[+depth] / left+right.
StatusOr<RosLiveOptions> ParseRosLiveUri(const std::string& uri);

// What a live ROS source saw so far.
struct RosLiveStats {
  int64_t frames = 0;           // Handed to the pipeline.
  int64_t unpaired = 0;         // Images dropped by the time sync (no partner).
  int64_t queue_overflows = 0;  // Synced frames dropped because the pipeline lagged.
  int64_t decode_errors = 0;    // Messages whose encoding could not be decoded.
  int64_t refused = 0;          // Messages whose bytes do not hold what their type declares.
  std::string last_refused;     // "/camera/camera_info: sensor_msgs/CameraInfo: field D ...".
  int64_t tf_missing = 0;       // Frames whose odometry or arm pose tf did not give in time.
};

// A source on live topics (not yet opened). Open fails with FailedPrecondition when ROS is not
// initialised, Unavailable when no camera info came within `wait`.
class RosLiveSource : public Source {
 public:
  explicit RosLiveSource(RosLiveOptions options);
  ~RosLiveSource() override;

  Status Open() override;
  const SourceInfo& info() const override;
  // Waits for the next synced frame; Cancelled when ROS shuts down (Ctrl-C, rosnode kill).
  Status Grab() override;
  StatusOr<Frame> Retrieve() override;
  int64_t Position() const override;
  void Close() override;

  // world_from_base (odom_frame -> base_frame) and base_from_end_effector (arm_base_frame ->
  // end_effector_frame) at the stamps of the frames retrieved so far; null while empty.
  // Read them from the thread that drives the source.
  const Trajectory* odometry() const override;
  const Trajectory* arm_poses() const override;

  RosLiveStats Stats() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// ParseRosLiveUri + RosLiveSource + Open.
StatusOr<std::unique_ptr<Source>> OpenRosLiveSource(const std::string& uri);

}  // namespace sightline
