// What the "mapping" pipeline (mapping_pipeline.h) hands its views for one frame, its table of
// per-frame statistics, and the requests a view may send it. Plain data: views include this
// header, never the mapping chain's classes.
#pragma once

#include <Eigen/Geometry>
#include <atomic>
#include <memory>
#include <optional>
#include <string>

#include "core/common/floor.h"
#include "core/mapping/mapping_types.h"
#include "core/pipeline/pipeline.h"

namespace sightline {

// One frame of the mapping pipeline. `mapping` is null while the floor is being calibrated
// (then `note` says how far) or when the frame could not be mapped (`status` says why).
struct MappingResult : PipelineResult {
  std::shared_ptr<const MappingFrameResult> mapping;
  std::optional<FloorPlane> floor;  // The floor calibration in use.
  Eigen::Isometry3d base_from_camera = Eigen::Isometry3d::Identity();
  std::string note;  // E.g. "calibrating the floor (2 of 5 frames)".
};

// Requests from the GUI thread to a mapping pipeline running on the playback worker.
struct MappingRequests {
  // Bumped to ask for a new floor calibration from the next frames ("Calibrate floor").
  std::atomic<int> floor_calibrations{0};
};

// The statistics every mapping frame publishes: "mapping/<stage>_ms" per stage of the chain
// (people, occupancy, scan, lines, odometry, rotation, stitch: the CLI's timing stages),
// "mapping/scan_points", "mapping/lines", "mapping/heading_deg", "mapping/reset" and, with RGB-D
// odometry, "mapping/odometry_failed".
const StatisticTable& MappingStatistics();

}  // namespace sightline
