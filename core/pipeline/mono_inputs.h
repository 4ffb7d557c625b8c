// The inputs the monocular pipelines share (mono-slam, button): the mono images of a recording
// (or a stereo recording's left images), its ground truth, and the measured camera poses the
// metric scale comes from (arm_poses.txt times hand_eye.yaml's end_effector_from_camera, or
// ground-truth displacements), with the run options that choose them.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/common/camera.h"
#include "core/common/frame.h"
#include "core/common/status.h"
#include "core/common/trajectory.h"
#include "core/io/dataset.h"
#include "core/mono/scale_estimator.h"
#include "core/mono/slam_map.h"
#include "core/options/option_table.h"

namespace sightline {

// Run-level options of the monocular pipelines. Keys "mono.run.*".
struct MonoSlamRunOptions {
  int max_frames = 0;                  // Frames read; 0 = all.
  int stride = 1;                      // Process every stride-th frame read (1 = all).
  std::string metric_source = "auto";  // auto, arm, arm_stream (button), ground_truth, none.
  std::string arm_poses;               // arm_poses.txt; "" = beside the sensor folder.
  std::string hand_eye;                // hand_eye.yaml; "" = beside arm_poses; "none" = identity.
  std::string scale_pairs = "keyframes";  // Displacements between keyframes or frames.
  int scale_interval_frames = 5;          // Frames per displacement pair (scale_pairs = frames).
  double gt_tolerance_s = 0.02;           // Time association tolerance [s].

  bool IsValid(std::string* error) const;
  static OptionTable<MonoSlamRunOptions> Describe();
};

// The mono images of `path`, or the left images of a stereo recording, or the colour images of
// an RGB-D recording, with the camera.
struct OpenedMono {
  std::unique_ptr<Source> source;
  PinholeCamera camera;
  std::optional<Trajectory> ground_truth;  // The source's, or groundtruth.txt beside the images.
};
StatusOr<OpenedMono> OpenMono(const std::string& path);

// A mono frame, or a stereo frame's left image or an RGB-D frame's colour image as one; nullopt
// for other kinds (and RGB-D frames without colour).
std::optional<MonoFrame> MonoFrameOf(const Frame& frame);

// The next frame as a mono frame (MonoFrameOf); nullopt at the end.
StatusOr<std::optional<MonoFrame>> NextMonoFrame(Source& source, const std::string& path);

// `name` in the folder `path` or its parent; "" when in neither.
std::string FindBeside(const std::string& path, const std::string& name);

// The measured camera poses (metres) the scale comes from, per `run.metric_source`: arm poses
// (arm_poses.txt beside `path` or its parent, times hand_eye.yaml's end_effector_from_camera,
// so base_from_camera) or `ground_truth`. *source says which ("arm", "ground_truth", "none";
// then empty). "arm_stream" is FailedPrecondition: only the serving button pipeline receives the
// arm's pose stream (ButtonPipeline feeds MetricSlamView::AddMeasuredPose).
// Without arm_poses.txt (and mono.run.arm_poses empty), `source_arm` (the source's own arm poses,
// base_from_end_effector, e.g. a ROS bag's tf) stands in for it, hand_eye.yaml then beside `path`.
StatusOr<Trajectory> LoadMetricCameraPoses(const std::string& path, const MonoSlamRunOptions& run,
                                           const std::optional<Trajectory>& ground_truth,
                                           std::string* source,
                                           const Trajectory* source_arm = nullptr);

// Scale pairs between consecutive keyframes of `map` and the metric poses at their times.
std::vector<ScalePair> KeyFrameScalePairs(const MapSnapshot& map, const Trajectory& metric,
                                          double tolerance_s);

}  // namespace sightline
