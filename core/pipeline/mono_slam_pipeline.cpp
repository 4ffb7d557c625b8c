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

const StatisticTable& MonoSlamStatistics() {
  static const StatisticTable kTable = {
      {"mono/tracked", "", "The frame's pose was tracked against the map."},
      {"mono/keypoints", "count", "ORB keypoints extracted."},
      {"mono/matches", "count", "Map points matched (fine pass)."},
      {"mono/inliers", "count", "Matches kept by the robust pose optimisation."},
      {"mono/rms_px", "px", "Inlier reprojection RMS (level-scaled)."},
      {"mono/map_points", "count", "Points in the map after this frame."},
      {"mono/keyframes", "count", "Keyframes in the map after this frame."},
      {"mono/features_ms", "ms", "Keypoint extraction."},
      {"mono/tracking_ms", "ms", "Features, tracking and relocalisation of the frame."},
      {"mono/tracking_cpu_ms", "ms", "CPU time of the tracking thread for the frame."},
      {"mono/mapping_ms", "ms", "Mapping of a new keyframe (frames that made one)."},
      {"mono/bundle_adjustment_ms", "ms", "Local bundle adjustment of a new keyframe."},
      {"mono/revisit_search_ms", "ms", "Search of a new keyframe for a revisit of mapped space."},
      {"mono/idle_bundle_adjustment_ms", "ms", "Global adjustment slices run in idle time."},
  };
  return kTable;
}

MonoSlamPipeline::MonoSlamPipeline(std::shared_ptr<MonoSlamCommands> commands)
    : commands_(std::move(commands)) {}

MonoSlamPipeline::~MonoSlamPipeline() {
  if (slam_) slam_->Stop();
}

Status MonoSlamPipeline::Configure(const OptionSet& options) {
  return Configure(options.Extract(MonoSlamOptions::Describe()),
                   options.Extract(MonoSlamRunOptions::Describe()));
}

Status MonoSlamPipeline::Configure(const MonoSlamOptions& options, const MonoSlamRunOptions& run) {
  std::string error;
  if (!run.IsValid(&error) || !options.IsValid(&error)) return InvalidArgument(error);
  options_ = options;
  run_ = run;
  if (!source_) return Status::Ok();
  return Open(*source_);  // New options restart the map, as a new run.
}

Status MonoSlamPipeline::Open(const PipelineSource& source) {
  const SourceInfo& info = source.info;
  if (info.camera) {
    camera_ = *info.camera;
  } else if (info.stereo) {
    camera_ = info.stereo->left;
  } else {
    return FailedPrecondition(info.path + ": the source has no camera calibration (camera.yaml)");
  }
  ground_truth_.reset();
  if (source.ground_truth && !source.ground_truth->empty()) {
    ground_truth_ = *source.ground_truth;
  } else if (const std::string file = (fs::path(info.path) / "groundtruth.txt").string();
             !info.live && fs::exists(file)) {
    // Image folders (the simulator's mono/) keep their camera's ground truth beside the images.
    StatusOr<Trajectory> gt = ReadTumTrajectory(file);
    if (!gt.ok()) return gt.status();
    ground_truth_ = *gt;
  }
  StatusOr<Trajectory> metric = LoadMetricCameraPoses(info.path, run_, ground_truth_,
                                                      &metric_source_, source.arm_poses.get());
  if (!metric.ok()) return metric.status();
  metric_ = std::move(*metric);
  source_ = source;
  return StartSlam();
}

Status MonoSlamPipeline::StartSlam() {
  if (slam_) slam_->Stop();
  slam_timing_.Clear();
  auto slam = std::make_unique<MonoSlam>(options_);
  SIGHTLINE_RETURN_IF_ERROR(
      slam->Configure(camera_, &slam_timing_).WithContext(source_->info.path));
  slam_ = std::move(slam);
  frames_.clear();
  last_map_.reset();
  lambda_ = single_ = 0;
  final_bundle_ms_ = -1;
  return Status::Ok();
}

void MonoSlamPipeline::Reset() {
  if (!slam_) return;
  slam_->Reset();
  slam_timing_.Clear();
  frames_.clear();
  last_map_.reset();
  lambda_ = single_ = 0;
  final_bundle_ms_ = -1;
}

int MonoSlamPipeline::lost_frames() const { return slam_ ? slam_->lost_frames() : 0; }

StatusOr<std::shared_ptr<const PipelineResult>> MonoSlamPipeline::Process(const Frame& frame) {
  StatusOr<std::shared_ptr<const MonoSlamFrameResult>> r = ProcessMono(frame);
  if (!r.ok()) return r.status();
  return std::shared_ptr<const PipelineResult>(*r);
}

StatusOr<std::shared_ptr<const MonoSlamFrameResult>> MonoSlamPipeline::ProcessMono(
    const Frame& frame) {
  if (!slam_) return FailedPrecondition("mono-slam: a frame before the source was opened");
  auto out = std::make_shared<MonoSlamFrameResult>();
  out->stamp = StampOf(frame);
  out->metric_source = metric_source_;
  const std::optional<MonoFrame> mono = MonoFrameOf(frame);
  if (!mono) {
    out->status = FailedPrecondition(
        "monocular SLAM needs mono images (or a stereo pair's left, or an RGB-D frame's colour)");
    return std::shared_ptr<const MonoSlamFrameResult>(out);
  }
  if (commands_) {
    if (commands_->TakeReset()) Reset();
    slam_->SetMappingPaused(commands_->mapping_paused());
  }
  StatusOr<std::shared_ptr<const MonoSlamResult>> processed = slam_->Process(*mono);
  if (!processed.ok()) return processed.status();
  const MonoSlamResult& r = **processed;
  out->slam = *processed;
  frames_.push_back({r.stamp.sequence_id, r.stamp.sensor_time_s, r.quality, r.tracked,
                     r.map_from_camera, r.stats});
  AddFrameStats(r, out.get());
  UpdateScale(r, out.get());
  return std::shared_ptr<const MonoSlamFrameResult>(out);
}

void MonoSlamPipeline::AddFrameStats(const MonoSlamResult& r, MonoSlamFrameResult* out) {
  const MonoFrameStats& s = r.stats;
  out->stats = {{"mono/tracked", r.tracked ? 1.0 : 0.0},
                {"mono/keypoints", double(s.keypoints)},
                {"mono/matches", double(s.matches)},
                {"mono/inliers", double(s.inliers)},
                {"mono/rms_px", s.rms_px},
                {"mono/map_points", double(s.map_points)},
                {"mono/keyframes", double(s.keyframes)}};
  // MonoSlam times its stages into slam_timing_: this frame's (and, with threaded mapping, the
  // mapper's since the last frame) become the frame's "ms" statistics.
  for (const char* stage : {"features", "tracking", "tracking_cpu", "mapping", "bundle_adjustment",
                            "revisit_search", "idle_bundle_adjustment"}) {
    const TimingSummary t = slam_timing_.Summary(stage);
    if (t.count > 0)
      out->stats.emplace_back(std::string("mono/") + stage + "_ms", t.mean_ms * t.count);
  }
  slam_timing_.Clear();
}

void MonoSlamPipeline::UpdateScale(const MonoSlamResult& r, MonoSlamFrameResult* out) {
  if (r.map && r.map != last_map_) {
    last_map_ = r.map;
    ScaleEstimator scale(options_.scale);
    for (const ScalePair& pair : KeyFrameScalePairs(*last_map_, metric_, run_.gt_tolerance_s)) {
      scale.Add(pair);
    }
    lambda_ = scale.max_likelihood();
    single_ = scale.single_ratio();
    out->scale_history = std::make_shared<const std::vector<ScaleSample>>(scale.history());
  }
  out->lambda = lambda_;
  out->single_ratio = single_;
}

StatusOr<MonoSlamRun> MonoSlamPipeline::Summary() {
  if (!slam_ || frames_.empty()) {
    return OutOfRange((source_ ? source_->info.path : std::string("mono-slam")) +
                      " holds no frames");
  }
  if (final_bundle_ms_ < 0) {
    const double start = HostTimeS();
    slam_->Stop();
    final_bundle_ms_ = (HostTimeS() - start) * 1000.0;
    slam_timing_.Clear();
  }
  MonoSlamRun out;
  out.dataset_format = source_->info.format;
  out.scale = ScaleEstimator(options_.scale);
  out.ground_truth = ground_truth_;
  out.metric_source = metric_source_;
  out.frames = frames_;
  out.map = slam_->Snapshot();
  out.keyframes = slam_->KeyFrameHistory();
  out.lost_frames = slam_->lost_frames();
  out.relocalisations = slam_->relocalisations();
  out.init_model = slam_->init_model();
  std::vector<DualPose> dual;
  auto add_dual = [&](int64_t index, double time_s, const Eigen::Isometry3d& map_from_camera) {
    DualPose d;
    d.frame = index;
    d.map_from_camera = map_from_camera;
    if (std::optional<size_t> k = metric_.Nearest(time_s, run_.gt_tolerance_s)) {
      d.metric_from_camera = metric_.poses()[*k].world_from_sensor;
    }
    dual.push_back(d);
  };
  for (const MonoRunFrame& f : out.frames) {
    if (!f.tracked) continue;
    out.estimate.Add(f.time_s, f.map_from_camera);
    if (run_.scale_pairs == "frames") add_dual(f.frame, f.time_s, f.map_from_camera);
  }
  if (run_.scale_pairs == "keyframes") {
    for (size_t k = 0; k < out.map->keyframes.size(); ++k) {
      add_dual(static_cast<int64_t>(k), out.map->keyframes[k].time_s,
               out.map->keyframes[k].map_from_camera);
    }
  }
  const int interval = run_.scale_pairs == "frames" ? run_.scale_interval_frames : 1;
  for (const ScalePair& pair : DisplacementPairs(dual, interval)) out.scale.Add(pair);
  return out;
}

namespace {

// Why a run achieved nothing: no frame was tracked (the map never initialised). Empty otherwise.
std::string NeverInitialised(const MonoSlamRun& run) {
  if (!run.estimate.empty()) return "";
  const std::string last = run.frames.empty() ? "" : run.frames.back().stats.status;
  return "never initialised: no frame tracked in " + std::to_string(run.frames.size()) +
         " frame(s) (two views with enough texture and parallax are needed" +
         (last.empty() ? std::string(")") : "; last frame: " + last + ")");
}

}  // namespace

StatusOr<RunResult> MonoSlamPipeline::Finish(const std::string& out_dir) {
  StatusOr<MonoSlamRun> run = Summary();
  if (!run.ok()) return run.status();
  RunResult result;
  result.dataset_format = run->dataset_format;
  result.frames = static_cast<int64_t>(run->frames.size());
  SIGHTLINE_RETURN_IF_ERROR(WriteMonoSlamOutputs(*run, out_dir, &result));
  std::vector<std::string> notes;
  result.accuracy = MonoSlamAccuracy(*run, run_.gt_tolerance_s, &notes);
  result.counts.emplace_back("tracked_frames", static_cast<double>(run->estimate.size()));
  result.counts.emplace_back("keyframes", static_cast<double>(run->map->keyframes.size()));
  result.counts.emplace_back("map_points", static_cast<double>(run->map->points.size()));
  result.counts.emplace_back("scale_pairs", static_cast<double>(run->scale.pairs().size()));
  result.counts.emplace_back("init_homography", run->init_model == "homography" ? 1 : 0);
  result.counts.emplace_back("metric_scale_from_arm", run->metric_source == "arm" ? 1 : 0);
  result.counts.emplace_back("final_bundle_adjustment_ms", final_bundle_ms_);
  const IdleBundleTotals idle = slam_->idle_bundle();
  result.counts.emplace_back("final_bundle_longest_step_ms", idle.stop_longest_step_ms);
  result.counts.emplace_back("idle_bundle_slices", idle.slices);
  result.counts.emplace_back("revisits", slam_->revisits());
  notes.push_back("metric scale source: " + run->metric_source);
  result.nothing_achieved = NeverInitialised(*run);
  if (!result.nothing_achieved.empty()) notes.insert(notes.begin(), result.nothing_achieved);
  std::ofstream log(fs::path(out_dir) / "mono_slam_notes.txt");
  for (const std::string& note : notes) log << note << "\n";
  result.outputs.push_back("mono_slam_notes.txt");
  return result;
}

StatusOr<MonoSlamRun> RunMonoSlam(const std::string& path, const MonoSlamOptions& options,
                                  const MonoSlamRunOptions& run, TimingStats* timing,
                                  const std::function<void(int64_t, int64_t)>& progress,
                                  const std::atomic<bool>* cancel) {
  MonoSlamPipeline pipeline;
  SIGHTLINE_RETURN_IF_ERROR(pipeline.Configure(options, run));
  StatusOr<OpenedMono> opened = OpenMono(path);
  if (!opened.ok()) return opened.status();
  Source& source = *opened->source;
  SIGHTLINE_RETURN_IF_ERROR(pipeline.Open(PipelineSource::From(source)));
  int64_t total = source.info().frame_count;
  if (run.max_frames > 0 && (total < 0 || total > run.max_frames)) total = run.max_frames;
  for (int64_t index = 0; total < 0 || index < total; ++index) {
    if (cancel != nullptr && cancel->load()) {
      return Cancelled("run cancelled after " + std::to_string(index) + " frames");
    }
    StatusOr<std::optional<MonoFrame>> next = NextMonoFrame(source, path);
    if (!next.ok()) return next.status().WithContext("frame " + std::to_string(index));
    if (!*next) break;
    if (!pipeline.Wants(index)) continue;
    const double start = HostTimeS();
    StatusOr<std::shared_ptr<const PipelineResult>> result = pipeline.Process(Frame(**next));
    if (!result.ok()) return result.status();
    if (timing) {
      for (const auto& [key, value] : (*result)->stats) {
        if (key.size() > 3 && key.compare(key.size() - 3, 3, "_ms") == 0) {
          timing->Add(key.substr(5, key.size() - 8), value);  // "mono/features_ms" -> "features".
        }
      }
      timing->Add("total", (HostTimeS() - start) * 1000.0);
    }
    if (progress) progress(index + 1, total);
  }
  return pipeline.Summary();
}

PipelineInfo MonoSlamPipelineInfo(const std::shared_ptr<MonoSlamCommands>& commands) {
  PipelineInfo info;
  info.name = "mono-slam";
  info.title = "Monocular SLAM (PTAM point cloud)";
  info.summary = "monocular SLAM (PTAM-style keyframes and bundle adjustment) with metric scale";
  info.accepts = {SourceKind::kMono, SourceKind::kStereo, SourceKind::kRgbd};
  info.declare_options = [](OptionSet* set) {
    SIGHTLINE_RETURN_IF_ERROR(set->Declare(MonoSlamOptions::Describe()));
    return set->Declare(MonoSlamRunOptions::Describe());
  };
  info.create = [commands]() -> std::unique_ptr<Pipeline> {
    return std::make_unique<MonoSlamPipeline>(commands);
  };
  return info;
}

}  // namespace sightline
