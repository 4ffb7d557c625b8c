#include "core/pipeline/mono_slam_pipeline.h"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/eval/evaluation.h"
#include "core/io/dataset.h"
#include "core/mono/metric_motion.h"

namespace sightline {

namespace fs = std::filesystem;

bool MonoSlamRunOptions::IsValid(std::string* error) const {
  auto fail = [&](const std::string& m) {
    if (error) *error = "mono.run." + m;
    return false;
  };
  if (max_frames < 0) return fail("max_frames must be >= 0");
  if (metric_source != "auto" && metric_source != "arm" && metric_source != "ground_truth" &&
      metric_source != "none") {
    return fail("metric_source must be auto, arm, ground_truth or none");
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
      .Choice("metric_source", &O::metric_source, {"auto", "arm", "ground_truth", "none"},
              "Measured motion for the metric scale: the arm's poses (arm_poses.txt), "
              "ground-truth displacements, or none; auto prefers the arm.")
      .String("arm_poses", &O::arm_poses,
              "arm_poses.txt (base_from_end_effector, TUM); empty = beside the sensor folder.")
      .String("hand_eye", &O::hand_eye,
              "hand_eye.yaml (end_effector_from_camera); empty = beside arm_poses; none = identity.")
      .Choice("scale_pairs", &O::scale_pairs, {"keyframes", "frames"},
              "Displacement pairs between consecutive keyframes (poses refined by bundle "
              "adjustment) or between tracked frames scale_interval_frames apart.")
      .Int("scale_interval_frames", &O::scale_interval_frames, "frames", 1, 10000, 1,
           "Frames spanned by one displacement pair of the scale estimators.")
      .Double("gt_tolerance_s", &O::gt_tolerance_s, "s", 0, 1, 0.005,
              "A pose belongs to a frame when this close in time.");
}

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

namespace {

// The folder holding arm_poses.txt for a dataset path (the path itself or its parent).
std::string FindBeside(const std::string& path, const std::string& name) {
  for (fs::path dir : {fs::path(path), fs::path(path).parent_path()}) {
    if (fs::exists(dir / name)) return (dir / name).string();
  }
  return "";
}

StatusOr<std::vector<double>> BracketNumbers(const std::string& line, const std::string& where,
                                             size_t count) {
  const size_t open = line.find('['), close = line.find(']');
  if (open == std::string::npos || close == std::string::npos || close < open) {
    return ParseError(where + ": expected [numbers]");
  }
  std::string inside = line.substr(open + 1, close - open - 1);
  for (char& c : inside) {
    if (c == ',') c = ' ';
  }
  std::istringstream in(inside);
  std::vector<double> values;
  double v;
  while (in >> v) values.push_back(v);
  if (values.size() != count) return ParseError(where + ": expected " + std::to_string(count) + " numbers");
  return values;
}

// end_effector_from_camera of a hand_eye.yaml as the simulator writes it.
StatusOr<Eigen::Isometry3d> ReadHandEye(const std::string& path) {
  std::ifstream in(path);
  if (!in) return NotFound("cannot read " + path);
  std::string line;
  bool inside = false;
  std::optional<Eigen::Vector3d> t;
  std::optional<Eigen::Quaterniond> q;
  for (int number = 1; std::getline(in, line); ++number) {
    if (!line.empty() && line[0] != ' ' && line[0] != '#') {
      inside = line.rfind("end_effector_from_camera:", 0) == 0;
      continue;
    }
    if (!inside) continue;
    const std::string where = path + ":" + std::to_string(number);
    if (line.find("translation:") != std::string::npos) {
      StatusOr<std::vector<double>> v = BracketNumbers(line, where, 3);
      if (!v.ok()) return v.status();
      t = Eigen::Vector3d((*v)[0], (*v)[1], (*v)[2]);
    } else if (line.find("quaternion_xyzw:") != std::string::npos) {
      StatusOr<std::vector<double>> v = BracketNumbers(line, where, 4);
      if (!v.ok()) return v.status();
      q = Eigen::Quaterniond((*v)[3], (*v)[0], (*v)[1], (*v)[2]);
    }
  }
  if (!t || !q || q->norm() < 1e-9) {
    return ParseError(path + ": no end_effector_from_camera with translation and quaternion_xyzw");
  }
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.linear() = q->normalized().toRotationMatrix();
  pose.translation() = *t;
  return pose;
}

Status LoadMetricPoses(const std::string& path, const MonoSlamRunOptions& run,
                       const std::optional<Trajectory>& ground_truth, Trajectory* metric,
                       std::string* source) {
  *source = "none";
  if (run.metric_source == "none") return Status::Ok();
  const std::string arm_path = run.arm_poses.empty() ? FindBeside(path, "arm_poses.txt") : run.arm_poses;
  const bool use_arm = run.metric_source == "arm" || (run.metric_source == "auto" && !arm_path.empty());
  if (use_arm) {
    if (arm_path.empty()) return NotFound(path + ": no arm_poses.txt beside the images (mono.run.arm_poses)");
    StatusOr<Trajectory> arm = ReadTumTrajectory(arm_path);
    if (!arm.ok()) return arm.status();
    Eigen::Isometry3d ee_from_camera = Eigen::Isometry3d::Identity();
    if (run.hand_eye != "none") {
      std::string hand_eye = run.hand_eye;
      if (hand_eye.empty()) hand_eye = (fs::path(arm_path).parent_path() / "hand_eye.yaml").string();
      StatusOr<Eigen::Isometry3d> read = ReadHandEye(hand_eye);
      if (!read.ok()) return read.status();
      ee_from_camera = *read;
    }
    for (const TimedPose& p : arm->poses()) metric->Add(p.time_s, p.world_from_sensor * ee_from_camera);
    *source = "arm";
    return Status::Ok();
  }
  if (ground_truth) {
    *metric = *ground_truth;
    *source = "ground_truth";
  } else if (run.metric_source == "ground_truth") {
    return NotFound(path + ": mono.run.metric_source = ground_truth but the dataset has none");
  }
  return Status::Ok();
}

// Opens the mono images of `path`, or the left images of a stereo recording.
struct OpenedMono {
  std::unique_ptr<Source> source;
  PinholeCamera camera;
};

StatusOr<OpenedMono> OpenMono(const std::string& path) {
  StatusOr<std::unique_ptr<Source>> opened = OpenDataset(path, SourceKind::kMono);
  if (!opened.ok()) opened = OpenDataset(path, SourceKind::kStereo);
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
  return out;
}

}  // namespace

StatusOr<Trajectory> LoadMetricCameraPoses(const std::string& path, const MonoSlamRunOptions& run,
                                           const std::optional<Trajectory>& ground_truth,
                                           std::string* source) {
  Trajectory metric;
  SIGHTLINE_RETURN_IF_ERROR(LoadMetricPoses(path, run, ground_truth, &metric, source));
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
  if (const Trajectory* gt = source.ground_truth(); gt != nullptr && !gt->empty()) {
    out.ground_truth = *gt;
  } else if (const std::string file = (fs::path(source.info().path) / "groundtruth.txt").string();
             fs::exists(file)) {
    // Image folders (the simulator's mono/) keep their camera's ground truth beside the images.
    StatusOr<Trajectory> gt = ReadTumTrajectory(file);
    if (!gt.ok()) return gt.status();
    out.ground_truth = *gt;
  }
  Trajectory metric;
  SIGHTLINE_RETURN_IF_ERROR(LoadMetricPoses(path, run, out.ground_truth, &metric, &out.metric_source));

  MonoSlam slam(options);
  SIGHTLINE_RETURN_IF_ERROR(slam.Configure(opened->camera, timing).WithContext(path));
  int64_t total = source.info().frame_count;
  if (run.max_frames > 0 && (total < 0 || total > run.max_frames)) total = run.max_frames;
  for (int64_t index = 0; total < 0 || index < total; ++index) {
    if (cancel != nullptr && cancel->load()) {
      return Cancelled("run cancelled after " + std::to_string(index) + " frames");
    }
    const Status grabbed = source.Grab();
    if (grabbed.code() == StatusCode::kOutOfRange) break;
    if (!grabbed.ok()) return grabbed;
    StatusOr<Frame> frame = source.Retrieve();
    if (!frame.ok()) return frame.status().WithContext("frame " + std::to_string(index));
    MonoFrame mono;
    if (const MonoFrame* m = std::get_if<MonoFrame>(&*frame)) {
      mono = *m;
    } else if (const StereoFrame* s = std::get_if<StereoFrame>(&*frame)) {
      mono.stamp = s->stamp;
      mono.image = s->left;
    } else {
      return InvalidArgument(path + " gives neither mono nor stereo frames");
    }
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
      add_dual(static_cast<int64_t>(k), out.map->keyframes[k].time_s, out.map->keyframes[k].map_from_camera);
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
    figures.emplace_back("ate_rmse_pct_of_path", 100 * sim3->ate.rmse / sim3->ground_truth_length_m);
  }
  figures.emplace_back("path_length_m", sim3->ground_truth_length_m);
  figures.emplace_back("tracked_poses_evaluated", static_cast<double>(sim3->pairs));
  // The alignment's scale s maps the map to metres, so the true lambda is 1 / s; measured on
  // the keyframes (the map as bundle adjustment left it) when there are enough.
  double lambda_true = 1.0 / sim3->ground_truth_from_estimate.scale;
  Trajectory keyframes;
  for (const MapSnapshot::Frame& k : run.map->keyframes) keyframes.Add(k.time_s, k.map_from_camera);
  if (StatusOr<TrajectoryErrors> kf = EvaluateTrajectory(keyframes, *run.ground_truth, eval); kf.ok()) {
    lambda_true = 1.0 / kf->ground_truth_from_estimate.scale;
    figures.emplace_back("keyframe_ate_rmse_m", kf->ate.rmse);
  }
  figures.emplace_back("scale_true", lambda_true);
  if (run.lambda() > 0) {
    figures.emplace_back("scale_error_pct_ml", 100 * std::abs(run.lambda() - lambda_true) / lambda_true);
    eval.align = "se3";
    StatusOr<TrajectoryErrors> metric = EvaluateTrajectory(run.MetricEstimate(), *run.ground_truth, eval);
    if (metric.ok()) figures.emplace_back("ate_metric_rmse_m", metric->ate.rmse);
  } else if (notes) {
    notes->push_back("no metric scale: no arm poses or ground-truth displacements, or too few pairs");
  }
  if (run.scale.single_ratio() > 0) {
    figures.emplace_back("scale_error_pct_single",
                         100 * std::abs(run.scale.single_ratio() - lambda_true) / lambda_true);
  }
  return figures;
}

namespace {

Status WriteFile(const std::string& path, const std::string& text) {
  std::ofstream out(path);
  if (!out) return Unavailable("cannot write " + path);
  out << text;
  out.flush();
  if (!out) return Unavailable("write to " + path + " failed (disk full?)");
  return Status::Ok();
}

// A colour per keyframe (golden-angle hues), so points show which keyframe made them.
Eigen::Vector3i KeyFrameColour(int64_t keyframe) {
  const double h = std::fmod(keyframe * 137.508, 360.0) / 60.0;
  const double x = 1 - std::abs(std::fmod(h, 2.0) - 1);
  double r = 0, g = 0, b = 0;
  switch (static_cast<int>(h)) {
    case 0: r = 1; g = x; break;
    case 1: r = x; g = 1; break;
    case 2: g = 1; b = x; break;
    case 3: g = x; b = 1; break;
    case 4: r = x; b = 1; break;
    default: r = 1; b = x; break;
  }
  return Eigen::Vector3i(static_cast<int>(55 + 200 * r), static_cast<int>(55 + 200 * g),
                         static_cast<int>(55 + 200 * b));
}

Status WriteOutputs(const MonoSlamRun& run, const std::string& dir, RunResult* result) {
  const double divide = run.lambda() > 0 ? run.lambda() : 1.0;
  SIGHTLINE_RETURN_IF_ERROR(WriteTumTrajectory(run.MetricEstimate(), (fs::path(dir) / "trajectory.txt").string()));
  SIGHTLINE_RETURN_IF_ERROR(WriteTumTrajectory(run.estimate, (fs::path(dir) / "trajectory_map.txt").string()));
  std::ostringstream ply;
  ply << "ply\nformat ascii 1.0\ncomment Sightline mono-slam map points ("
      << (run.lambda() > 0 ? "metres" : "map units") << "), coloured by creating keyframe\n"
      << "element vertex " << run.map->points.size()
      << "\nproperty float x\nproperty float y\nproperty float z\n"
         "property uchar red\nproperty uchar green\nproperty uchar blue\nend_header\n";
  for (const MapSnapshot::Point& p : run.map->points) {
    const Eigen::Vector3d x = p.position / divide;
    const Eigen::Vector3i c = KeyFrameColour(p.first_keyframe);
    ply << x.x() << ' ' << x.y() << ' ' << x.z() << ' ' << c.x() << ' ' << c.y() << ' ' << c.z() << '\n';
  }
  SIGHTLINE_RETURN_IF_ERROR(WriteFile((fs::path(dir) / "map.ply").string(), ply.str()));
  std::ostringstream kf;
  kf << "# keyframe frame timestamp tx ty tz qx qy qz qw points  (map_from_camera, "
     << (run.lambda() > 0 ? "metres" : "map units") << ")\n";
  for (const MapSnapshot::Frame& k : run.map->keyframes) {
    const Eigen::Vector3d t = k.map_from_camera.translation() / divide;
    const Eigen::Quaterniond q(k.map_from_camera.rotation());
    char line[256];
    std::snprintf(line, sizeof(line), "%lld %lld %.6f %.6f %.6f %.6f %.6f %.6f %.6f %.6f %d\n",
                  static_cast<long long>(k.id), static_cast<long long>(k.frame_index), k.time_s,
                  t.x(), t.y(), t.z(), q.x(), q.y(), q.z(), q.w(), k.points);
    kf << line;
  }
  SIGHTLINE_RETURN_IF_ERROR(WriteFile((fs::path(dir) / "keyframes.txt").string(), kf.str()));
  std::ostringstream scale;
  scale << "sample,single_ratio,ml_estimate,pair_ratio,pairs_used\n";
  for (const ScaleSample& s : run.scale.history()) {
    scale << s.index << ',' << s.single_ratio << ',' << s.max_likelihood << ',' << s.pair_ratio
          << ',' << s.pairs_used << '\n';
  }
  SIGHTLINE_RETURN_IF_ERROR(WriteFile((fs::path(dir) / "scale.csv").string(), scale.str()));
  std::ostringstream frames;
  frames << "frame,time_s,quality,tracked,keypoints,predicted,matches,inliers,rms_px,map_points,keyframes,"
            "new_keyframe,relocalised,tracking_ms,status\n";
  for (const MonoRunFrame& f : run.frames) {
    std::string status = f.stats.status;
    for (char& c : status) {
      if (c == '"' || c == ',') c = ';';
    }
    frames << f.frame << ',' << f.time_s << ',' << TrackingQualityName(f.quality) << ','
           << f.tracked << ',' << f.stats.keypoints << ',' << f.stats.predicted << ','
           << f.stats.matches << ','
           << f.stats.inliers << ',' << f.stats.rms_px << ',' << f.stats.map_points << ','
           << f.stats.keyframes << ',' << f.stats.new_keyframe << ',' << f.stats.relocalised << ','
           << f.stats.tracking_ms << ",\"" << status << "\"\n";
  }
  SIGHTLINE_RETURN_IF_ERROR(WriteFile((fs::path(dir) / "frames.csv").string(), frames.str()));
  result->outputs = {"trajectory.txt", "trajectory_map.txt", "map.ply", "keyframes.txt",
                     "scale.csv", "frames.csv"};
  return Status::Ok();
}

StatusOr<RunResult> RunMonoSlamPipeline(const RunContext& context) {
  const MonoSlamOptions options = context.options.Extract(MonoSlamOptions::Describe());
  const MonoSlamRunOptions run = context.options.Extract(MonoSlamRunOptions::Describe());
  StatusOr<MonoSlamRun> estimated = RunMonoSlam(context.dataset_path, options, run, context.timing,
                                                context.progress, context.cancel);
  if (!estimated.ok()) return estimated.status();
  RunResult result;
  result.dataset_format = estimated->dataset_format;
  result.frames = static_cast<int64_t>(estimated->frames.size());
  SIGHTLINE_RETURN_IF_ERROR(WriteOutputs(*estimated, context.out_dir, &result));
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
