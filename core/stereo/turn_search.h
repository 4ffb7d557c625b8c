// The camera's rotation between two frames found from the images alone: a prior for tracking
// when the image moved further than the tracker's pyramid reaches (a sharp turn, or a turn seen
// at a low frame rate). On copies of the two images reduced to a few hundred pixels across,
// the previous image is warped by the homography of each candidate rotation (K R K^-1: the
// scene taken as far away) and compared with the current one by normalised cross-correlation
// over the pixels both see; yaw is searched over its whole range, then yaw and pitch near the
// best. Yaw turns about the axis the camera has been turning about (a vehicle's vertical, which
// a camera tilted down sees off its own y axis: searched about y, a turn is found short and
// cannot be matched by pitch alone).
#pragma once

#include <Eigen/Core>
#include <opencv2/core.hpp>
#include <optional>

#include "core/stereo/stereo_geometry.h"

namespace sightline {

struct TurnSearchOptions {
  int width_px = 160;                // Columns of the reduced copies.
  double max_yaw_deg = 60;           // Yaw searched in [-max, max] ...
  double coarse_step_deg = 1.5;      // ... in these steps, then refined to a quarter of a step.
  double max_pitch_deg = 3;          // Pitch searched around the best yaw, in half steps.
  double max_axis_tilt_deg = 20;     // The yaw axis tilted about x by up to this, in steps ...
  double min_yaw_for_tilt_deg = 15;  // ... when the turn is at least this large.
  double min_overlap = 0.2;      // A rotation must leave this fraction of the image seen by both.
  double min_correlation = 0.3;  // Weaker best matches give no answer.
};

struct TurnEstimate {
  Eigen::Matrix3d current_from_previous = Eigen::Matrix3d::Identity();
  double yaw_deg = 0, pitch_deg = 0;
  double axis_tilt_deg = 0;  // The yaw axis' tilt about the camera's x axis.
  double correlation = 0;    // Normalised cross-correlation of the best rotation.
  double overlap = 0;        // Fraction of the reduced image both views see.
};

// nullopt for empty images, images of different sizes, or no rotation that matches well
// enough. Yaw turns about `turn_axis` (camera frame; its y axis, down, by default), pitch about
// the camera's x axis.
std::optional<TurnEstimate> FindTurn(const cv::Mat& previous, const cv::Mat& current,
                                     const RectifiedStereoCamera& camera,
                                     const TurnSearchOptions& options = {},
                                     const Eigen::Vector3d& turn_axis = Eigen::Vector3d::UnitY());

// The axis a camera has been turning about, from its past frame-to-frame rotations: each adds
// its axis times its angle (turned to agree with the sum), so that the turns dominate and the
// small rotations of driving straight average out. The camera's y axis until enough was seen.
class TurnAxis {
 public:
  void Add(const Eigen::Matrix3d& current_from_previous);
  Eigen::Vector3d axis() const;
  void Reset() { sum_.setZero(); }

 private:
  Eigen::Vector3d sum_ = Eigen::Vector3d::Zero();
};

}  // namespace sightline
