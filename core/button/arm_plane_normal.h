// The panel's normal from the arm's own motion: corners around the button are tracked (KLT,
// checked forward and backward) from an anchor frame, and the plane is the one whose
// homography between the anchor and the current view, given their relative pose from the arm
// (metric, independent of the SLAM's map and its drift), best explains the tracks. The same
// idea as the arm triangulation of the button's centre (arm_triangulation.h), for the surface
// around it: with the views' poses known, only the plane's three parameters are estimated.
#pragma once

#include <Eigen/Geometry>
#include <opencv2/core.hpp>
#include <vector>

#include "core/button/panel_normal.h"
#include "core/common/camera.h"
#include "core/common/status.h"

namespace sightline {

// One frame's view for the plane: a grey or colour image, the camera's pose in the arm's base
// (arm pose times the mount), where the button is and how far around it the panel is sampled.
struct ArmPlaneView {
  cv::Mat image;
  PinholeCamera camera;
  Eigen::Isometry3d base_from_camera = Eigen::Isometry3d::Identity();
  Eigen::Vector2d button_px = Eigen::Vector2d::Zero();
  double region_radius_px = 0;  // Corners are taken within this of the button.
  // The located button in this camera, metric; NaN when not known (the plane is then not
  // checked against it).
  Eigen::Vector3d button_in_camera = Eigen::Vector3d::Constant(std::nan(""));
};

// Tracks the panel from an anchor frame and solves the plane each frame once the arm has moved
// far enough. One per tapped button; Reset() on a new tap.
class ArmPlaneNormal {
 public:
  explicit ArmPlaneNormal(PanelNormalOptions options = {}) : options_(options) {}

  // Adds a frame: the panel normal in this frame's camera (toward the camera) with its
  // uncertainty; NotFound while anchoring, while the arm's motion since the anchor gives too
  // little parallax, or when no plane near the button explains enough tracks (the message
  // says which); InvalidArgument for invalid options or an empty image.
  StatusOr<PanelNormal> Add(const ArmPlaneView& view);
  void Reset();
  int tracks() const { return static_cast<int>(current_.size()); }

 private:
  // Starts again on this frame: corners around the button. False when too few were found.
  bool Anchor(const cv::Mat& grey, const ArmPlaneView& view);
  // Undistorted, normalised image coordinates (z = 1).
  static std::vector<Eigen::Vector3d> Normalised(const std::vector<cv::Point2f>& px,
                                                 const PinholeCamera& camera);

  PanelNormalOptions options_;
  cv::Mat previous_;                    // Grey image of the last frame.
  Eigen::Isometry3d base_from_anchor_;  // The anchor camera's pose.
  std::vector<cv::Point2f> anchor_;     // Corners in the anchor frame...
  std::vector<cv::Point2f> current_;    // ... and where they are now.
  size_t anchored_ = 0;                 // Corners at the anchor.
};

}  // namespace sightline
