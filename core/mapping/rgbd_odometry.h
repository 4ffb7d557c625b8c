// Frame-to-keyframe RGB-D visual odometry: the camera's 6-DoF motion from the depth (and, when
// registered, the colour) frames a mapping run already receives, for recordings without wheel
// odometry. Built on OpenCV's rgbd module (dense photometric + depth alignment of Steinbruecker
// et al. 2011, point-to-plane ICP, or both); kept behind this small class so that its headers
// stay out of the mapping chain's.
#pragma once

#include <Eigen/Geometry>
#include <memory>
#include <opencv2/core.hpp>
#include <string>
#include <vector>

#include "core/common/camera.h"
#include "core/common/frame.h"
#include "core/common/status.h"
#include "core/mapping/pose2d.h"
#include "core/options/option_table.h"

namespace sightline {

// Options of the RGB-D odometry. Keys "mapping.pose.rgbd.*".
struct RgbdOdometryOptions {
  std::string method = "rgbd";       // rgbd: photometric + depth (needs colour); icp: depth only,
                                     // point-to-plane; rgbd_icp: both terms.
  double min_depth_m = 0.4;          // Depth readings outside [min, max] are not used [m].
  double max_depth_m = 4.5;          //
  double max_depth_diff_m = 0.07;    // Correspondences farther apart in depth are rejected [m].
  int pyramid_levels = 4;            // Image pyramid levels (coarse to fine alignment).
  int iterations = 10;               // Gauss-Newton iterations per pyramid level.
  double max_points_part = 0.2;      // Fraction of the pixels used per level (OpenCV: 0.07).
  double min_valid_fraction = 0.05;  // A frame with fewer depth pixels in range is not used.
  double min_gray_stddev = 2.0;  // rgbd, rgbd_icp: a colour frame flatter than this (grey levels)
                                 // has no texture and is not used.
  double max_speed_mps = 3.0;    // A step faster than this is a failure [m/s].
  double max_turn_rate_deg_s = 240;  // A step turning faster than this is a failure [deg/s].
  double max_gap_s = 1.0;  // Frames farther apart than this in sensor time are not aligned: the
                           // tracking starts again from the held pose [s].
  bool constant_velocity = true;  // Start each alignment from the last motion, scaled by the time
                                  // between the frames (large steps at low frame rates).
  bool feature_guess = true;      // rgbd, rgbd_icp: start it from ORB features + PnP RANSAC when
                                  // they agree (turns too fast for the pyramid alone).
  int max_features = 500;         // ORB features per frame for that guess.
  int min_feature_inliers = 25;   // PnP inliers the guess needs.
  double keyframe_translation_m = 0.1;  // A frame becomes the reference when it moved this far
  double keyframe_rotation_deg = 5.0;   // or turned this much from it; 0 and 0 = every frame.
                                        // Fewer references, less drift at high frame rates.

  bool IsValid(std::string* error) const;
  static OptionTable<RgbdOdometryOptions> Describe();
};

// One frame's outcome. Data problems (too little depth, a blank image, a diverged or implausible
// alignment, a gap in time) give ok = false with a human `failure`; the pose is then held.
struct RgbdOdometryStep {
  bool ok = false;
  bool first = false;         // The first usable frame: it defines the odometry's world frame.
  bool restarted = false;     // Tracking started again from the held pose (after a gap).
  bool keyframe = false;      // The frame became the reference of the next alignments.
  std::string failure;        // Why the step failed ("" when ok).
  double valid_fraction = 0;  // Depth pixels in range.
  // world_from_camera of the odometry (world = the camera at the first usable frame); after a
  // failure, the last tracked pose.
  Eigen::Isometry3d world_from_camera = Eigen::Isometry3d::Identity();
};

// The odometry of one run. Not thread-safe; one instance per run, many instances per process.
//
//   RgbdOdometry odometry(options);
//   SIGHTLINE_RETURN_IF_ERROR(odometry.Configure(camera));
//   for (...) {
//     StatusOr<RgbdOdometryStep> step = odometry.Track(frame.stamp, frame.depth_m, frame.color);
//     if (!step.ok()) return step.status();       // Misuse: wrong image types, no Configure.
//     if (!step->ok) Log(step->failure);          // Data: the pose is held.
//   }
class RgbdOdometry {
 public:
  explicit RgbdOdometry(RgbdOdometryOptions options = {});
  ~RgbdOdometry();
  RgbdOdometry(const RgbdOdometry&) = delete;
  RgbdOdometry& operator=(const RgbdOdometry&) = delete;

  // Sets the depth camera (its intrinsics are scaled to each frame's depth size). Fails on
  // invalid options or camera, naming the field.
  Status Configure(const PinholeCamera& camera);
  // One frame: depth CV_32FC1 metres (NaN or 0 = none), colour CV_8UC3 BGR or CV_8UC1 (resized to
  // the depth's size; registered to it), optional for method icp. Pixels inside `moving` (depth
  // pixels; e.g. people's boxes) are not used: the alignment assumes a static scene. Decisions
  // on time use `stamp.sensor_time_s` only.
  StatusOr<RgbdOdometryStep> Track(const FrameStamp& stamp, const cv::Mat& depth_m,
                                   const cv::Mat& color, const std::vector<cv::Rect>& moving = {});
  // Forgets the reference, the velocity and the pose.
  void Reset();

  const RgbdOdometryOptions& options() const { return options_; }
  int failures() const { return failures_; }  // Failed steps since Configure() / Reset().

 private:
  struct Impl;
  RgbdOdometryOptions options_;
  std::unique_ptr<Impl> impl_;
  int failures_ = 0;
};

// The floor pose of the robot base under a camera tracked by visual odometry: world_from_base,
// with the world being the base at the odometry's first frame. `base_from_camera` is the camera's
// mounting (rotation from the floor plane, height); the 6-DoF motion is projected onto the floor
// (x, y and the heading of the base's forward axis).
Pose2d FloorPoseOfCamera(const Eigen::Isometry3d& base_from_camera,
                         const Eigen::Isometry3d& odometry_world_from_camera);

}  // namespace sightline
