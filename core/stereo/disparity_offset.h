// Online estimate of a constant disparity offset of the stereo rig: measured disparities that are
// all too small (or too large) by the same fraction of a pixel, as a principal-point difference
// left in the rectification or a matcher bias common to every feature gives. Such an offset moves
// far points much further than near ones (depth error ~ Z^2 offset / (f b)), so the translation
// comes out too long or too short, and more so when only far points survive (fast motion,
// subsampled input). The offset is observable from motion: under a forward or turning motion the
// image expansion of a point must agree with the change of its disparity. A pair of frames (an
// anchor and the first later frame that has moved a tenth of the tracks' median depth from it)
// gives a measurement of the offset with the motion and the points marginalised (only when that
// takes at most max_span_frames frames: tracks followed over many frames drift, and their drift
// reads as an offset: -0.2 px on a simulated drive at 25 Hz and 0.5 m/s, where pairs took 15
// frames, against +-0.05 px within 8 frames); the estimate is
// the information-weighted mean of all such measurements, with a prior at zero, and is applied to
// the right columns of all later correspondences. Without motion nothing is measured and the
// estimate stays where it is.
//
// Measured on kitti_clip1 (51 frames, 59.9 m): the estimate settles at 0.23-0.24 px with every
// frame and at about 0.2 px with every fifth frame; with the ground-truth motion held fixed, the
// same pairs give 0.11-0.15 px (about 0.28 px at k = 1 if a disparity scale error, which motion
// alone cannot see, is fitted as well). On the simulated corridor (no offset by construction) it
// stays within +-0.03 px, below min_applied_px, so nothing is applied there.
#pragma once

#include <Eigen/Geometry>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "core/options/option_table.h"
#include "core/stereo/motion_refiner.h"
#include "core/stereo/stereo_correspondence.h"
#include "core/stereo/stereo_geometry.h"

namespace sightline {

// Keys "stereo.disparity_offset.*".
struct DisparityOffsetOptions {
  bool enabled = true;           // Estimate and apply the offset.
  double prior_sigma_px = 0.1;   // Prior standard deviation of the offset around zero [px].
  double max_offset_px = 1.0;    // The estimate is clamped to +-this [px].
  double huber_px = 0.5;         // Huber threshold of the measurement's robust weights [px].
  double min_noise_px = 0.1;     // Floor of the residual RMS that scales a measurement [px].
  double min_parallax = 0.1;     // A pair is measured once the translation from the anchor reaches
                                 // this fraction of the common tracks' median depth ...
  int max_span_frames = 8;       // ... within this many frames; else the anchor starts again.
  double min_applied_px = 0.05;  // Smaller estimates are not applied [px].

  bool IsValid(std::string* error) const;
  static OptionTable<DisparityOffsetOptions> Describe();
};

// The offset seen in one frame pair, relative to the offset already applied to it.
struct DisparityOffsetMeasurement {
  bool valid = false;
  double gradient = 0;     // Of the cost in the offset, motion and points marginalised [1/px].
  double information = 0;  // Its curvature [1/px^2], already divided by the residual variance.
  int points = 0;          // Correspondences used.
};

// A feature's stereo observation in one frame, as matched (no offset applied).
struct OffsetTrack {
  int64_t id = -1;
  StereoObservation observation;
};

// Measures the disparity offset in one frame pair: the correspondences' observations (with the
// current offset applied), the refined motion and its inliers. One Gauss-Newton step of the
// two-frame bundle adjustment with the offset as a seventh unknown, with the points and then the
// motion marginalised. Meaningful only for pairs with enough parallax (see Observe).
DisparityOffsetMeasurement MeasureDisparityOffset(
    const RectifiedStereoCamera& camera, const std::vector<StereoCorrespondence>& correspondences,
    const std::vector<int>& inliers, const Eigen::Isometry3d& current_from_previous,
    const DisparityOffsetOptions& options);

class DisparityOffsetEstimator {
 public:
  explicit DisparityOffsetEstimator(DisparityOffsetOptions options = {}) : options_(options) {
    Reset();
  }

  // Back to the prior: no offset, no anchor.
  void Reset();
  // Disparity to add to every measured disparity [px]: the estimate, or 0 when disabled or when
  // the estimate is smaller than min_applied_px.
  double offset_px() const {
    return options_.enabled && std::abs(offset_px_) >= options_.min_applied_px ? offset_px_ : 0.0;
  }
  // The running estimate, applied or not [px].
  double estimate_px() const { return offset_px_; }
  // Corrects both observations of a correspondence (moves the right columns); call before
  // Triangulate.
  void Apply(StereoCorrespondence* c) const;
  // Folds in the measurement of an accepted frame pair.
  void Update(const DisparityOffsetMeasurement& m);
  // Called once per frame with its tracks (as matched) and pose. The first frame, and any frame
  // after a rejected motion or when too few of the anchor's tracks are left, becomes the anchor.
  // Once the camera has moved min_parallax of the common tracks' median depth from the anchor,
  // the pair (anchor, this frame) is measured: inliers at the motion between the two poses,
  // refined with `refiner`, MeasureDisparityOffset, Update; this frame becomes the anchor. So
  // slow motion is measured over several frames instead of from pairs with little parallax.
  void Observe(const RectifiedStereoCamera& camera, const MotionRefiner& refiner,
               double inlier_threshold_px, std::vector<OffsetTrack> tracks,
               const Eigen::Isometry3d& world_from_camera, bool motion_accepted);
  const DisparityOffsetOptions& options() const { return options_; }

 private:
  DisparityOffsetOptions options_;
  double offset_px_ = 0;
  double information_ = 0;           // Prior plus all measurements [1/px^2].
  std::vector<OffsetTrack> anchor_;  // Sorted by id; empty = no anchor.
  Eigen::Isometry3d world_from_anchor_ = Eigen::Isometry3d::Identity();
  int frames_since_anchor_ = 0;
};

}  // namespace sightline
