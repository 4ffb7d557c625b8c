// What the `mono-slam` pipeline (core/pipeline/mono_slam_pipeline.h) gives its views for one
// frame, its table of per-frame statistics, and the requests a user sends it while it runs.
// No estimator classes: the GUI includes this header.
#pragma once

#include <atomic>
#include <memory>
#include <string>
#include <vector>

#include "core/mono/mono_types.h"
#include "core/pipeline/pipeline.h"
#include "core/pipeline/pipeline_registry.h"

namespace sightline {

// One frame of the monocular SLAM, immutable once made.
struct MonoSlamFrameResult : PipelineResult {
  std::shared_ptr<const MonoSlamResult> slam;  // Pose, tracked features, map (null on error).
  // The scale estimate's history, recomputed when the map changed; null when unchanged.
  std::shared_ptr<const std::vector<ScaleSample>> scale_history;
  double lambda = 0;          // ML map units per metre, 0 = unknown.
  double single_ratio = 0;    // Single-ratio estimate, 0 = unknown.
  std::string metric_source;  // "arm", "ground_truth", "none"; button: "arm_stream".
};

// A user's requests to a running mono-slam pipeline; any thread may call them. The pipeline
// applies them at its next frame.
class MonoSlamCommands {
 public:
  void ResetMap() { reset_ = true; }
  void PauseMapping(bool paused) { pause_mapping_ = paused; }

  // For the pipeline: whether a reset was asked since the last call; whether mapping is paused.
  bool TakeReset() { return reset_.exchange(false); }
  bool mapping_paused() const { return pause_mapping_.load(); }

 private:
  std::atomic<bool> reset_{false};
  std::atomic<bool> pause_mapping_{false};
};

// The statistics every MonoSlamFrameResult may hold ("mono/inliers", "mono/tracking_ms", ...).
const StatisticTable& MonoSlamStatistics();

// The registry entry of "mono-slam"; `commands` reach every pipeline object it creates (the
// GUI's Reset map and Pause mapping).
PipelineInfo MonoSlamPipelineInfo(const std::shared_ptr<MonoSlamCommands>& commands = nullptr);

}  // namespace sightline
