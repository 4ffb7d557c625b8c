#include "core/pipeline/mono_inputs.h"

#include <filesystem>

#include "core/io/hand_eye_file.h"
#include "core/mono/metric_motion.h"

namespace sightline {

namespace fs = std::filesystem;

bool MonoSlamRunOptions::IsValid(std::string* error) const {
  auto fail = [&](const std::string& m) {
    if (error) *error = "mono.run." + m;
    return false;
  };
  if (max_frames < 0) return fail("max_frames must be >= 0");
  if (stride < 1) return fail("stride must be >= 1");
  if (metric_source != "auto" && metric_source != "arm" && metric_source != "arm_stream" &&
      metric_source != "ground_truth" && metric_source != "none") {
    return fail("metric_source must be auto, arm, arm_stream, ground_truth or none");
  }
  if (scale_interval_frames < 1) return fail("scale_interval_frames must be >= 1");
  if (scale_pairs != "keyframes" && scale_pairs != "frames") {
    return fail("scale_pairs must be keyframes or frames");
  }
  if (!(gt_tolerance_s >= 0)) return fail("gt_tolerance_s must be >= 0");
  return true;
}

OptionTable<MonoSlamRunOptions> MonoSlamRunOptions::Describe() {
  using O = MonoSlamRunOptions;
  return OptionTable<O>("mono.run")
      .Int("max_frames", &O::max_frames, "frames", 0, 1e9, 1, "Frames read; 0 = all.")
      .Int("stride", &O::stride, "frames", 1, 1000, 1,
           "Process every stride-th frame read, from the first (1 = all): a keyframe-rate "
           "sequence from a full-rate recording.")
      .Choice("metric_source", &O::metric_source,
              {"auto", "arm", "arm_stream", "ground_truth", "none"},
              "Measured motion for the metric scale: the arm's recorded poses (arm_poses.txt), "
              "the arm's poses streamed live to the button pipeline's arm-target server "
              "(arm_stream), ground-truth displacements, or none. auto: the recorded arm poses "
              "when arm_poses.txt is there; else, for the button pipeline while serving, the "
              "stream; else (mono-slam) ground truth.")
      .String("arm_poses", &O::arm_poses,
              "arm_poses.txt (base_from_end_effector, TUM); empty = beside the sensor folder.")
      .String("hand_eye", &O::hand_eye,
              "hand_eye.yaml (end_effector_from_camera); empty = beside arm_poses (for arm_stream: "
              "beside the images); none = identity.")
      .Choice("scale_pairs", &O::scale_pairs, {"keyframes", "frames"},
              "Displacement pairs between consecutive keyframes (poses refined by bundle "
              "adjustment) or between tracked frames scale_interval_frames apart.")
      .Int("scale_interval_frames", &O::scale_interval_frames, "frames", 1, 10000, 1,
           "Frames spanned by one displacement pair of the scale estimators.")
      .Double("gt_tolerance_s", &O::gt_tolerance_s, "s", 0, 1, 0.005,
              "A pose belongs to a frame when this close in time.");
}

std::string FindBeside(const std::string& path, const std::string& name) {
  for (const fs::path& dir : {fs::path(path), fs::path(path).parent_path()}) {
    if (fs::exists(dir / name)) return (dir / name).string();
  }
  return "";
}

StatusOr<OpenedMono> OpenMono(const std::string& path) {
  StatusOr<std::unique_ptr<Source>> opened = OpenDataset(path, SourceKind::kMono);
  for (SourceKind kind : {SourceKind::kStereo, SourceKind::kRgbd}) {
    if (opened.ok()) break;
    if (StatusOr<std::unique_ptr<Source>> other = OpenDataset(path, kind); other.ok()) {
      opened = std::move(other);
    }
  }
  if (!opened.ok()) return opened.status();
  OpenedMono out;
  out.source = std::move(*opened);
  const SourceInfo& info = out.source->info();
  if (info.camera) {
    out.camera = *info.camera;
  } else if (info.stereo) {
    out.camera = info.stereo->left;
  } else {
    return FailedPrecondition(path + ": the source has no camera calibration (camera.yaml)");
  }
  if (const Trajectory* gt = out.source->ground_truth(); gt != nullptr && !gt->empty()) {
    out.ground_truth = *gt;
  } else if (const std::string file = (fs::path(info.path) / "groundtruth.txt").string();
             fs::exists(file)) {
    // Image folders (the simulator's mono/) keep their camera's ground truth beside the images.
    StatusOr<Trajectory> gt = ReadTumTrajectory(file);
    if (!gt.ok()) return gt.status();
    out.ground_truth = *gt;
  }
  return out;
}

std::optional<MonoFrame> MonoFrameOf(const Frame& frame) {
  if (const MonoFrame* m = std::get_if<MonoFrame>(&frame)) return *m;
  if (const StereoFrame* s = std::get_if<StereoFrame>(&frame)) {
    MonoFrame mono;
    mono.stamp = s->stamp;
    mono.image = s->left;
    return mono;
  }
  if (const RgbdFrame* r = std::get_if<RgbdFrame>(&frame); r != nullptr && !r->color.empty()) {
    MonoFrame mono;
    mono.stamp = r->stamp;
    mono.image = r->color;
    return mono;
  }
  return std::nullopt;
}

StatusOr<std::optional<MonoFrame>> NextMonoFrame(Source& source, const std::string& path) {
  const Status grabbed = source.Grab();
  if (grabbed.code() == StatusCode::kOutOfRange) return std::optional<MonoFrame>();
  if (!grabbed.ok()) return grabbed;
  StatusOr<Frame> frame = source.Retrieve();
  if (!frame.ok()) return frame.status();
  std::optional<MonoFrame> mono = MonoFrameOf(*frame);
  if (!mono) {
    return InvalidArgument(path +
                           " gives no mono images, stereo pairs or colour images (RGB-D without "
                           "colour?)");
  }
  return mono;
}

StatusOr<Trajectory> LoadMetricCameraPoses(const std::string& path, const MonoSlamRunOptions& run,
                                           const std::optional<Trajectory>& ground_truth,
                                           std::string* source, const Trajectory* source_arm) {
  *source = "none";
  Trajectory metric;
  if (run.metric_source == "none") return metric;
  if (run.metric_source == "arm_stream") {
    return FailedPrecondition(
        "mono.run.metric_source = arm_stream: only the button pipeline, serving, receives the "
        "arm's pose stream");
  }
  const std::string arm_path =
      run.arm_poses.empty() ? FindBeside(path, "arm_poses.txt") : run.arm_poses;
  const bool from_source = arm_path.empty() && source_arm != nullptr && !source_arm->empty();
  const bool use_arm = run.metric_source == "arm" ||
                       (run.metric_source == "auto" && (!arm_path.empty() || from_source));
  if (use_arm) {
    if (arm_path.empty() && !from_source)
      return NotFound(path + ": no arm_poses.txt beside the images (mono.run.arm_poses)");
    Trajectory arm;
    if (from_source) {
      arm = *source_arm;
    } else {
      StatusOr<Trajectory> read = ReadTumTrajectory(arm_path);
      if (!read.ok()) return read.status();
      arm = std::move(*read);
    }
    Eigen::Isometry3d ee_from_camera = Eigen::Isometry3d::Identity();
    if (run.hand_eye != "none") {
      std::string hand_eye = run.hand_eye;
      if (hand_eye.empty() && from_source) {
        hand_eye = FindBeside(path, "hand_eye.yaml");
        if (hand_eye.empty()) {
          return NotFound(path +
                          ": no hand_eye.yaml beside the recording for its arm poses "
                          "(mono.run.hand_eye; \"none\" = the camera is the end effector)");
        }
      }
      if (hand_eye.empty())
        hand_eye = (fs::path(arm_path).parent_path() / "hand_eye.yaml").string();
      StatusOr<HandEye> read = ReadHandEyeFile(hand_eye);
      if (!read.ok()) return read.status();
      ee_from_camera = read->end_effector_from_camera;
    }
    for (const TimedPose& p : arm.poses())
      metric.Add(p.time_s, p.world_from_sensor * ee_from_camera);
    *source = "arm";
    return metric;
  }
  if (ground_truth) {
    metric = *ground_truth;
    *source = "ground_truth";
  } else if (run.metric_source == "ground_truth") {
    return NotFound(path + ": mono.run.metric_source = ground_truth but the dataset has none");
  }
  return metric;
}

std::vector<ScalePair> KeyFrameScalePairs(const MapSnapshot& map, const Trajectory& metric,
                                          double tolerance_s) {
  std::vector<DualPose> dual;
  for (size_t k = 0; k < map.keyframes.size(); ++k) {
    DualPose d;
    d.frame = static_cast<int64_t>(k);
    d.map_from_camera = map.keyframes[k].map_from_camera;
    if (std::optional<size_t> i = metric.Nearest(map.keyframes[k].time_s, tolerance_s)) {
      d.metric_from_camera = metric.poses()[*i].world_from_sensor;
    }
    dual.push_back(d);
  }
  return DisplacementPairs(dual, 1);
}

}  // namespace sightline
