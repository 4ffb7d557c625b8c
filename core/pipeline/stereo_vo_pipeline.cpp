#include "core/pipeline/stereo_vo_pipeline.h"

#include <variant>

#include "core/io/stereo_calibration_file.h"
#include "core/sensors/sensor_options.h"

namespace sightline {

bool StereoVoRunOptions::IsValid(std::string* error) const {
  if (subsample < 1) {
    if (error) *error = "stereo.subsample must be >= 1";
    return false;
  }
  if (output_format != "tum" && output_format != "kitti") {
    if (error) *error = "stereo.output_format must be tum or kitti";
    return false;
  }
  if (max_frames < 0) {
    if (error) *error = "stereo.max_frames must be >= 0";
    return false;
  }
  if (!(gt_tolerance_s >= 0)) {
    if (error) *error = "stereo.gt_tolerance_s must be >= 0";
    return false;
  }
  return true;
}

OptionTable<StereoVoRunOptions> StereoVoRunOptions::Describe() {
  using O = StereoVoRunOptions;
  return OptionTable<O>("stereo")
      .Int("subsample", &O::subsample, "frames", 1, 1000, 1,
           "Process every k-th frame (the published subsampling sweep); --subsample K.")
      .Choice("output_format", &O::output_format, {"tum", "kitti"},
              "Format of trajectory.txt; --format kitti.")
      .Int("max_frames", &O::max_frames, "frames", 0, 1e9, 1,
           "Frames read before subsampling; 0 = all.")
      .Double("gt_tolerance_s", &O::gt_tolerance_s, "s", 0, 1, 0.005,
              "A ground-truth pose belongs to a frame when this close in time.")
      .String("calibration_file", &O::calibration_file,
              "Stereo calibration (OpenCV stereo YAML as `sightline-cli calibrate stereo` "
              "writes) used instead of the source's; needed for live pairs (aravis://L,R) "
              "opened without one.");
}

namespace {

// The odometry's stages with a "vo/<stage>_ms" statistic, and where FrameStats keeps each.
struct StageField {
  const char* stage;
  double FrameStats::*ms;
};
constexpr StageField kStages[] = {
    {"rectify", &FrameStats::rectify_ms},   {"pyramid", &FrameStats::pyramid_ms},
    {"tracking", &FrameStats::tracking_ms}, {"detection", &FrameStats::detection_ms},
    {"matching", &FrameStats::matching_ms}, {"ransac", &FrameStats::ransac_ms},
    {"refine", &FrameStats::refine_ms},     {"window", &FrameStats::window_ms}};

// The named statistics of one frame: every count and measure, the times of the stages that ran
// (`ran` holds them; a stage that did not run publishes none, as the run's timing has none).
std::vector<std::pair<std::string, double>> StatValues(const FrameStats& s,
                                                       const TimingStats& ran) {
  std::vector<std::pair<std::string, double>> v = {
      {"vo/tracked", s.tracked},
      {"vo/retracked", s.retracked ? 1 : 0},
      {"vo/anchored", s.anchored},
      {"vo/new_features", s.new_features},
      {"vo/stereo_matches", s.stereo_matches},
      {"vo/correspondences", s.correspondences},
      {"vo/inliers", s.inliers},
      {"vo/ransac_iterations", s.ransac_iterations},
      {"vo/rigidity_failures", s.rigidity_failures},
      {"vo/residual_px", s.residual_px},
      {"vo/disparity_offset_px", s.disparity_offset_px},
      {"vo/window_points", s.window_points},
      {"vo/window_rms_px", s.window_rms_px},
      {"vo/translation_m", s.translation_m},
      {"vo/rotation_deg", s.rotation_deg},
      {"vo/gated", s.gated ? 1 : 0},
      {"vo/turn_searched", s.turn_searched ? 1 : 0}};
  for (const StageField& f : kStages) {
    if (ran.Summary(f.stage).count > 0)
      v.emplace_back(std::string("vo/") + f.stage + "_ms", s.*f.ms);
  }
  v.emplace_back("vo/total_ms", s.total_ms);
  return v;
}

// The rig a source's frames need: stereo.calibration_file's when set, else the source's.
StatusOr<StereoRig> RigFor(const SourceInfo& info, const std::string& calibration_file) {
  if (!calibration_file.empty()) {
    StatusOr<StereoRig> read = ReadStereoCalibration(calibration_file);
    if (!read.ok()) return read.status().WithContext("stereo.calibration_file");
    if (read->left.width != info.width || read->left.height != info.height) {
      return InvalidArgument("stereo.calibration_file " + calibration_file + " is for " +
                             std::to_string(read->left.width) + "x" +
                             std::to_string(read->left.height) + " images but " + info.path +
                             " gives " + std::to_string(info.width) + "x" +
                             std::to_string(info.height));
    }
    return *read;
  }
  if (!info.stereo) {
    return FailedPrecondition(
        info.path +
        ": the source has no stereo calibration; give one with "
        "stereo.calibration_file=FILE (--set; an OpenCV stereo YAML as `sightline-cli "
        "calibrate stereo` writes), or for an Aravis pair "
        "aravis://LEFT,RIGHT?calibration_file=FILE");
  }
  return *info.stereo;
}

}  // namespace

Status StereoVoPipeline::Configure(const OptionSet& options) {
  return Configure(options.Extract(StereoOdometryOptions::Describe()),
                   options.Extract(StereoVoRunOptions::Describe()));
}

Status StereoVoPipeline::Configure(const StereoOdometryOptions& odometry,
                                   const StereoVoRunOptions& run) {
  std::string error;
  if (!run.IsValid(&error) || !odometry.IsValid(&error)) return InvalidArgument(error);
  const StereoOdometryOptions previous_odometry = odometry_options_;
  const StereoVoRunOptions previous_run = run_options_;
  odometry_options_ = odometry;
  run_options_ = run;
  if (!source_info_) return Status::Ok();
  // Opened: the odometry starts over with the new options (the old one stays on an error).
  Status started = StartOdometry();
  if (!started.ok()) {
    odometry_options_ = previous_odometry;
    run_options_ = previous_run;
  }
  return started;
}

Status StereoVoPipeline::Open(const PipelineSource& source) {
  const SourceInfo& info = source.info;
  if (info.kind != SourceKind::kStereo) {
    return InvalidArgument(info.path + " is a " + SourceKindName(info.kind) +
                           " source; stereo-vo needs stereo pairs");
  }
  source_info_ = info;
  ground_truth_.reset();
  if (source.ground_truth != nullptr && !source.ground_truth->empty()) {
    ground_truth_ = source.ground_truth;
  }
  run_ = StereoVoRun();
  run_.dataset_format = info.format;
  Status started = StartOdometry();  // Also starts the run.
  if (!started.ok()) {
    source_info_.reset();
    odometry_.reset();
  }
  return started;
}

Status StereoVoPipeline::StartOdometry() {
  // The rig is looked up again each time, so a changed stereo.calibration_file applies at once.
  StatusOr<StereoRig> rig = RigFor(*source_info_, run_options_.calibration_file);
  if (!rig.ok()) return rig.status();
  auto odometry = std::make_unique<StereoOdometry>(odometry_options_);
  SIGHTLINE_RETURN_IF_ERROR(odometry->Configure(*rig).WithContext(source_info_->path));
  odometry_ = std::move(odometry);
  Reset();
  return Status::Ok();
}

void StereoVoPipeline::Reset() {
  if (odometry_) odometry_->Reset();
  first_ground_truth_.reset();
  run_.estimate = Trajectory();
  run_.frames.clear();
  run_.sequence_ids.clear();
  run_.ground_truth.reset();
  if (ground_truth_) run_.ground_truth = *ground_truth_;
  log_.Clear();
}

std::optional<Eigen::Isometry3d> StereoVoPipeline::GroundTruthAt(double time_s) {
  if (!ground_truth_) return std::nullopt;
  const std::optional<size_t> i = ground_truth_->Nearest(time_s, run_options_.gt_tolerance_s);
  if (!i) return std::nullopt;
  const Eigen::Isometry3d& world_from_camera = ground_truth_->poses()[*i].world_from_sensor;
  if (!first_ground_truth_) first_ground_truth_ = world_from_camera;
  return first_ground_truth_->inverse() * world_from_camera;
}

StatusOr<std::shared_ptr<const PipelineResult>> StereoVoPipeline::Process(const Frame& frame) {
  if (!odometry_) return FailedPrecondition("stereo-vo: a frame before the source was opened");
  const StereoFrame* stereo = std::get_if<StereoFrame>(&frame);
  if (stereo == nullptr)
    return InvalidArgument(source_info_->path + " does not give stereo frames");
  TimingStats ran;
  StatusOr<std::shared_ptr<const StereoOdometryResult>> odometry =
      odometry_->Process(*stereo, &ran);
  if (!odometry.ok()) return odometry.status();
  const StereoOdometryResult& r = **odometry;
  auto result = std::make_shared<StereoVoResult>();
  result->stamp = r.stamp;
  result->odometry = *odometry;
  result->camera = odometry_->camera();
  result->stats = StatValues(r.stats, ran);
  // A gated frame says why, as frames.csv's status. The first frame is the origin, not a
  // problem: its status stays ok (frames.csv's status is empty, the GUI logs nothing).
  if (r.stats.status != "ok" && r.stats.status != "first frame") {
    result->status = FailedPrecondition(r.stats.status);
  }
  result->ground_truth = GroundTruthAt(r.stamp.sensor_time_s);
  run_.estimate.Add(r.stamp.sensor_time_s, r.world_from_camera);
  run_.frames.push_back(r.stats);
  run_.sequence_ids.push_back(stereo->stamp.sequence_id);
  log_.Add(*result);
  return std::shared_ptr<const PipelineResult>(std::move(result));
}

PipelineInfo StereoVoPipelineInfo() {
  PipelineInfo info;
  info.name = "stereo-vo";
  info.title = "Stereo visual odometry";
  info.summary = "stereo visual odometry (KLT tracks, rigidity RANSAC, reprojection refinement)";
  info.accepts = {SourceKind::kStereo};
  info.declare_options = [](OptionSet* set) {
    SIGHTLINE_RETURN_IF_ERROR(set->Declare(StereoOdometryOptions::Describe()));
    SIGHTLINE_RETURN_IF_ERROR(set->Declare(StereoVoRunOptions::Describe()));
    return DeclareSensorOptions(set);  // Live sources: sensors.aravis.stereo.* and the others.
  };
  info.create = [] { return std::make_unique<StereoVoPipeline>(); };
  return info;
}

}  // namespace sightline
