// The "inspect" pipeline: reads every frame of a dataset, checks it and times the reading.
// A data check before a long experiment, and the reference for decoding cost.
#pragma once

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

// Writes frames.csv (frame, time_s, kind-specific check, has_gt) and reports
// accuracy.gt_coverage (fraction of frames with a ground-truth pose).
PipelineInfo InspectPipeline();

}  // namespace sightline
