// What the "mobility" pipeline (mobility_pipeline.h) hands its views for one frame, and its
// table of per-frame statistics. Plain data: views include this header, never the mapper.
#pragma once

#include <memory>
#include <opencv2/core.hpp>
#include <string>
#include <vector>

#include "core/common/frame.h"
#include "core/mobility/mobility_types.h"
#include "core/pipeline/pipeline.h"

namespace sightline {

// One frame of the mobility pipeline: the mapper's result and the scored cloud coloured three
// ways for the 3D view. `mobility` is null when the frame could not be read as a cloud.
struct MobilityFrameResult : PipelineResult {
  std::shared_ptr<const MobilityResult> mobility;
  std::shared_ptr<const PointCloud> by_score;    // The scored cloud in rule-score colours.
  std::shared_ptr<const PointCloud> by_gpr;      // ... in GPR-score colours.
  std::shared_ptr<const PointCloud> by_segment;  // ... in segment colours.
};

// The mapper's stages in the seed's Table II order: their timing is "mobility/<stage>_ms"
// (the CLI's timing stages) and the points entering them "mobility/<stage>_points".
const std::vector<std::string>& MobilityStages();

// The statistics of a mobility frame: per stage "_ms" and "_points", "mobility/segments",
// "mobility/ground_height_m" (when the ground was found).
const StatisticTable& MobilityStatistics();

// The GPR score over slope and roughness (fixed: the model is trained on the seed's table).
cv::Mat MobilityScoreSurface();

}  // namespace sightline
