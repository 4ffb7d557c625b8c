// The `mono-slam` pipeline: monocular SLAM (core/mono) over a recording's mono images (or a
// stereo recording's left images), metric scale from the arm's poses (arm_poses.txt +
// hand_eye.yaml beside the sensor folder) or from ground-truth displacements, and the files
// trajectory.txt (TUM, metric when the scale is known), trajectory_map.txt (map units),
// map.ply, keyframes.txt, scale.csv, frames.csv and metrics.json.
#pragma once

#include <atomic>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "core/common/status.h"
#include "core/common/timing.h"
#include "core/common/trajectory.h"
#include "core/mono/mono_slam.h"
#include "core/mono/scale_estimator.h"
#include "core/options/option_table.h"
#include "core/pipeline/mono_inputs.h"
#include "core/pipeline/mono_slam_result.h"
#include "core/pipeline/pipeline_registry.h"

namespace sightline {

// One processed frame.
struct MonoRunFrame {
  int64_t frame = -1;
  double time_s = 0;
  TrackingQuality quality = TrackingQuality::kInitialising;
  bool tracked = false;
  Eigen::Isometry3d map_from_camera = Eigen::Isometry3d::Identity();
  MonoFrameStats stats;
};

// The outcome of one run.
struct MonoSlamRun {
  std::string dataset_format;
  std::vector<MonoRunFrame> frames;
  Trajectory estimate;                     // Tracked frames, map units.
  std::shared_ptr<const MapSnapshot> map;  // After the last frame.
  std::vector<KeyFrameStats> keyframes;
  int lost_frames = 0, relocalisations = 0;
  std::string init_model;
  std::string metric_source;  // What the scale came from ("arm", ...), or "none".
  ScaleEstimator scale;
  std::optional<Trajectory> ground_truth;

  // Map units per metre, ML (0 when unknown).
  double lambda() const { return scale.max_likelihood(); }
  // The estimate in metres when the scale is known, else in map units.
  Trajectory MetricEstimate() const;
};

// Runs the pipeline over `path` (a mono recording or a stereo one's left images) and returns
// its run. Errors: unreadable dataset, no camera calibration, invalid options, an unreadable
// arm_poses.txt / hand_eye.yaml that was asked for, cancellation.
StatusOr<MonoSlamRun> RunMonoSlam(const std::string& path, const MonoSlamOptions& options,
                                  const MonoSlamRunOptions& run, TimingStats* timing = nullptr,
                                  const std::function<void(int64_t, int64_t)>& progress = {},
                                  const std::atomic<bool>* cancel = nullptr);

// accuracy.* of metrics.json: lost_frames, relocalisations, scale_ml, scale_single, and with
// ground truth ate_rmse_m (Sim(3)), ate_rmse_pct_of_path, ate_metric_rmse_m (SE(3) only, scale
// from the ML estimate), scale_true (of the final map: Sim(3) alignment of the keyframes),
// scale_error_pct_ml, scale_error_pct_single.
std::vector<std::pair<std::string, double>> MonoSlamAccuracy(const MonoSlamRun& run,
                                                             double gt_tolerance_s,
                                                             std::vector<std::string>* notes);

// Writes trajectory.txt, trajectory_map.txt, map.ply, keyframes.txt, scale.csv and frames.csv
// into `dir` and lists them in result->outputs.
Status WriteMonoSlamOutputs(const MonoSlamRun& run, const std::string& dir, RunResult* result);

// The mono-slam pipeline: MonoSlam over each frame (a mono image or a stereo pair's left), the
// metric scale re-estimated whenever the map changes, and the run's files on Finish.
class MonoSlamPipeline : public Pipeline {
 public:
  // `commands` (optional) carries a user's Reset map / Pause mapping from another thread.
  explicit MonoSlamPipeline(std::shared_ptr<MonoSlamCommands> commands = nullptr);
  ~MonoSlamPipeline() override;

  Status Configure(const OptionSet& options) override;
  // The same with parsed options (the button pipeline forces the metric source to the arm).
  Status Configure(const MonoSlamOptions& options, const MonoSlamRunOptions& run);
  Status Open(const PipelineSource& source) override;
  // The metric source the next Open uses (the button pipeline resolves auto per source).
  void SetMetricSource(const std::string& source) { run_.metric_source = source; }
  int64_t FrameLimit() const override { return run_.max_frames; }
  bool Wants(int64_t index) const override { return index % run_.stride == 0; }
  StatusOr<std::shared_ptr<const PipelineResult>> Process(const Frame& frame) override;
  // The typed result of Process.
  StatusOr<std::shared_ptr<const MonoSlamFrameResult>> ProcessMono(const Frame& frame);
  // Tracks the frame again on the map as it is (a still frame simply tracks again).
  StatusOr<std::shared_ptr<const PipelineResult>> Reprocess(const Frame& frame) override {
    return Process(frame);
  }
  void Reset() override;
  StatusOr<RunResult> Finish(const std::string& out_dir) override;
  const StatisticTable& Statistics() const override { return MonoSlamStatistics(); }

  // The run so far, with the map's final bundle adjustment (run once per map).
  StatusOr<MonoSlamRun> Summary();

  // What Open found: the camera, the measured camera poses (metres) and where they came from.
  const PinholeCamera& camera() const { return camera_; }
  const Trajectory& metric_poses() const { return metric_; }
  const std::string& metric_source() const { return metric_source_; }
  const std::optional<Trajectory>& ground_truth() const { return ground_truth_; }
  const MonoSlamRunOptions& run_options() const { return run_; }
  const MonoSlamOptions& slam_options() const { return options_; }
  int lost_frames() const;

 private:
  Status StartSlam();
  void AddFrameStats(const MonoSlamResult& r, MonoSlamFrameResult* out);
  void UpdateScale(const MonoSlamResult& r, MonoSlamFrameResult* out);

  std::shared_ptr<MonoSlamCommands> commands_;
  MonoSlamOptions options_;
  MonoSlamRunOptions run_;
  std::optional<PipelineSource> source_;
  PinholeCamera camera_;
  std::optional<Trajectory> ground_truth_;
  Trajectory metric_;
  std::string metric_source_ = "none";
  TimingStats slam_timing_;  // MonoSlam's stages, read into each frame's statistics.
  std::unique_ptr<MonoSlam> slam_;
  std::vector<MonoRunFrame> frames_;
  std::shared_ptr<const MapSnapshot> last_map_;
  double lambda_ = 0, single_ = 0;
  double final_bundle_ms_ = -1;  // The final bundle adjustment's time, once run.
};

}  // namespace sightline
