// The `stereo-vo` pipeline: stereo visual odometry (core/stereo) over a recording or a live pair,
// as one Pipeline object run by the CLI's headless loop, `sightline-cli sweep stereo-vo` and the
// GUI. Its files: trajectory.txt (TUM or KITTI), frames.csv, stereo_vo_notes.txt and the accuracy
// block of metrics.json.
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
#include "core/options/option_set.h"
#include "core/options/option_table.h"
#include "core/pipeline/pipeline_registry.h"
#include "core/pipeline/statistics_log.h"
#include "core/pipeline/stereo_vo_result.h"
#include "core/stereo/stereo_odometry.h"

namespace sightline {

// Run-level options of stereo-vo. Keys "stereo.*".
struct StereoVoRunOptions {
  int subsample = 1;                  // Process every k-th frame (the seed's Table 1 sweep).
  std::string output_format = "tum";  // trajectory.txt as tum or kitti.
  int max_frames = 0;                 // Frames read (before subsampling); 0 = all.
  double gt_tolerance_s = 0.02;       // Ground-truth association tolerance [s].
  std::string calibration_file;       // OpenCV stereo YAML replacing the source's; "" = source's.

  bool IsValid(std::string* error) const;
  static OptionTable<StereoVoRunOptions> Describe();
};

// The estimate of one run over a dataset.
struct StereoVoRun {
  std::string dataset_format;
  Trajectory estimate;                     // One pose per processed frame.
  std::vector<FrameStats> frames;          // One per processed frame.
  std::vector<int64_t> sequence_ids;       // Source frame index of each processed frame.
  std::optional<Trajectory> ground_truth;  // The source's, if any.
};

// The pipeline object. Configure with the option set of StereoVoPipelineInfo(), Open with a
// stereo source (its calibration, or stereo.calibration_file's), then Process its frames.
class StereoVoPipeline : public Pipeline {
 public:
  StereoVoPipeline() = default;

  Status Configure(const OptionSet& options) override;
  // The same with typed options.
  Status Configure(const StereoOdometryOptions& odometry, const StereoVoRunOptions& run);
  // Errors: not a stereo source, stereo.calibration_file unreadable or for another image size,
  // no calibration at all (the message names stereo.calibration_file), an unusable rig.
  Status Open(const PipelineSource& source) override;
  bool Wants(int64_t index) const override { return index % run_options_.subsample == 0; }
  int64_t FrameLimit() const override { return run_options_.max_frames; }
  StatusOr<std::shared_ptr<const PipelineResult>> Process(const Frame& frame) override;
  void Reset() override;
  StatusOr<RunResult> Finish(const std::string& out_dir) override;
  const StatisticTable& Statistics() const override { return StereoVoStatistics(); }

  // The run so far: the estimate, every frame's statistics, the source's ground truth.
  const StereoVoRun& run() const { return run_; }

 private:
  // Builds the odometry for the opened source's rig (or stereo.calibration_file's) with the
  // current options, and starts the run over.
  Status StartOdometry();
  // The ground-truth pose of a frame at `time_s`, relative to the run's first matched one.
  std::optional<Eigen::Isometry3d> GroundTruthAt(double time_s);

  StereoOdometryOptions odometry_options_;
  StereoVoRunOptions run_options_;
  std::optional<SourceInfo> source_info_;  // Set by Open.
  std::shared_ptr<const Trajectory> ground_truth_;
  std::unique_ptr<StereoOdometry> odometry_;
  std::optional<Eigen::Isometry3d> first_ground_truth_;  // world_from_camera of the first match.
  StereoVoRun run_;
  StatisticsLog log_;
};

// Runs the pipeline object headless (RunHeadless) over `path` (a dataset, stereo; or a sensor
// URI such as aravis://L,R), every `run.subsample`-th frame, and returns its estimate without
// writing files. Live sources run until run.max_frames; `sensor_options` (sensors.* keys,
// DeclareSensorOptions) configure them. Errors as StereoVoPipeline::Open's, or the run was
// cancelled or gave no frame.
StatusOr<StereoVoRun> RunStereoOdometry(
    const std::string& path, const StereoOdometryOptions& options, const StereoVoRunOptions& run,
    TimingStats* timing = nullptr, const std::function<void(int64_t, int64_t)>& progress = {},
    const std::atomic<bool>* cancel = nullptr, const OptionSet* sensor_options = nullptr);
// The same with an option set declared by StereoVoPipelineInfo().declare_options.
StatusOr<StereoVoRun> RunStereoOdometry(const std::string& path, const OptionSet& options,
                                        TimingStats* timing = nullptr);

// Accuracy figures of a run against its ground truth: AccuracyFigures() of EvaluateTrajectory,
// or, when the ground truth moves less than 5 cm (static), the estimated motion instead
// (static_translation_m, the largest distance from the first pose, and static_rotation_deg). Always
// adds estimated_length_m. Notes explain figures left out.
std::vector<std::pair<std::string, double>> StereoVoAccuracy(const StereoVoRun& run,
                                                             double gt_tolerance_s,
                                                             std::vector<std::string>* notes);

// The registry entry: title "Stereo visual odometry", stereo sources, the odometry's, the run's
// and the sensors' options.
PipelineInfo StereoVoPipelineInfo();

}  // namespace sightline
