#include "core/pipeline/stereo_vo_pipeline.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>

#include "core/eval/evaluation.h"
#include "core/io/dataset.h"
#include "core/io/stereo_calibration_file.h"
#include "core/sensors/driver_registry.h"

namespace sightline {

namespace {
// A ground-truth path shorter than this is a static recording [m].
constexpr double kStaticPathM = 0.05;
}  // namespace

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
           "Process every k-th frame (the seed's subsampling sweep); --subsample K.")
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

StatusOr<StereoVoRun> RunStereoOdometry(const std::string& path,
                                        const StereoOdometryOptions& options,
                                        const StereoVoRunOptions& run, TimingStats* timing,
                                        const std::function<void(int64_t, int64_t)>& progress,
                                        const std::atomic<bool>* cancel,
                                        const OptionSet* sensor_options) {
  std::string error;
  if (!run.IsValid(&error) || !options.IsValid(&error)) return InvalidArgument(error);
  StatusOr<std::unique_ptr<Source>> opened =
      IsSensorUri(path) ? OpenSource(path, sensor_options ? *sensor_options : OptionSet())
                        : OpenDataset(path, SourceKind::kStereo);
  if (!opened.ok()) return opened.status();
  Source& source = **opened;
  if (source.info().kind != SourceKind::kStereo) {
    return InvalidArgument(path + " is a " + SourceKindName(source.info().kind) +
                           " source; stereo-vo needs stereo pairs");
  }
  std::optional<StereoRig> rig = source.info().stereo;
  if (!run.calibration_file.empty()) {
    StatusOr<StereoRig> read = ReadStereoCalibration(run.calibration_file);
    if (!read.ok()) return read.status().WithContext("stereo.calibration_file");
    if (read->left.width != source.info().width || read->left.height != source.info().height) {
      return InvalidArgument("stereo.calibration_file " + run.calibration_file + " is for " +
                             std::to_string(read->left.width) + "x" +
                             std::to_string(read->left.height) + " images but " + path + " gives " +
                             std::to_string(source.info().width) + "x" +
                             std::to_string(source.info().height));
    }
    rig = *read;
  }
  if (!rig) {
    return FailedPrecondition(
        path +
        ": the source has no stereo calibration; give one with "
        "stereo.calibration_file=FILE (--set; an OpenCV stereo YAML as `sightline-cli "
        "calibrate stereo` writes), or for an Aravis pair "
        "aravis://LEFT,RIGHT?calibration_file=FILE");
  }
  StereoOdometry odometry(options);
  SIGHTLINE_RETURN_IF_ERROR(odometry.Configure(*rig).WithContext(path));

  StereoVoRun out;
  out.dataset_format = source.info().format;
  if (const Trajectory* gt = source.ground_truth(); gt != nullptr && !gt->empty()) {
    out.ground_truth = *gt;
  }
  int64_t total = source.info().frame_count;
  if (run.max_frames > 0 && (total < 0 || total > run.max_frames)) total = run.max_frames;
  for (int64_t index = 0; total < 0 || index < total; ++index) {
    if (cancel != nullptr && cancel->load()) {
      return Cancelled("run cancelled after " + std::to_string(index) + " frames");
    }
    const double read_start = HostTimeS();
    const Status grabbed = source.Grab();
    if (grabbed.code() == StatusCode::kOutOfRange) break;
    if (!grabbed.ok()) return grabbed;
    if (index % run.subsample != 0) continue;  // Grabbed but not decoded.
    StatusOr<Frame> frame = source.Retrieve();
    if (timing) timing->Add("read", (HostTimeS() - read_start) * 1000.0);
    if (!frame.ok()) return frame.status().WithContext("frame " + std::to_string(index));
    const StereoFrame* stereo = std::get_if<StereoFrame>(&*frame);
    if (stereo == nullptr) return InvalidArgument(path + " does not give stereo frames");
    StatusOr<std::shared_ptr<const StereoOdometryResult>> result =
        odometry.Process(*stereo, timing);
    if (!result.ok()) return result.status();
    out.estimate.Add((*result)->stamp.sensor_time_s, (*result)->world_from_camera);
    out.frames.push_back((*result)->stats);
    out.sequence_ids.push_back(stereo->stamp.sequence_id);
    if (progress) progress(index + 1, total);
  }
  if (out.frames.empty()) return OutOfRange(path + " holds no frames");
  return out;
}

std::vector<std::pair<std::string, double>> StereoVoAccuracy(const StereoVoRun& run,
                                                             double gt_tolerance_s,
                                                             std::vector<std::string>* notes) {
  std::vector<std::pair<std::string, double>> figures;
  if (run.ground_truth && run.ground_truth->LengthM() < kStaticPathM) {
    // A static recording: relative figures (% of a path of millimetres) mean nothing; the only
    // error is any motion at all.
    double max_translation = 0, max_rotation = 0;
    const Eigen::Isometry3d first_inverse =
        run.estimate.poses().front().world_from_sensor.inverse();
    for (const TimedPose& p : run.estimate.poses()) {
      const Eigen::Isometry3d rel = first_inverse * p.world_from_sensor;
      max_translation = std::max(max_translation, rel.translation().norm());
      max_rotation = std::max(max_rotation, Eigen::AngleAxisd(rel.rotation()).angle() * 180 / M_PI);
    }
    figures.emplace_back("static_translation_m", max_translation);
    figures.emplace_back("static_rotation_deg", max_rotation);
    if (notes) {
      notes->push_back(
          "the ground truth moves less than 5 cm: static recording, reporting the "
          "estimated motion (static_translation_m, static_rotation_deg) instead of "
          "trajectory errors");
    }
  } else if (run.ground_truth) {
    EvaluationOptions eval;
    eval.max_time_difference_s = gt_tolerance_s;
    StatusOr<TrajectoryErrors> errors = EvaluateTrajectory(run.estimate, *run.ground_truth, eval);
    if (errors.ok()) {
      figures = AccuracyFigures(*errors);
      if (notes) notes->insert(notes->end(), errors->notes.begin(), errors->notes.end());
    } else if (notes) {
      notes->push_back("trajectory accuracy not computed: " + errors.status().message());
    }
  }
  figures.emplace_back("estimated_length_m", run.estimate.LengthM());
  return figures;
}

namespace {

Status WriteFramesCsv(const StereoVoRun& run, const std::string& path) {
  std::ofstream csv(path);
  if (!csv) return NotFound("cannot write " + path);
  csv << "frame,time_s,tracked,retracked,anchored,new_features,stereo_matches,correspondences,"
         "inliers,"
         "ransac_iterations,rigidity_failures,residual_px,disparity_offset_px,window_points,"
         "window_rms_px,translation_m,rotation_deg,gated,"
         "rectify_ms,pyramid_ms,tracking_ms,detection_ms,matching_ms,ransac_ms,refine_ms,"
         "window_ms,total_ms,status\n";
  for (size_t i = 0; i < run.frames.size(); ++i) {
    const FrameStats& s = run.frames[i];
    std::string status = s.status;
    for (char& c : status) {
      if (c == '"') c = '\'';
    }
    char row[512];
    std::snprintf(row, sizeof(row),
                  "%lld,%.6f,%d,%d,%d,%d,%d,%d,%d,%d,%d,%.4f,%.4f,%d,%.4f,%.5f,%.5f,%d,%.3f,%.3f,"
                  "%.3f,%.3f,%.3f,%.3f,%.3f,%.3f,%.3f,\"%s\"\n",
                  static_cast<long long>(run.sequence_ids[i]), run.estimate.poses()[i].time_s,
                  s.tracked, s.retracked ? 1 : 0, s.anchored, s.new_features, s.stereo_matches,
                  s.correspondences, s.inliers, s.ransac_iterations, s.rigidity_failures,
                  s.residual_px, s.disparity_offset_px, s.window_points, s.window_rms_px,
                  s.translation_m, s.rotation_deg, s.gated ? 1 : 0, s.rectify_ms, s.pyramid_ms,
                  s.tracking_ms, s.detection_ms, s.matching_ms, s.ransac_ms, s.refine_ms,
                  s.window_ms, s.total_ms, status.c_str());
    csv << row;
  }
  csv.flush();
  if (!csv) return Unavailable("write to " + path + " failed (disk full?)");
  return Status::Ok();
}

StatusOr<RunResult> RunStereoVo(const RunContext& context) {
  const StereoOdometryOptions options = context.options.Extract(StereoOdometryOptions::Describe());
  const StereoVoRunOptions run = context.options.Extract(StereoVoRunOptions::Describe());
  StatusOr<StereoVoRun> estimated =
      RunStereoOdometry(context.dataset_path, options, run, context.timing, context.progress,
                        context.cancel, &context.options);
  if (!estimated.ok()) return estimated.status();
  RunResult result;
  result.dataset_format = estimated->dataset_format;
  result.frames = static_cast<int64_t>(estimated->frames.size());

  namespace fs = std::filesystem;
  const std::string trajectory_path = (fs::path(context.out_dir) / "trajectory.txt").string();
  SIGHTLINE_RETURN_IF_ERROR(run.output_format == "kitti"
                                ? WriteKittiTrajectory(estimated->estimate, trajectory_path)
                                : WriteTumTrajectory(estimated->estimate, trajectory_path));
  result.outputs.push_back("trajectory.txt");
  SIGHTLINE_RETURN_IF_ERROR(
      WriteFramesCsv(*estimated, (fs::path(context.out_dir) / "frames.csv").string()));
  result.outputs.push_back("frames.csv");

  std::vector<std::string> notes;
  result.accuracy = StereoVoAccuracy(*estimated, run.gt_tolerance_s, &notes);
  double gated = 0, inliers = 0, matches = 0;
  for (const FrameStats& s : estimated->frames) {
    gated += s.gated ? 1 : 0;
    inliers += s.inliers;
    matches += s.stereo_matches;
  }
  const double n = static_cast<double>(estimated->frames.size());
  result.counts.emplace_back("frames_gated", gated);
  result.counts.emplace_back("inliers_per_frame", inliers / n);
  result.counts.emplace_back("stereo_matches_per_frame", matches / n);
  if (!notes.empty()) {
    std::ofstream log(fs::path(context.out_dir) / "stereo_vo_notes.txt");
    for (const std::string& note : notes) log << note << "\n";
    result.outputs.push_back("stereo_vo_notes.txt");
  }
  return result;
}

}  // namespace

PipelineInfo StereoVoPipeline() {
  PipelineInfo info;
  info.name = "stereo-vo";
  info.summary = "stereo visual odometry (KLT tracks, rigidity RANSAC, reprojection refinement)";
  info.declare_options = [](OptionSet* set) {
    SIGHTLINE_RETURN_IF_ERROR(set->Declare(StereoOdometryOptions::Describe()));
    SIGHTLINE_RETURN_IF_ERROR(set->Declare(StereoVoRunOptions::Describe()));
    return DeclareSensorOptions(set);  // Live sources: sensors.aravis.stereo.* and the others.
  };
  info.run = RunStereoVo;
  return info;
}

}  // namespace sightline
