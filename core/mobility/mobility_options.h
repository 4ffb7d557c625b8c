// Options of the mobility map (seed 001): every threshold of every stage, with the platform
// profiles (a wheelchair or mobile base by default, the seed's iCub as a profile). Keys
// "mobility.*".
#pragma once

#include <string>

#include "core/options/option_table.h"

namespace sightline {

// Which way the per-point stages run.
//  "grid": on the organized 640x480 pixel grid (a pixel stride stands in for the voxel grid,
//          normals from window sums of the point moments slid along the grid, denoising and
//          region growing over grid neighbours). Needs an organized cloud; the fast path.
//  "pcl":  the seed's unorganized path (PCL voxel grid, statistical outlier removal, k-d tree
//          normals and region growing over k-d tree neighbours). Any cloud.
// Both share the ground search, surface properties, scoring and the maps.
struct MobilityOptions {
  std::string mode = "grid";            // "grid" or "pcl".
  std::string platform = "wheelchair";  // "wheelchair", "icub" or "custom" (range_cut_m and
                                        // max_step_m as set below).
  double range_cut_m = 5.0;             // custom: points farther from the sensor are dropped [m].
  double max_step_m = 0.03;             // custom: a segment raised more than this above the
                                        // ground scores 0 [m].
  int min_points = 200;                 // Fewer points after the range cut is reported [points].

  // Downsampling.
  int grid_stride = 4;    // grid: every n-th pixel in both directions [px].
  double voxel_m = 0.01;  // pcl: voxel size of the voxel grid [m].

  // Denoising (statistical outlier removal, seed eq. 1: keep d <= mu + alpha sigma).
  int sor_k = 8;           // pcl: neighbours of the mean distance (grid: the 8
                           // grid neighbours, distances divided by depth).
  double sor_alpha = 2.0;  // Density restrictiveness factor alpha.

  // Normals (oriented towards the viewpoint).
  int normal_window = 3;         // grid: half-width of the normal's window [cells].
  int normal_k = 16;             // pcl: neighbours of the k-d tree normal fit.
  double max_curvature = 0.1;    // Points whose neighbourhood bends more (smallest
                                 // eigenvalue / sum: 0 flat, 1/3 isotropic) get no normal:
                                 // edges between surfaces stay unsegmented.
  double max_depth_jump = 0.05;  // grid: neighbours whose depth differs by more than this
                                 // fraction of the depth are not neighbours.

  // Ground: the lowest large plane whose normal lies near the expected up direction.
  double mount_pitch_deg = 0;             // Camera pitched down by this [deg] (expected up =
  double mount_roll_deg = 0;              // camera -y turned by pitch and roll) [deg].
  double up_tolerance_deg = 60;           // Largest angle between a ground normal and up [deg].
  double ground_distance_m = 0.02;        // RANSAC inlier distance at the sensor [m] ...
  double ground_distance_per_m2 = 0.004;  // ... growing with the depth squared like the Kinect's
                                          // noise and quantisation [m per m^2].
  double ground_normal_deg = 25;          // A ground point's own normal must lie this close [deg].
  double ransac_success = 0.99;           // p of seed eq. 6.
  double ransac_inlier_ratio = 0.3;       // Expected inlier ratio w of eq. 6 among the
                                          // points whose normals face up.
  int ground_candidates = 3;              // Up-facing planes searched before taking the lowest.
  double min_ground_ratio = 0.03;         // A candidate holds at least this fraction of points.
  int ransac_sample_points = 1500;        // Points a hypothesis is scored on.

  // Region growing on the RGB-N colours (seed Algorithm 1).
  double color_threshold = 14;          // Largest RGB-N colour distance of neighbours.
  double pcl_neighbor_radius_m = 0.03;  // pcl: neighbour radius of the region growing [m].
  int min_segment_points = 30;          // Smaller regions stay unsegmented (not scored).

  // Surface properties.
  int plane_ransac_iterations = 30;    // Per-segment RANSAC before the least-squares refit.
  double plane_distance_m = 0.015;     // Its inlier distance [m].
  double roughness_cell_m = 0.03;      // Points are averaged in plane cells of this size before
                                       // the triangulation (depth noise would read as roughness).
  double roughness_max_range_m = 2.5;  // Only points this close enter the roughness (Kinect
                                       // noise grows with z^2); all when none is [m].
  std::string triangulation = "grid";  // "grid" (cells' grid) or "delaunay" (cv::Subdiv2D).
  double max_edge_cells = 2.0;         // delaunay: triangles with a longer edge are dropped.
  double height_percentile = 0.05;     // Raised height = this quantile of the heights above
                                       // ground (a ramp touches the ground, a box top does not).
  double ramp_foot_m = 0.3;            // A sloped segment whose plane meets the ground within
                                       // this distance of its lowest points is not raised [m].

  // Scores.
  std::string score = "rule";  // Score shown and used for the maps: "rule" or "gpr".

  // Maps.
  double map_cell_m = 0.02;   // Top-view grid cell [m].
  double rgb_offset_x_m = 0;  // Depth-to-colour sensor offsets of seed eq. 13 [m].
  double rgb_offset_y_m = 0;

  // The effective range cut and step height of the platform.
  double RangeCutM() const;
  double MaxStepM() const;

  bool IsValid(std::string* error) const;
  static OptionTable<MobilityOptions> Describe();
};

}  // namespace sightline
