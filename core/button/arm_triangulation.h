// The button's 3D position from the arm's metric camera poses alone, independent of the
// monocular map's scale and structure: every tracked frame gives the button centre's pixel
// (a viewing ray, metric through the arm's pose times the hand-eye transform) and the button's
// apparent size. The rays cross where the camera moved across them (the sideways move), and the
// size grows as 1 / depth while the camera moves along them (looming: s_i / s_j = z_j / z_i, the
// measured forward displacement gives the depth in metres). One robust least squares over the
// pixel residuals and the log-size residuals solves for the point and the size constant.
#pragma once

#include <Eigen/Geometry>
#include <optional>
#include <string>
#include <vector>

#include "core/common/camera.h"
#include "core/common/status.h"
#include "core/options/option_table.h"

namespace sightline {

// Keys "button.triangulate.*".
struct ArmTriangulationOptions {
  bool enabled = false;           // Combine the triangulated point with the map's (by variances).
  double pixel_sigma_px = 1.0;    // 1-sigma of the tracked centre [px] ...
  double pixel_sigma_rel = 0.05;  // ... plus this fraction of the tracked radius (the model
                                  // centre's offset grows with the apparent size).
  bool use_size = true;           // Use the apparent size (looming) besides the rays.
  bool anchor_size = true;        // The size from the tap's own keypoints (no refresh drift;
                                  // ButtonTrack::anchor_scale), else ButtonTrack::radius_px.
  double size_sigma_rel = 0.01;   // 1-sigma relative error of the tracked size [-].
  bool pixel_offset = true;       // Estimate a constant image offset of the tracked centre.
  double robust_sigmas = 2.0;     // Huber threshold [sigmas].
  int min_views = 8;              // Fewer tracked views: no estimate.
  double min_depth_span = 0.1;    // Looming needs depths differing by this fraction ...
  double min_baseline_m = 0.02;   // ... or rays from camera centres this far apart [m].
  double floor_sigma_m = 0.005;   // Added to the stated 1-sigma: biases no residual shows (the
                                  // tracked centre and size follow features partly on the plate
                                  // behind the button's face: 0-5 mm on the simulated panel) [m].
  int iterations = 15;            // Gauss-Newton iterations (reweighted).

  bool IsValid(std::string* error) const;
  static OptionTable<ArmTriangulationOptions> Describe();
};

// One tracked frame: where the camera was (metric, arm base frame), the tracked centre and the
// button's apparent radius (ButtonTrack::radius_px; 0 = unknown).
struct ArmView {
  Eigen::Isometry3d base_from_camera = Eigen::Isometry3d::Identity();
  Eigen::Vector2d pixel = Eigen::Vector2d::Zero();
  double radius_px = 0;
};

// The triangulated button in the arm's base frame.
struct ArmTriangulation {
  Eigen::Vector3d in_base = Eigen::Vector3d::Zero();
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Identity();  // [m^2], incl. the floor.
  double radius_at_1m_px = 0;  // The fitted size constant: apparent radius times depth [px m].
  Eigen::Vector2d pixel_offset_px = Eigen::Vector2d::Zero();  // The tracked centre's offset.
  int views = 0;                                              // Views used.
  int inliers = 0;         // Views whose residuals lie within the robust threshold.
  double rms_px = 0;       // RMS pixel residual of the inliers.
  double rms_size = 0;     // RMS relative size residual of the inliers.
  bool used_size = false;  // The looming constraint entered the fit.
  // 1-sigma along the largest axis of the covariance [m].
  double SigmaMaxM() const;
};

// Solves for the point seen in `views` through `camera` (no distortion, as the tracker's
// pixels). `prior_in_base` (e.g. the map's estimate) only starts the iteration when the rays
// alone do not fix the point. FailedPrecondition when the views neither cross nor loom enough
// (min_views, min_baseline_m, min_depth_span) or the fit is degenerate; InvalidArgument for
// invalid options.
StatusOr<ArmTriangulation> TriangulateFromArm(
    const std::vector<ArmView>& views, const PinholeCamera& camera,
    const ArmTriangulationOptions& options,
    const std::optional<Eigen::Vector3d>& prior_in_base = std::nullopt);

}  // namespace sightline
