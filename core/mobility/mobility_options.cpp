#include "core/mobility/mobility_options.h"

namespace sightline {
namespace {

bool Invalid(std::string* error, const std::string& message) {
  if (error != nullptr) *error = "mobility." + message;
  return false;
}

}  // namespace

double MobilityOptions::RangeCutM() const {
  if (platform == "icub") return 1.75;       // The seed's 1.5-2 m.
  if (platform == "wheelchair") return 5.0;  // office1's floor lies 3.3-5 m away.
  return range_cut_m;
}

double MobilityOptions::MaxStepM() const {
  if (platform == "icub") return 0.05;  // A humanoid may step onto low surfaces.
  if (platform == "wheelchair") return 0.03;
  return max_step_m;
}

bool MobilityOptions::IsValid(std::string* error) const {
  if (mode != "grid" && mode != "pcl") return Invalid(error, "mode must be grid or pcl");
  if (platform != "wheelchair" && platform != "icub" && platform != "custom") {
    return Invalid(error, "platform must be wheelchair, icub or custom");
  }
  if (!(range_cut_m > 0)) return Invalid(error, "range_cut_m must be positive");
  if (!(max_step_m >= 0)) return Invalid(error, "max_step_m must be >= 0");
  if (min_points < 3) return Invalid(error, "min_points must be >= 3");
  if (grid_stride < 1) return Invalid(error, "grid_stride must be >= 1");
  if (!(voxel_m > 0)) return Invalid(error, "voxel_m must be positive");
  if (sor_k < 1) return Invalid(error, "sor_k must be >= 1");
  if (!(sor_alpha > 0)) return Invalid(error, "sor_alpha must be positive");
  if (normal_window < 1) return Invalid(error, "normal_window must be >= 1");
  if (normal_k < 3) return Invalid(error, "normal_k must be >= 3");
  if (!(max_curvature > 0)) return Invalid(error, "max_curvature must be positive");
  if (!(max_depth_jump > 0)) return Invalid(error, "max_depth_jump must be positive");
  if (!(up_tolerance_deg > 0 && up_tolerance_deg < 90)) {
    return Invalid(error, "up_tolerance_deg must lie in (0, 90)");
  }
  if (!(ground_distance_m > 0)) return Invalid(error, "ground_distance_m must be positive");
  if (!(ground_distance_per_m2 >= 0)) return Invalid(error, "ground_distance_per_m2 must be >= 0");
  if (!(ground_normal_deg > 0 && ground_normal_deg <= 90)) {
    return Invalid(error, "ground_normal_deg must lie in (0, 90]");
  }
  if (!(ransac_success > 0 && ransac_success < 1)) {
    return Invalid(error, "ransac_success must lie in (0, 1)");
  }
  if (!(ransac_inlier_ratio > 0 && ransac_inlier_ratio < 1)) {
    return Invalid(error, "ransac_inlier_ratio must lie in (0, 1)");
  }
  if (ground_candidates < 1) return Invalid(error, "ground_candidates must be >= 1");
  if (!(min_ground_ratio > 0 && min_ground_ratio < 1)) {
    return Invalid(error, "min_ground_ratio must lie in (0, 1)");
  }
  if (ransac_sample_points < 10) return Invalid(error, "ransac_sample_points must be >= 10");
  if (!(color_threshold > 0)) return Invalid(error, "color_threshold must be positive");
  if (!(pcl_neighbor_radius_m > 0)) return Invalid(error, "pcl_neighbor_radius_m must be positive");
  if (min_segment_points < 3) return Invalid(error, "min_segment_points must be >= 3");
  if (plane_ransac_iterations < 0) return Invalid(error, "plane_ransac_iterations must be >= 0");
  if (!(plane_distance_m > 0)) return Invalid(error, "plane_distance_m must be positive");
  if (!(roughness_cell_m > 0)) return Invalid(error, "roughness_cell_m must be positive");
  if (!(roughness_max_range_m > 0)) return Invalid(error, "roughness_max_range_m must be positive");
  if (triangulation != "grid" && triangulation != "delaunay") {
    return Invalid(error, "triangulation must be grid or delaunay");
  }
  if (!(max_edge_cells >= 1)) return Invalid(error, "max_edge_cells must be >= 1");
  if (!(height_percentile >= 0 && height_percentile <= 1)) {
    return Invalid(error, "height_percentile must lie in [0, 1]");
  }
  if (!(ramp_foot_m >= 0)) return Invalid(error, "ramp_foot_m must be >= 0");
  if (score != "rule" && score != "gpr") return Invalid(error, "score must be rule or gpr");
  if (!(map_cell_m > 0)) return Invalid(error, "map_cell_m must be positive");
  return true;
}

OptionTable<MobilityOptions> MobilityOptions::Describe() {
  using O = MobilityOptions;
  return OptionTable<O>("mobility")
      .Choice("mode", &O::mode, {"grid", "pcl"},
              "grid: organized pixel-grid path (fast); pcl: the published voxel grid, outlier "
              "removal and k-d tree path.")
      .Choice("platform", &O::platform, {"wheelchair", "icub", "custom"},
              "wheelchair: 5 m range, 3 cm step; icub: 1.75 m, 5 cm (the published humanoid); "
              "custom: range_cut_m and max_step_m.")
      .Double("range_cut_m", &O::range_cut_m, "m", 0.1, 20, 0.1,
              "custom platform: points farther from the sensor are dropped.")
      .Double("max_step_m", &O::max_step_m, "m", 0, 1, 0.005,
              "custom platform: a segment raised more than this above the ground scores 0.")
      .Int("min_points", &O::min_points, "points", 3, 1e6, 10,
           "Fewer points left after the range cut is reported as an error.")
      .Int("grid_stride", &O::grid_stride, "px", 1, 16, 1,
           "grid: every n-th pixel in both directions (stands in for the voxel grid).")
      .Double("voxel_m", &O::voxel_m, "m", 0.001, 0.2, 0.001, "pcl: voxel grid leaf size.")
      .Int("sor_k", &O::sor_k, "", 1, 100, 1, "pcl: neighbours of the outlier removal.")
      .Double("sor_alpha", &O::sor_alpha, "", 0.1, 10, 0.1,
              "Outlier removal: keep points with mean neighbour distance <= mu + alpha sigma.")
      .Int("normal_window", &O::normal_window, "cells", 1, 20, 1,
           "grid: half-width of the window of grid points each normal is fitted to.")
      .Int("normal_k", &O::normal_k, "", 3, 100, 1, "pcl: neighbours of the normal fit.")
      .Double("max_curvature", &O::max_curvature, "", 0.001, 0.34, 0.001,
              "Points whose neighbourhood bends more (surface variation, 0 = flat) get no normal "
              "and stay unsegmented: edges between surfaces.")
      .Double("max_depth_jump", &O::max_depth_jump, "", 0.005, 1, 0.005,
              "grid: grid neighbours whose depths differ by more than this fraction are apart.")
      .Double("mount_pitch_deg", &O::mount_pitch_deg, "deg", -90, 90, 1,
              "Camera pitched down by this: expected up = camera -y turned by pitch and roll.")
      .Double("mount_roll_deg", &O::mount_roll_deg, "deg", -90, 90, 1, "Camera roll.")
      .Double("up_tolerance_deg", &O::up_tolerance_deg, "deg", 1, 89, 1,
              "A ground plane's normal lies at most this far from the expected up direction.")
      .Double("ground_distance_m", &O::ground_distance_m, "m", 0.001, 0.5, 0.005,
              "Ground RANSAC inlier distance at the sensor ...")
      .Double("ground_distance_per_m2", &O::ground_distance_per_m2, "m/m^2", 0, 0.1, 0.001,
              "... plus this times the depth squared (Kinect noise and quantisation).")
      .Double("ground_normal_deg", &O::ground_normal_deg, "deg", 1, 90, 1,
              "A ground point's own normal lies at most this far from the plane's.")
      .Double("ransac_success", &O::ransac_success, "", 0.5, 0.99999, 0.001,
              "Published eq. 6: wanted probability p of drawing one all-inlier sample.")
      .Double("ransac_inlier_ratio", &O::ransac_inlier_ratio, "", 0.01, 0.99, 0.01,
              "Published eq. 6: expected inlier ratio w; iterations = log(1-p) / log(1-w^3).")
      .Int("ground_candidates", &O::ground_candidates, "planes", 1, 10, 1,
           "Up-facing planes searched; the lowest large one is the ground.")
      .Double("min_ground_ratio", &O::min_ground_ratio, "", 0.001, 0.9, 0.005,
              "A ground candidate holds at least this fraction of the points.")
      .Int("ransac_sample_points", &O::ransac_sample_points, "points", 10, 1e6, 100,
           "Points each ground hypothesis is scored on.")
      .Double("color_threshold", &O::color_threshold, "", 0.5, 255, 0.5,
              "Region growing: largest RGB-N colour distance between neighbours (255 (n+1)/2).")
      .Double("pcl_neighbor_radius_m", &O::pcl_neighbor_radius_m, "m", 0.002, 0.5, 0.002,
              "pcl: neighbour radius of the region growing.")
      .Int("min_segment_points", &O::min_segment_points, "points", 3, 1e6, 1,
           "Smaller regions stay unsegmented and unscored.")
      .Int("plane_ransac_iterations", &O::plane_ransac_iterations, "", 0, 10000, 10,
           "Per-segment plane RANSAC iterations before the least-squares refit (0 = PCA only).")
      .Double("plane_distance_m", &O::plane_distance_m, "m", 0.001, 0.5, 0.005,
              "Per-segment plane RANSAC inlier distance.")
      .Double("roughness_cell_m", &O::roughness_cell_m, "m", 0.002, 0.5, 0.005,
              "Roughness: points are averaged in plane cells of this size, then triangulated.")
      .Double("roughness_max_range_m", &O::roughness_max_range_m, "m", 0.1, 20, 0.1,
              "Roughness uses the segment's points within this range (all when none is).")
      .Choice("triangulation", &O::triangulation, {"grid", "delaunay"},
              "Roughness triangulation in plane coordinates: the cells' grid or 2D Delaunay.")
      .Double("max_edge_cells", &O::max_edge_cells, "cells", 1, 10, 0.1,
              "delaunay: triangles with an edge longer than this many cells are dropped.")
      .Double("height_percentile", &O::height_percentile, "", 0, 1, 0.01,
              "A segment's raised height is this quantile of its heights above the ground.")
      .Double("ramp_foot_m", &O::ramp_foot_m, "m", 0, 2, 0.01,
              "A sloped segment whose plane meets the ground within this distance of its lowest "
              "points is connected to the ground (a ramp), not raised.")
      .Choice("score", &O::score, {"rule", "gpr"},
              "Score drawn in the maps: the published Table I rule or the Gaussian process.")
      .Double("map_cell_m", &O::map_cell_m, "m", 0.005, 0.5, 0.005, "Top-view grid cell.")
      .Double("rgb_offset_x_m", &O::rgb_offset_x_m, "m", -0.2, 0.2, 0.001,
              "Published eq. 13: depth-to-colour sensor offset along x.")
      .Double("rgb_offset_y_m", &O::rgb_offset_y_m, "m", -0.2, 0.2, 0.001,
              "Published eq. 13: depth-to-colour sensor offset along y.");
}

}  // namespace sightline
