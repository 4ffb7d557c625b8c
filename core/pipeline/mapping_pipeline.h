// The "mapping" pipeline (seed 000): indoor Manhattan mapping from a Kinect recording, one
// object run headless (`sightline-cli run mapping`) and in the GUI.
//
// Reads an RGB-D dataset (a TUM folder or a recording with an rgbd/ sensor folder). From the
// recording's top folder it also uses, when present: odometry.txt (wheel odometry, the dead
// reckoning pose source unless mapping.pose.source asks for RGB-D odometry or none; without it
// auto uses RGB-D odometry), people.csv (ground-truth person boxes), walls.csv (true wall faces,
// for accuracy) and scene.yaml (the camera's offset ahead of the odometry base).
//
// Finish writes trajectory.txt (TUM, camera poses), lines.csv, map.pgm + map.yaml (ROS map_server),
// map.png, floor.yaml (the floor calibration used), mapping_log.txt (per-frame status and every
// reset, the pose source used), and metrics.json with timing for occupancy, scan, lines, odometry
// (RGB-D), rotation, stitch, the pose source as a note and counts, and, with
// ground truth: accuracy.heading_error_deg_mean, heading_error_deg_max, ate_rmse_m, and with
// walls.csv also wall_angle_error_deg_median, wall_recall and map_iou (map_precision,
// map_recall).
#pragma once

#include <memory>
#include <string>

#include "core/options/option_table.h"
#include "core/pipeline/mapping_result.h"
#include "core/pipeline/pipeline_registry.h"

namespace sightline {

// Options of a mapping run besides the mapping chain's own. Keys "mapping.run.*".
struct MappingRunOptions {
  int max_frames = 0;                    // Frames to process; 0 = all.
  std::string floor_file;                // Floor calibration to use; "" = calibrate from the
                                         // first floor_frames frames.
  int floor_frames = 5;                  // Frames for the automatic floor calibration.
  double gt_tolerance_s = 0.02;          // Pose association tolerance (ground truth, odometry) [s].
  bool camera_offset_from_scene = true;  // Read the camera's offset ahead of the odometry base
                                         // from scene.yaml (simulator) when present.
  double camera_forward_m = 0.0;         // Else: the camera's optical centre ahead of the
                                         // odometry base [m].
  int map_tolerance_cells = 2;           // Tolerance of the map agreement (map_iou) [cells].
  double visible_wall_min_length_m = 1.0;  // A true wall counts as visible in a frame when this
  double visible_wall_min_fraction = 0.2;  // much of it and this fraction of the scan's rays
                                           // hit it (ratio_min: smaller walls cannot be lines).

  bool IsValid(std::string* error) const;
  static OptionTable<MappingRunOptions> Describe();
};

// The mapping pipeline: the floor calibration (mapping.run.floor_file, or fitted on the first
// mapping.run.floor_frames frames, which are then mapped too), the mapping chain on every
// frame, and the run's files and figures. The one object `sightline-cli run mapping` and the
// GUI run. `requests` (optional) carries the GUI's "Calibrate floor".
class MappingPipeline : public Pipeline {
 public:
  explicit MappingPipeline(std::shared_ptr<const MappingRequests> requests = nullptr);
  ~MappingPipeline() override;

  Status Configure(const OptionSet& options) override;
  Status Open(const PipelineSource& source) override;
  int64_t FrameLimit() const override;
  StatusOr<std::shared_ptr<const PipelineResult>> Process(const Frame& frame) override;
  void Reset() override;
  StatusOr<RunResult> Finish(const std::string& out_dir) override;
  const StatisticTable& Statistics() const override { return MappingStatistics(); }

  // The run's state (mapping_run.h; for the pipeline's own source files).
  struct State;

 private:
  std::unique_ptr<State> state_;
};

// The pipeline's options: the mapping chain's (MappingOptions, with the map rendered every 10
// frames for views) and mapping.run.*.
Status DeclareMappingOptions(OptionSet* options);

// The pipeline's registry entry; its objects share `requests` when given.
PipelineInfo MappingPipelineInfo(const std::shared_ptr<const MappingRequests>& requests = nullptr);

}  // namespace sightline
