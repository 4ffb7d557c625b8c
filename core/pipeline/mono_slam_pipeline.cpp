#include "core/pipeline/mono_slam_pipeline.h"

#include <cmath>
#include <filesystem>
#include <fstream>

#include "core/eval/evaluation.h"
#include "core/mono/metric_motion.h"

namespace sightline {

namespace fs = std::filesystem;

Trajectory MonoSlamRun::MetricEstimate() const {
  if (lambda() <= 0) return estimate;
  Trajectory metric;
  for (const TimedPose& p : estimate.poses()) {
    Eigen::Isometry3d pose = p.world_from_sensor;
    pose.translation() /= lambda();
    metric.Add(p.time_s, pose);
  }
  return metric;
}

StatusOr<MonoSlamRun> RunMonoSlam(const std::string& path, const MonoSlamOptions& options,
                                  const MonoSlamRunOptions& run, TimingStats* timing,
                                  const std::function<void(int64_t, int64_t)>& progress,
                                  const std::atomic<bool>* cancel) {
  std::string error;
  if (!run.IsValid(&error) || !options.IsValid(&error)) return InvalidArgument(error);
  StatusOr<OpenedMono> opened = OpenMono(path);
  if (!opened.ok()) return opened.status();
  Source& source = *opened->source;
  MonoSlamRun out;
  out.scale = ScaleEstimator(options.scale);
  out.dataset_format = source.info().format;
  out.ground_truth = opened->ground_truth;
  StatusOr<Trajectory> metric_poses =
      LoadMetricCameraPoses(path, run, out.ground_truth, &out.metric_source);
  if (!metric_poses.ok()) return metric_poses.status();
  const Trajectory& metric = *metric_poses;

  MonoSlam slam(options);
  SIGHTLINE_RETURN_IF_ERROR(slam.Configure(opened->camera, timing).WithContext(path));
  int64_t total = source.info().frame_count;
  if (run.max_frames > 0 && (total < 0 || total > run.max_frames)) total = run.max_frames;
  for (int64_t index = 0; total < 0 || index < total; ++index) {
    if (cancel != nullptr && cancel->load()) {
      return Cancelled("run cancelled after " + std::to_string(index) + " frames");
    }
    StatusOr<std::optional<MonoFrame>> next = NextMonoFrame(source, path);
    if (!next.ok()) return next.status().WithContext("frame " + std::to_string(index));
    if (!*next) break;
    const MonoFrame& mono = **next;
    const double start = HostTimeS();
    StatusOr<std::shared_ptr<const MonoSlamResult>> result = slam.Process(mono);
    if (!result.ok()) return result.status();
    if (timing) timing->Add("total", (HostTimeS() - start) * 1000.0);
    const MonoSlamResult& r = **result;
    out.frames.push_back({r.stamp.sequence_id, r.stamp.sensor_time_s, r.quality, r.tracked,
                          r.map_from_camera, r.stats});
    if (progress) progress(index + 1, total);
  }
  slam.Stop();
  if (out.frames.empty()) return OutOfRange(path + " holds no frames");
  out.map = slam.Snapshot();
  out.keyframes = slam.KeyFrameHistory();
  out.lost_frames = slam.lost_frames();
  out.relocalisations = slam.relocalisations();
  out.init_model = slam.init_model();
  std::vector<DualPose> dual;
  auto add_dual = [&](int64_t index, double time_s, const Eigen::Isometry3d& map_from_camera) {
    DualPose d;
    d.frame = index;
    d.map_from_camera = map_from_camera;
    if (std::optional<size_t> k = metric.Nearest(time_s, run.gt_tolerance_s)) {
      d.metric_from_camera = metric.poses()[*k].world_from_sensor;
    }
    dual.push_back(d);
  };
  for (const MonoRunFrame& f : out.frames) {
    if (!f.tracked) continue;
    out.estimate.Add(f.time_s, f.map_from_camera);
    if (run.scale_pairs == "frames") add_dual(f.frame, f.time_s, f.map_from_camera);
  }
  if (run.scale_pairs == "keyframes") {
    for (size_t k = 0; k < out.map->keyframes.size(); ++k) {
      add_dual(static_cast<int64_t>(k), out.map->keyframes[k].time_s,
               out.map->keyframes[k].map_from_camera);
    }
  }
  const int interval = run.scale_pairs == "frames" ? run.scale_interval_frames : 1;
  for (const ScalePair& pair : DisplacementPairs(dual, interval)) out.scale.Add(pair);
  return out;
}

std::vector<std::pair<std::string, double>> MonoSlamAccuracy(const MonoSlamRun& run,
                                                             double gt_tolerance_s,
                                                             std::vector<std::string>* notes) {
  std::vector<std::pair<std::string, double>> figures;
  figures.emplace_back("lost_frames", run.lost_frames);
  figures.emplace_back("relocalisations", run.relocalisations);
  if (run.scale.single_ratio() > 0) figures.emplace_back("scale_single", run.scale.single_ratio());
  if (run.lambda() > 0) figures.emplace_back("scale_ml", run.lambda());
  if (!run.ground_truth) return figures;
  EvaluationOptions eval;
  eval.max_time_difference_s = gt_tolerance_s;
  eval.align = "sim3";
  StatusOr<TrajectoryErrors> sim3 = EvaluateTrajectory(run.estimate, *run.ground_truth, eval);
  if (!sim3.ok()) {
    if (notes) notes->push_back("trajectory accuracy not computed: " + sim3.status().message());
    return figures;
  }
  figures.emplace_back("ate_rmse_m", sim3->ate.rmse);
  if (sim3->ground_truth_length_m > 0) {
    figures.emplace_back("ate_rmse_pct_of_path",
                         100 * sim3->ate.rmse / sim3->ground_truth_length_m);
  }
  figures.emplace_back("path_length_m", sim3->ground_truth_length_m);
  figures.emplace_back("tracked_poses_evaluated", static_cast<double>(sim3->pairs));
  // The alignment's scale s maps the map to metres, so the true lambda is 1 / s; measured on
  // the keyframes (the map as bundle adjustment left it) when there are enough.
  double lambda_true = 1.0 / sim3->ground_truth_from_estimate.scale;
  Trajectory keyframes;
  for (const MapSnapshot::Frame& k : run.map->keyframes) keyframes.Add(k.time_s, k.map_from_camera);
  if (StatusOr<TrajectoryErrors> kf = EvaluateTrajectory(keyframes, *run.ground_truth, eval);
      kf.ok()) {
    lambda_true = 1.0 / kf->ground_truth_from_estimate.scale;
    figures.emplace_back("keyframe_ate_rmse_m", kf->ate.rmse);
  }
  figures.emplace_back("scale_true", lambda_true);
  if (run.lambda() > 0) {
    figures.emplace_back("scale_error_pct_ml",
                         100 * std::abs(run.lambda() - lambda_true) / lambda_true);
    eval.align = "se3";
    StatusOr<TrajectoryErrors> metric =
        EvaluateTrajectory(run.MetricEstimate(), *run.ground_truth, eval);
    if (metric.ok()) figures.emplace_back("ate_metric_rmse_m", metric->ate.rmse);
  } else if (notes) {
    notes->push_back(
        "no metric scale: no arm poses or ground-truth displacements, or too few pairs");
  }
  if (run.scale.single_ratio() > 0) {
    figures.emplace_back("scale_error_pct_single",
                         100 * std::abs(run.scale.single_ratio() - lambda_true) / lambda_true);
  }
  return figures;
}

namespace {
StatusOr<RunResult> RunMonoSlamPipeline(const RunContext& context) {
  const MonoSlamOptions options = context.options.Extract(MonoSlamOptions::Describe());
  const MonoSlamRunOptions run = context.options.Extract(MonoSlamRunOptions::Describe());
  StatusOr<MonoSlamRun> estimated = RunMonoSlam(context.dataset_path, options, run, context.timing,
                                                context.progress, context.cancel);
  if (!estimated.ok()) return estimated.status();
  RunResult result;
  result.dataset_format = estimated->dataset_format;
  result.frames = static_cast<int64_t>(estimated->frames.size());
  SIGHTLINE_RETURN_IF_ERROR(WriteMonoSlamOutputs(*estimated, context.out_dir, &result));
  std::vector<std::string> notes;
  result.accuracy = MonoSlamAccuracy(*estimated, run.gt_tolerance_s, &notes);
  result.counts.emplace_back("tracked_frames", static_cast<double>(estimated->estimate.size()));
  result.counts.emplace_back("keyframes", static_cast<double>(estimated->map->keyframes.size()));
  result.counts.emplace_back("map_points", static_cast<double>(estimated->map->points.size()));
  result.counts.emplace_back("scale_pairs", static_cast<double>(estimated->scale.pairs().size()));
  result.counts.emplace_back("init_homography", estimated->init_model == "homography" ? 1 : 0);
  result.counts.emplace_back("metric_scale_from_arm", estimated->metric_source == "arm" ? 1 : 0);
  notes.push_back("metric scale source: " + estimated->metric_source);
  std::ofstream log(fs::path(context.out_dir) / "mono_slam_notes.txt");
  for (const std::string& note : notes) log << note << "\n";
  result.outputs.push_back("mono_slam_notes.txt");
  return result;
}

}  // namespace

PipelineInfo MonoSlamPipeline() {
  PipelineInfo info;
  info.name = "mono-slam";
  info.summary = "monocular SLAM (PTAM-style keyframes and bundle adjustment) with metric scale";
  info.declare_options = [](OptionSet* set) {
    SIGHTLINE_RETURN_IF_ERROR(set->Declare(MonoSlamOptions::Describe()));
    return set->Declare(MonoSlamRunOptions::Describe());
  };
  info.run = RunMonoSlamPipeline;
  return info;
}

}  // namespace sightline
