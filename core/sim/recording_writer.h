// Writes simulated frames as a Sightline recording: one folder per sensor, each in a format the
// existing readers open (core/io/dataset.h), with index files flushed after every frame so an
// interrupted recording is still readable.
//
//   DIR/rgbd/    TUM RGB-D: rgb/NNNNNN.png, depth/NNNNNN.png (16-bit, metres x 5000, 0 = none),
//                rgb.txt, depth.txt, associations.txt, groundtruth.txt (colour camera in the map
//                frame), camera.yaml
//   DIR/stereo/  KITTI odometry: image_0/ (left), image_1/ (right), calib.txt (P0, P1),
//                times.txt, poses.txt (left camera in the frame of the left camera at frame 0,
//                as KittiSource reads it), groundtruth.txt (left camera in the map frame, TUM)
//   DIR/mono/    image folder: NNNNNN.png, times.txt, camera.yaml, groundtruth.txt (TUM, map)
#pragma once

#include <Eigen/Geometry>
#include <fstream>
#include <memory>
#include <opencv2/core.hpp>
#include <optional>
#include <string>
#include <vector>

#include "core/common/camera.h"
#include "core/common/status.h"

namespace sightline::sim {

// What a recording holds.
struct RecordingSetup {
  std::string dir;                           // Created if missing.
  std::optional<PinholeCamera> rgbd_camera;  // Set to write DIR/rgbd.
  double rgbd_max_depth_m = 4.5;
  std::optional<StereoRig> stereo_rig;       // Set to write DIR/stereo.
  std::optional<PinholeCamera> mono_camera;  // Set to write DIR/mono.
  double rate_hz = 30;
  int png_compression = 1;  // zlib level 0-9.
};

// The TUM line "t tx ty tz qx qy qz qw" of a pose, formatted as WriteTumTrajectory does.
std::string TumLine(double time_s, const Eigen::Isometry3d& pose);
// The KITTI line (top 3x4 of the pose, row-major), formatted as WriteKittiTrajectory does.
std::string KittiLine(const Eigen::Isometry3d& pose);

// Writes a recording frame by frame. Frames must be written in order, once per sensor.
class RecordingWriter {
 public:
  // Creates the folders and the calibration files, opens the index files.
  static StatusOr<std::unique_ptr<RecordingWriter>> Create(const RecordingSetup& setup);

  // Colour (CV_8UC3 BGR) and depth (CV_32FC1 metres, NaN = none) with the camera's true pose.
  Status WriteRgbd(int frame, double time_s, const cv::Mat& color, const cv::Mat& depth_m,
                   const Eigen::Isometry3d& world_from_camera);
  // A rectified pair (8-bit) with the left camera's true pose.
  Status WriteStereo(int frame, double time_s, const cv::Mat& left, const cv::Mat& right,
                     const Eigen::Isometry3d& world_from_left);
  // One image with the camera's true pose.
  Status WriteMono(int frame, double time_s, const cv::Mat& image,
                   const Eigen::Isometry3d& world_from_camera);
  // Flushes and closes every file.
  Status Close();

  // Paths written so far, relative to the recording folder (images counted, not listed).
  std::vector<std::string> Files() const;
  int64_t images_written() const { return images_; }

 private:
  RecordingWriter() = default;
  Status WritePng(const std::string& relative, const cv::Mat& image);
  Status OpenIndex(const std::string& relative, std::ofstream* out, const std::string& header);
  Status Flush(std::ofstream* out, const std::string& relative);

  RecordingSetup setup_;
  std::vector<std::string> files_;
  int64_t images_ = 0;
  std::ofstream rgb_txt_, depth_txt_, associations_txt_, rgbd_gt_;
  std::ofstream stereo_times_, stereo_poses_, stereo_gt_;
  std::ofstream mono_times_, mono_gt_;
  std::optional<Eigen::Isometry3d> first_left_from_world_;
};

}  // namespace sightline::sim
