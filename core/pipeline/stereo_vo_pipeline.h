// The `stereo-vo` pipeline: stereo visual odometry (core/stereo) over a recording, with
// trajectory.txt (TUM or KITTI), frames.csv and the accuracy block of metrics.json; and the
// run over every k-th frame that `sightline-cli sweep stereo-vo` repeats for k = 1..N.
#pragma once

#include <atomic>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "core/common/status.h"
#include "core/common/timing.h"
#include "core/common/trajectory.h"
#include "core/options/option_set.h"
#include "core/options/option_table.h"
#include "core/pipeline/pipeline_registry.h"
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

// Runs the odometry over `path` (a dataset through OpenDataset, stereo; or a sensor URI such as
// aravis://L,R through OpenSource), every `run.subsample`-th frame, with the calibration of
// run.calibration_file when set, else the source's. Live sources run until run.max_frames;
// `sensor_options` (sensors.* keys, DeclareSensorOptions) configure them.
// Errors: the source cannot be opened or gives no stereo calibration (the message names
// stereo.calibration_file), options are invalid, the calibration is unusable, or the run was
// cancelled.
StatusOr<StereoVoRun> RunStereoOdometry(
    const std::string& path, const StereoOdometryOptions& options, const StereoVoRunOptions& run,
    TimingStats* timing = nullptr, const std::function<void(int64_t, int64_t)>& progress = {},
    const std::atomic<bool>* cancel = nullptr, const OptionSet* sensor_options = nullptr);

// Accuracy figures of a run against its ground truth: AccuracyFigures() of EvaluateTrajectory,
// or, when the ground truth moves less than 5 cm (static), the estimated motion instead
// (static_translation_m, the largest distance from the first pose, and static_rotation_deg). Always
// adds estimated_length_m. Notes explain figures left out.
std::vector<std::pair<std::string, double>> StereoVoAccuracy(const StereoVoRun& run,
                                                             double gt_tolerance_s,
                                                             std::vector<std::string>* notes);

// The registry entry.
PipelineInfo StereoVoPipeline();

}  // namespace sightline
