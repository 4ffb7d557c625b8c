// The "inspect" pipeline: reads every frame of a dataset, checks it and times the reading.
// A data check before a long experiment, and the reference for decoding cost.
#pragma once

#include <cstdint>
#include <memory>
#include <string>

#include "core/options/option_table.h"
#include "core/pipeline/pipeline_registry.h"

namespace sightline {

// Options of the inspect pipeline.
struct InspectOptions {
  int max_frames = 0;            // Frames to read; 0 reads all.
  double max_depth_m = 10.0;     // Depth beyond this counts as invalid [m].
  double gt_tolerance_s = 0.02;  // A frame has ground truth if a pose lies this close in time [s].

  bool IsValid(std::string* error) const;
  static OptionTable<InspectOptions> Describe();
};

// The per-frame statistics of inspect: "inspect/check_ms" (the CLI's timing stage "check"), the
// frame's check by kind and "inspect/has_gt".
const StatisticTable& InspectStatistics();

// Checks every frame; Finish writes frames.csv (frame, time_s, kind-specific check, has_gt)
// and reports accuracy.gt_coverage (fraction of frames with a ground-truth pose).
class InspectPipeline : public Pipeline {
 public:
  InspectPipeline();
  ~InspectPipeline() override;

  Status Configure(const OptionSet& options) override;
  Status Open(const PipelineSource& source) override;
  int64_t FrameLimit() const override { return options_.max_frames; }
  StatusOr<std::shared_ptr<const PipelineResult>> Process(const Frame& frame) override;
  void Reset() override;
  StatusOr<RunResult> Finish(const std::string& out_dir) override;
  const StatisticTable& Statistics() const override { return InspectStatistics(); }

 private:
  InspectOptions options_;
  std::shared_ptr<const Trajectory> ground_truth_;
  std::string column_;  // The check's name: the first frame's kind.
  std::string rows_;    // frames.csv without its header.
  int64_t frames_ = 0;
  int64_t with_gt_ = 0;
};

// The pipeline's registry entry.
PipelineInfo InspectPipelineInfo();

}  // namespace sightline
