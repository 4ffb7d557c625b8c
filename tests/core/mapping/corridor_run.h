// Runs the mapping chain on the simulator's corridor in memory (no files) and measures it
// against the simulator's ground truth: heading error, wall angles, visible walls found, map
// agreement. Several mapping configurations run side by side on the same rendered frames.
#pragma once

#include <string>
#include <vector>

#include "core/common/status.h"
#include "core/mapping/mapping_accuracy.h"
#include "core/mapping/mapping_frame_processor.h"
#include "core/sim/scene.h"
#include "core/sim/simulation_options.h"

namespace sightline::testing {

// What one mapping configuration achieved on the corridor.
struct CorridorScore {
  HeadingErrors heading;  // Relative to the first frame [deg].
  double wall_angle_error_deg_median = 0;
  std::vector<double> wall_angle_errors_deg;
  int visible_walls = 0;            // (frame, wall) pairs visible to the scan.
  int found_walls = 0;              // ... of which a line matched the wall.
  std::vector<std::string> missed;  // "frame 12: wall 3 (1.8 m, 62 rays)".
  MapAgreement map;                 // Against the wall faces (walls.csv).
  MapAgreement map_all_obstacles;   // Against every static obstacle a scan can see: walls,
                                    // recessed doors, boxes, bins (TrueObstacleOutlines).
  int resets = 0;
  int frames = 0;
  // The base's position against the truth, both trajectories anchored at their first pose (no
  // best fit: this is the drift): the path driven, the final and the largest error [m].
  double path_m = 0;
  double position_error_final_m = 0;
  double position_error_max_m = 0;
  int odometry_failures = 0;          // Frames whose RGB-D odometry step failed.
  std::vector<double> odometry_ms;    // Per frame, when the RGB-D odometry ran.
  std::vector<double> frame_ms;       // Per-frame mapping time (occupancy .. stitch).
  std::vector<std::string> statuses;  // Per frame.
  // Detected people (boxes the chain used with id -1) against the true ones that are in view
  // (kPersonMinPixels or more pixels) kPersonMinRangeM to kPersonMaxRangeM from the camera: a true
  // person is found when a detection covers half of the smaller box; a detection is false when it
  // covers no true person's box (people out of range included) by a fifth of its own area.
  int people_visible = 0, people_found = 0;
  int people_detections = 0, people_false = 0;
  std::vector<std::string> people_missed;  // "frame 12: person 1 (840 px, 3.2 m)".
};

constexpr int kPersonMinPixels = 300;
constexpr double kPersonMinRangeM = 1.0;  // Nearer, a person fills the view (no head, no feet).
constexpr double kPersonMaxRangeM = 5.5;

// The simulation: a corridor drive of `metres` at `speed_mps` sampled at `rate_hz`, 320x240
// Kinect with the seed's noise ("kinect" profile), wheel odometry drifting
// `heading_drift_deg_per_m`.
sim::SimulationOptions CorridorSimulation(double metres, double rate_hz, double speed_mps,
                                          double heading_drift_deg_per_m, int seed = 1);

// The floor-plan outline of every static obstacle of a simulated scene between the two heights:
// vertical faces (walls, doors, boxes, posters) as segments, cylinders (bins) as 16-gons.
std::vector<TrueWall> TrueObstacleOutlines(const sim::Scene& scene, double min_height_m,
                                           double max_height_m);

// Renders every frame once and feeds it (depth, colour, the wheel odometry, the true person
// boxes) to one MappingFrameProcessor per entry of `configs`; the floor is calibrated from the
// first `floor_frames` frames. Fails on any error.
StatusOr<std::vector<CorridorScore>> RunCorridor(const sim::SimulationOptions& simulation,
                                                 const std::vector<MappingOptions>& configs,
                                                 int floor_frames = 3);

// A visible wall must cover at least this length and fraction of the scan's rays
// (the seed's ratio_min: walls holding fewer of the points cannot become lines).
constexpr double kVisibleWallMinLengthM = 1.0;
constexpr double kVisibleWallMinRayFraction = 0.2;
// Map agreement tolerance: 2 cells of the 5 cm map (Kinect noise at 4 m is 2.3 cm, and dead
// reckoning moves the trajectory by a few centimetres).
constexpr int kMapToleranceCells = 2;

}  // namespace sightline::testing
