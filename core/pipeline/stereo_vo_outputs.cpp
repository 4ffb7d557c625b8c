// stereo-vo's run files and figures (StereoVoPipeline::Finish, StereoVoAccuracy), and its
// estimate-only headless run (RunStereoOdometry).
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>

#include "core/eval/evaluation.h"
#include "core/pipeline/stereo_vo_pipeline.h"

namespace sightline {

namespace {

// A ground-truth path shorter than this is a static recording [m].
constexpr double kStaticPathM = 0.05;

Status WriteNotes(const std::vector<std::string>& notes, const std::string& path) {
  std::ofstream log(path);
  for (const std::string& note : notes) log << note << "\n";
  log.flush();
  if (!log) return Unavailable("cannot write " + path);
  return Status::Ok();
}

// The pipeline as RunStereoOdometry runs it: its Finish hands over the estimate, no files.
class EstimateOnlyPipeline : public StereoVoPipeline {
 public:
  EstimateOnlyPipeline(StereoOdometryOptions odometry, StereoVoRunOptions run,
                       std::shared_ptr<StereoVoRun> out)
      : odometry_(std::move(odometry)), run_(std::move(run)), out_(std::move(out)) {}

  Status Configure(const OptionSet& options) override {
    (void)options;  // The typed options given at construction.
    return StereoVoPipeline::Configure(odometry_, run_);
  }
  StatusOr<RunResult> Finish(const std::string& out_dir) override {
    (void)out_dir;
    *out_ = run();
    RunResult result;
    result.dataset_format = out_->dataset_format;
    result.frames = static_cast<int64_t>(out_->frames.size());
    return result;
  }

 private:
  StereoOdometryOptions odometry_;
  StereoVoRunOptions run_;
  std::shared_ptr<StereoVoRun> out_;
};

// Why a run tracked nothing: no frame after the first got an accepted motion estimate (every
// one gated or lost). Empty when at least one did.
std::string NothingTracked(const std::vector<FrameStats>& frames) {
  size_t tracked = 0;
  const FrameStats* first_rejected = nullptr;
  for (size_t i = 1; i < frames.size(); ++i) {
    if (!frames[i].gated && frames[i].status == "ok") ++tracked;
    if (first_rejected == nullptr && frames[i].status != "ok") first_rejected = &frames[i];
  }
  if (tracked > 0) return "";
  if (frames.size() < 2) {
    return "no frame tracked: stereo-vo needs at least two frames, the run had " +
           std::to_string(frames.size());
  }
  return "no frame tracked: every one of the " + std::to_string(frames.size() - 1) +
         " frames after the first was gated or lost (first reason: " +
         (first_rejected ? first_rejected->status : std::string("none")) + ")";
}

}  // namespace

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

StatusOr<RunResult> StereoVoPipeline::Finish(const std::string& out_dir) {
  if (run_.frames.empty()) return FailedPrecondition("stereo-vo has processed no frame yet");
  namespace fs = std::filesystem;
  RunResult result;
  result.dataset_format = run_.dataset_format;
  result.frames = static_cast<int64_t>(run_.frames.size());
  const std::string trajectory_path = (fs::path(out_dir) / "trajectory.txt").string();
  SIGHTLINE_RETURN_IF_ERROR(run_options_.output_format == "kitti"
                                ? WriteKittiTrajectory(run_.estimate, trajectory_path)
                                : WriteTumTrajectory(run_.estimate, trajectory_path));
  result.outputs.push_back("trajectory.txt");
  SIGHTLINE_RETURN_IF_ERROR(
      log_.WriteCsv((fs::path(out_dir) / "frames.csv").string(), Statistics()));
  result.outputs.push_back("frames.csv");

  std::vector<std::string> notes;
  result.accuracy = StereoVoAccuracy(run_, run_options_.gt_tolerance_s, &notes);
  const double n = static_cast<double>(run_.frames.size());
  result.counts.emplace_back("frames_gated", log_.Sum("vo/gated"));
  result.counts.emplace_back("inliers_per_frame", log_.Sum("vo/inliers") / n);
  result.counts.emplace_back("stereo_matches_per_frame", log_.Sum("vo/stereo_matches") / n);
  result.nothing_achieved = NothingTracked(run_.frames);
  if (!result.nothing_achieved.empty()) notes.insert(notes.begin(), result.nothing_achieved);
  if (!notes.empty()) {
    SIGHTLINE_RETURN_IF_ERROR(
        WriteNotes(notes, (fs::path(out_dir) / "stereo_vo_notes.txt").string()));
    result.outputs.push_back("stereo_vo_notes.txt");
  }
  return result;
}

StatusOr<StereoVoRun> RunStereoOdometry(const std::string& path,
                                        const StereoOdometryOptions& options,
                                        const StereoVoRunOptions& run, TimingStats* timing,
                                        const std::function<void(int64_t, int64_t)>& progress,
                                        const std::atomic<bool>* cancel,
                                        const OptionSet* sensor_options) {
  auto estimate = std::make_shared<StereoVoRun>();
  PipelineInfo info = StereoVoPipelineInfo();
  info.create = [options, run, estimate] {
    return std::make_unique<EstimateOnlyPipeline>(options, run, estimate);
  };
  RunContext context;
  context.dataset_path = path;
  // Sources read the sensors.* keys; the pipeline takes the typed options given here.
  if (sensor_options != nullptr) context.options = *sensor_options;
  context.timing = timing;
  context.progress = progress;
  context.cancel = cancel;
  StatusOr<RunResult> result = RunHeadless(info, context);
  if (!result.ok()) return result.status();
  if (!result->ended_early.ok()) return result->ended_early;  // Cancelled: not a whole run.
  return std::move(*estimate);
}

StatusOr<StereoVoRun> RunStereoOdometry(const std::string& path, const OptionSet& options,
                                        TimingStats* timing) {
  return RunStereoOdometry(path, options.Extract(StereoOdometryOptions::Describe()),
                           options.Extract(StereoVoRunOptions::Describe()), timing, {}, nullptr,
                           &options);
}

}  // namespace sightline
