// One depth frame through the whole indoor mapping chain of seed 000: person boxes, occupancy
// image, polar scan, wall lines, the pose source (a recording's odometry or RGB-D odometry),
// Manhattan rotation with dead reckoning, map stitching; with per-stage timing. The CLI pipeline
// and the GUI worker both call this.
#pragma once

#include <Eigen/Geometry>
#include <memory>
#include <opencv2/core.hpp>
#include <optional>
#include <string>
#include <vector>

#include "core/common/camera.h"
#include "core/common/frame.h"
#include "core/common/status.h"
#include "core/common/timing.h"
#include "core/mapping/dead_reckoning.h"
#include "core/mapping/depth_person_detector.h"
#include "core/mapping/floor_plane.h"
#include "core/mapping/line_extractor.h"
#include "core/mapping/manhattan_rotation.h"
#include "core/mapping/mapping_types.h"
#include "core/mapping/multi_line_ransac.h"
#include "core/mapping/occupancy_grid_map.h"
#include "core/mapping/occupancy_image.h"
#include "core/mapping/person_boxes.h"
#include "core/mapping/polar_scan.h"
#include "core/mapping/rgbd_odometry.h"
#include "core/mapping/split_and_merge.h"
#include "core/options/option_table.h"

namespace sightline {

// Every option of the mapping chain: keys "mapping.extractor", "mapping.floor.*",
// "mapping.occupancy.*", "mapping.scan.*", "mapping.ransac.*", "mapping.split_merge.*",
// "mapping.rotation.*", "mapping.stitch.*", "mapping.people.*", "mapping.pose.*".
struct MappingOptions {
  std::string extractor = "multi_line_ransac";  // Or "split_and_merge".
  // Where translation and the heading's prediction come from: recording (the input's odometry,
  // MappingInput::odometry), rgbd (RGB-D odometry on the frames), none (heading from walls
  // only, no translation) or auto, decided on the first frame: recording when it carries
  // odometry, else rgbd when it has colour (or mapping.pose.rgbd.method is icp), else none.
  std::string pose_source = "auto";
  RgbdOdometryOptions odometry;  // mapping.pose.rgbd.*
  FloorPlaneOptions floor;
  OccupancyImageOptions occupancy;
  PolarScanOptions scan;
  MultiLineRansacOptions ransac;
  SplitAndMergeOptions split_merge;
  ManhattanRotationOptions rotation;
  OccupancyGridMapOptions stitch;
  PersonDetectorOptions people;

  bool IsValid(std::string* error) const;
  static OptionTable<MappingOptions> Describe();
};

// One frame's input.
struct MappingInput {
  FrameStamp stamp;
  cv::Mat depth_m;  // CV_32FC1 metres, NaN = invalid (any resolution; seed: 320 x 240).
  cv::Mat color;    // BGR, optional; mapping.people.source=hog runs on it.
  // world_from_base of the recording's pose source (wheel odometry, a bag's odometry or tf) at
  // this frame; used when mapping.pose.source is recording (or auto and the first frame has one).
  std::optional<Pose2d> odometry;
  // Ground-truth person boxes; nullopt = unknown (the detector may run, see mapping.people).
  std::optional<std::vector<PersonBox>> people;
};

// Runs the chain frame by frame. One instance per run; not thread-safe (one worker drives it).
//
//   MappingFrameProcessor processor(options);
//   SIGHTLINE_RETURN_IF_ERROR(processor.Configure(floor, camera));
//   for (...) {
//     StatusOr<std::shared_ptr<const MappingFrameResult>> r = processor.Process(input, &timing);
//     if (!r.ok()) return r.status();
//   }
//   processor.map().SaveRos(out_dir);
class MappingFrameProcessor {
 public:
  explicit MappingFrameProcessor(MappingOptions options = {});
  ~MappingFrameProcessor();
  MappingFrameProcessor(const MappingFrameProcessor&) = delete;
  MappingFrameProcessor& operator=(const MappingFrameProcessor&) = delete;

  // Sets the floor plane and the depth camera and restarts the run. Fails on invalid options,
  // plane or camera, naming the field.
  Status Configure(const FloorPlane& floor, const PinholeCamera& camera);
  // One frame. When `timing` is given, adds "people" (if run), "occupancy", "scan", "lines",
  // "odometry" (RGB-D odometry, if run), "rotation" and "stitch" durations to it. Degenerate
  // input (empty or all-invalid depth, no floor, people everywhere, a failed odometry step)
  // gives an ok result whose status says so; a frame whose odometry failed keeps the previous
  // position and is not stitched into the map.
  StatusOr<std::shared_ptr<const MappingFrameResult>> Process(const MappingInput& input,
                                                              TimingStats* timing = nullptr);
  // Forgets poses, reference and map (Configure() does this too).
  void Restart();

  const OccupancyGridMap& map() const { return map_; }
  // Estimated poses (world_from_base) and their times, one per processed frame.
  const std::vector<Pose2d>& trajectory() const { return trajectory_; }
  const std::vector<double>& trajectory_times() const { return times_; }
  // Camera poses (world_from_camera) of the trajectory, for TUM output.
  const std::vector<Eigen::Isometry3d>& camera_trajectory() const { return camera_poses_; }
  // Times the reset rule fired, and why.
  const std::vector<std::string>& reset_log() const { return reset_log_; }
  // The pose source in use: "recording", "rgbd" or "none"; "" before the first frame (auto
  // decides on it).
  const std::string& active_pose_source() const { return active_pose_source_; }
  // Frames whose RGB-D odometry step failed, and why ("frame 12 (t = 2.400 s): ...").
  int odometry_failures() const { return static_cast<int>(odometry_log_.size()); }
  const std::vector<std::string>& odometry_log() const { return odometry_log_; }
  // base_from_camera of the configured floor plane.
  const Eigen::Isometry3d& base_from_camera() const { return base_from_camera_; }
  const MappingOptions& options() const { return options_; }

 private:
  StatusOr<std::vector<PersonBox>> HogPeople(const cv::Mat& color);
  // Drops the depth boxes HOG does not score as people (mapping.people.depth_hog_*).
  void CheckWithHog(const cv::Mat& color, const cv::Size& depth_size,
                    std::vector<PersonBox>* people);
  // The pose source's world_from_base at this frame (nullopt: none); false when the RGB-D
  // odometry failed on it (result->odometry_failure says why).
  StatusOr<bool> SourcePose(const MappingInput& input, MappingFrameResult* result,
                            std::optional<Pose2d>* world_from_base);

  MappingOptions options_;
  bool configured_ = false;
  OccupancyImageBuilder occupancy_;
  PolarScanner scanner_;
  std::unique_ptr<LineExtractor> extractor_;
  std::unique_ptr<HogPersonDetector> detector_;  // Made on first use (loads the SVM).
  DepthPersonDetector depth_people_;
  ManhattanRotation rotation_;
  DeadReckoning odometry_;
  RgbdOdometry visual_odometry_;
  std::string active_pose_source_;
  std::vector<std::string> odometry_log_;
  OccupancyGridMap map_;
  Eigen::Isometry3d base_from_camera_ = Eigen::Isometry3d::Identity();
  Pose2d pose_;
  std::vector<Pose2d> trajectory_;
  std::vector<double> times_;
  std::vector<Eigen::Isometry3d> camera_poses_;
  std::vector<std::string> reset_log_;
  int64_t frames_ = 0;
};

}  // namespace sightline
