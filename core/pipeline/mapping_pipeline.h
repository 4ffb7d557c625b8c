// The "mapping" pipeline (seed 000): indoor Manhattan mapping from a Kinect recording, headless.
//
// Reads an RGB-D dataset (a TUM folder or a recording with an rgbd/ sensor folder). From the
// recording's top folder it also uses, when present: odometry.txt (wheel odometry, the dead
// reckoning pose source), people.csv (ground-truth person boxes), walls.csv (true wall faces,
// for accuracy) and scene.yaml (the camera's offset ahead of the odometry base).
//
// Writes trajectory.txt (TUM, camera poses), lines.csv, map.pgm + map.yaml (ROS map_server),
// map.png, floor.yaml (the floor calibration used), mapping_log.txt (per-frame status and every
// reset), and metrics.json with timing for occupancy, scan, lines, rotation, stitch and, with
// ground truth: accuracy.heading_error_deg_mean, heading_error_deg_max, ate_rmse_m, and with
// walls.csv also wall_angle_error_deg_median, wall_recall and map_iou (map_precision,
// map_recall).
#pragma once

#include <string>

#include "core/mapping/floor_plane.h"
#include "core/options/option_table.h"
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

// Calibrates the floor from the first `frames` frames of an RGB-D dataset or the clouds of a
// PCD file/folder (`sightline-cli floor`). `used_frames` receives the number of frames read.
StatusOr<FloorFitResult> CalibrateFloorFromDataset(const std::string& path, int frames,
                                                   const FloorPlaneOptions& options,
                                                   int* used_frames = nullptr);

// The pipeline's registry entry.
PipelineInfo MappingPipeline();

}  // namespace sightline
