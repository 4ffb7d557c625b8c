// The button's 3D position from the map (the seed's interaction phase): map points whose
// projection lies near the tracked button centre, a plane through them (RANSAC, then least
// squares on the inliers) that judges whether the panel there is sound, the panel plane over a
// wider disc (panel_radii tracked radii, a robust fit) moved onto the button's face by its
// points' median offset, the viewing ray through the button centre intersected with that plane,
// and the plane normal as the approach direction.
#pragma once

#include <Eigen/Geometry>
#include <string>
#include <vector>

#include "core/common/camera.h"
#include "core/common/status.h"
#include "core/options/option_table.h"

namespace sightline {

// Locator options. Keys "button.locate.*".
struct ButtonLocatorOptions {
  double button_radii = 0.9;          // Map points within this many tracked button radii lie on
                                      // the button's face; 0 = ignore the face.
  double radius_px = 60;              // The panel around the button: points projecting within
                                      // this of the centre [px].
  double panel_radii = 6;             // The position's plane: a robust fit to the map points
                                      // within this many tracked radii, moved onto the face by
                                      // the face points' median offset; 0 = the plane above.
  int min_points = 3;                 // Fewer points near the button: no position.
  int good_points = 6;                // Points for a sound fit (fewer: plane_sound = false); this
                                      // many on the face: the face's own plane is fitted.
  int min_face_points = 3;            // Else this many face points move the panel plane onto the
                                      // face (median offset; buttons stand out of their plate).
  double max_face_offset_m = 0.03;    // Larger median face offsets are not applied [m].
  double face_clip_sigmas = 2.5;      // The face offset: the median of the points within this
                                      // many robust sigmas of it, until they settle; 0 = the
                                      // median of all (a tail of bad points drags it).
  int ransac_iterations = 200;        // Plane RANSAC hypotheses.
  double ransac_threshold_m = 0.004;  // Plane inlier distance [m].
  double max_plane_rms_m = 0.004;     // Inlier RMS above this: plane not sound [m].
  double min_inlier_fraction = 0.5;   // Fewer inliers than this fraction: plane not sound.
  double min_incidence_cos = 0.2;     // |cos| between ray and normal below this: near-parallel.
  uint64_t seed = 1;                  // RANSAC random seed (deterministic runs).

  bool IsValid(std::string* error) const;
  static OptionTable<ButtonLocatorOptions> Describe();
};

// What the locator needs from the SLAM: camera intrinsics, the camera pose, the metric map
// points (world frame) and the relative uncertainty of the map's scale.
struct LocatorInput {
  PinholeCamera camera;
  Eigen::Isometry3d camera_from_world = Eigen::Isometry3d::Identity();
  const std::vector<Eigen::Vector3d>* points_in_world = nullptr;
  Eigen::Vector2d button_px = Eigen::Vector2d::Zero();  // Tracked button centre.
  double button_radius_px = 0;  // Tracked apparent radius (ButtonTrack::radius_px); 0 = unknown.
  double scale_sigma_rel = 0;   // 1-sigma relative error of the metric scale (0 = exact).
};

// The located button, in the camera frame.
struct ButtonLocation {
  Eigen::Vector3d button_in_camera = Eigen::Vector3d::Zero();
  Eigen::Vector3d normal_in_camera = Eigen::Vector3d::UnitZ();    // Out of the panel (towards
                                                                  // the camera).
  Eigen::Vector3d approach_in_camera = Eigen::Vector3d::UnitZ();  // = -normal: push direction.
  int points_near = 0;                                            // Map points near the button.
  bool on_button = false;    // The position is on the button's face (own plane or offset);
                             // else on the panel plane around it.
  int inliers = 0;           // Plane inliers.
  double plane_rms_m = 0;    // RMS distance of the inliers to the plane.
  double incidence_cos = 0;  // |cos| between the viewing ray and the normal.
  double uncertainty_m = 0;  // 1-sigma position uncertainty (fit and scale).
  bool plane_sound = false;  // Enough points, enough inliers, small residual.
};

// Stateless; constructible many times.
//
//   ButtonLocator locator(options);
//   StatusOr<ButtonLocation> at = locator.Locate(input);
//   Eigen::Vector3d button_in_base = base_from_camera * at->button_in_camera;
class ButtonLocator {
 public:
  explicit ButtonLocator(ButtonLocatorOptions options = {}) : options_(options) {}

  // Fits the button face when good_points map points lie on it, else the panel within
  // radius_px moved onto the face by min_face_points face points. NotFound with the count
  // when fewer than min_points map points lie near the button;
  // FailedPrecondition for a degenerate plane or a ray nearly parallel to it (or hitting it
  // behind the camera); InvalidArgument for invalid input.
  StatusOr<ButtonLocation> Locate(const LocatorInput& input) const;

 private:
  ButtonLocatorOptions options_;
};

// The camera in the arm base frame for an eye-in-hand camera:
// base_from_camera = base_from_end_effector * end_effector_from_camera.
Eigen::Isometry3d BaseFromCamera(const Eigen::Isometry3d& base_from_end_effector,
                                 const Eigen::Isometry3d& end_effector_from_camera);

}  // namespace sightline
