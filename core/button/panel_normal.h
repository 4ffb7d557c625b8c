// The panel's normal for the approach direction. Preferred: the plane from the arm's motion
// (arm_plane_normal.h). Otherwise: a robust plane through the SLAM map points
// around the located button (the plate and the wall around it, up to 45 cm away: the wider the
// surface, the less a map's depth errors tilt it), passing near the located button (so that a
// side wall or a door frame cannot give the push direction), oriented toward the camera, with
// its own angular uncertainty; and its average over frames in data time (the panel and the
// arm's base stay put during an approach).
#pragma once

#include <Eigen/Geometry>
#include <string>
#include <vector>

#include "core/common/status.h"
#include "core/options/option_table.h"

namespace sightline {

// Panel normal options. Keys "button.normal.*".
struct PanelNormalOptions {
  double radius_m = 0.45;             // Map points within this of the located button [m].
  int min_points = 12;                // Fewer points (or inliers): no normal this frame.
  int ransac_iterations = 300;        // Plane hypotheses.
  double ransac_threshold_m = 0.003;  // Plane inlier distance [m].
  double max_button_offset_m = 0.03;  // The plane passes this near the located button [m].
  double min_sigma_deg = 0.5;         // Floor of a frame's 1-sigma (weights, outlier test).
  double stated_min_sigma_deg = 1.5;  // Floor of the sigma a target states [deg].
  double smoothing_s = 2.0;           // Time constant of the data-time average [s]; 0 = none.
  double outlier_sigmas = 4;          // A frame this many sigmas off the average is skipped.
  uint64_t seed = 7;                  // RANSAC random seed (deterministic runs).
  // The plane from the arm's motion (arm_plane_normal.h), preferred to the map's when it has
  // one: corners tracked around the button, their homography given the arm's poses.
  bool arm_motion = true;
  double arm_min_parallax_deg = 3.0;  // Arm motion since the anchor, seen from the panel [deg].
  int arm_max_corners = 300;          // Corners tracked around the button.
  double arm_inlier_px = 1.5;         // Inlier distance of a track to the plane's transfer [px].

  bool IsValid(std::string* error) const;
  static OptionTable<PanelNormalOptions> Describe();
};

// One frame's panel normal, in the camera frame.
struct PanelNormal {
  Eigen::Vector3d normal_in_camera = -Eigen::Vector3d::UnitZ();  // Unit, toward the camera.
  double sigma_rad = 0;  // 1-sigma angular uncertainty of the normal.
  int points = 0;        // Map points within radius_m.
  int inliers = 0;       // Plane inliers.
  double rms_m = 0;      // RMS distance of the inliers to the plane.
};

// The panel plane around `button_in_camera` from `points_in_camera`: RANSAC, then least squares
// on the inliers; the normal points toward the camera. NotFound with the counts when fewer than
// min_points points (or inliers) are there; InvalidArgument for invalid options.
StatusOr<PanelNormal> EstimatePanelNormal(const std::vector<Eigen::Vector3d>& points_in_camera,
                                          const Eigen::Vector3d& button_in_camera,
                                          const PanelNormalOptions& options);

// The data-time average of per-frame normals given in one fixed frame (e.g. the arm's base):
// each frame weighs 1/sigma^2, and older frames fade with exp(-age / smoothing_s). The average's
// sigma is the weighted mean of the frames' sigmas (they share one map: it does not shrink with
// their number), widened by their spread about the average. A frame far off the average is
// skipped; when frames are skipped for longer than the smoothing time (and at least
// kMinSkippedToRestart of them), the average starts again from the latest.
class NormalAverage {
 public:
  explicit NormalAverage(PanelNormalOptions options = {}) : options_(options) {}
  // Adds a frame's normal at data time `stamp_s`; false when it is skipped as an outlier. A
  // stamp older than the last one starts the average again.
  bool Add(double stamp_s, const Eigen::Vector3d& normal, double sigma_rad);
  bool empty() const { return frames_ == 0; }
  int frames() const { return frames_; }
  Eigen::Vector3d normal() const;  // Unit; NaN when empty.
  double sigma_rad() const;        // Infinite when empty.
  void Reset();

 private:
  static constexpr int kMinSkippedToRestart = 3;
  // Sums faded below this share of one frame at the floor sigma are dropped.
  static constexpr double kFadedFraction = 1e-9;

  void Decay(double stamp_s);
  double sigma_rad_inner() const;  // Weighted mean of the frames' sigmas.

  PanelNormalOptions options_;
  int frames_ = 0;
  double last_stamp_s_ = 0;
  int skipped_ = 0;             // Frames skipped in a row.
  double first_skipped_s_ = 0;  // Data time of the first of them.
  Eigen::Vector3d sum_normal_ = Eigen::Vector3d::Zero();
  double sum_weight_ = 0, sum_weight_sigma_ = 0, sum_weight_dev2_ = 0;
};

}  // namespace sightline
