// Button tracking in later frames (the seed's tracking phase): SIFT on a search window
// predicted from the camera pose (or the last position), FLANN matching against the model of
// the tapped button with Lowe's ratio test and the seed's distance gate, and the new centre
// from the matches; lost when too few matches survive. After a loss (a finger over the button,
// the button out of view) every frame is searched whole against the model kept from the tap
// (plus refreshed features), and the button is re-acquired only on a confident match at a
// plausible size, inside the view.
#pragma once

#include <memory>
#include <opencv2/core.hpp>
#include <opencv2/flann.hpp>
#include <optional>
#include <string>

#include "core/button/button_model.h"
#include "core/common/status.h"
#include "core/options/option_table.h"

namespace sightline {

// Tracker options. Keys "button.track.*".
struct ButtonTrackerOptions {
  double ratio = 0.8;                   // Lowe's ratio: best / second-best descriptor distance.
  double gate_px = 40;                  // Distance gate: matches farther from the predicted
                                        // centre are dropped [px] (at least; see gate_radius).
  double gate_radius = 2.5;             // ... or this many predicted button radii, if larger.
  bool use_window = true;               // Search only a window around the prediction.
  double window_px = 80;                // Half size of the search window [px] (at least) ...
  double window_radius = 4.0;           // ... or this many predicted button radii, if larger.
  int min_matches = 4;                  // Fewer consistent matches: the button is lost.
  std::string centre = "similarity";    // similarity (model centre through a RANSAC similarity
                                        // of the matches) or centroid (the published rule).
  double ransac_px = 3.0;               // Inlier distance of the similarity RANSAC [px].
  double sift_contrast = 0.01;          // SIFT contrast threshold.
  int flann_trees = 4;                  // FLANN randomised kd-trees.
  int flann_checks = 64;                // FLANN leaf checks per query.
  bool refresh = true;                  // Add features of confidently tracked frames to the
                                        // model when the button's size has changed (keeps
                                        // tracking through a long approach).
  double refresh_scale_step = 1.15;     // Size change since the last refresh that triggers one.
  double refresh_radius = 5.0;          // Features within this many button radii are added.
  double refresh_min_confidence = 0.5;  // Only frames tracked at least this confidently.
  int max_model_keypoints = 2000;       // The model never grows beyond this.
  bool reacquire = true;                // After a loss, search whole frames and re-acquire
                                        // only on a confident match (false: the first frame
                                        // with min_matches consistent matches, as before).
  int reacquire_min_inliers = 8;        // Consistent matches needed to re-acquire.
  int reacquire_min_face = 3;           // ... of which at least this many on the button
  double reacquire_face_radius = 1.5;   // ... within this many radii of its centre.
  double reacquire_ambiguity = 0.5;     // Refused when the matches left over support a
                                        // second similarity with this fraction of the
                                        // inliers (a repeated panel: another button).
  double reacquire_max_scale = 1.6;     // Scale change since the last tracked frame allowed
                                        // at re-acquisition (either way).
  double view_margin_px = 4;            // A centre farther outside the image: not in view.
  int anchor_min_matches = 6;           // Consistent matches with the tap's own keypoints
                                        // needed for ButtonTrack::anchor_scale.

  bool IsValid(std::string* error) const;
  static OptionTable<ButtonTrackerOptions> Describe();
};

// Where the button should be in the next frame, e.g. the button's 3D point projected with the
// SLAM pose; scale = expected size relative to the model (still frame).
struct TrackPrediction {
  bool valid = false;
  cv::Point2d center;
  double scale = 1.0;
};

// Where the track stands after a frame.
enum class TrackState {
  kTracking,    // Found, as in the frame before.
  kReacquired,  // Found again after one or more lost frames.
  kLost,        // Not found in this frame.
};
const char* TrackStateName(TrackState state);

// The tracker's answer for one frame.
struct ButtonTrack {
  bool found = false;  // False: lost (too few matches); `reason` says why.
  TrackState state = TrackState::kLost;
  int lost_frames = 0;     // Consecutive lost frames up to this one (0 when found).
  int reacquisitions = 0;  // Times the button was re-acquired since the tap.
  std::string reason;
  cv::Point2d center;    // Button centre in this frame [px].
  double scale = 1.0;    // Size relative to the model.
  double radius_px = 0;  // Apparent button radius [px].
  // The size relative to the model from the tap's own keypoints alone (not those the refresh
  // added: each refresh carries its frame's scale error on, so `scale` drifts over a long
  // approach); 0 with fewer than anchor_min_matches of them among the inliers.
  double anchor_scale = 0;
  double confidence = 0;  // 0..1: inlier count and inlier fraction.
  int keypoints = 0;      // SIFT keypoints found in the window.
  int matches = 0;        // After ratio test and distance gate.
  int inliers = 0;        // Consistent with the similarity (= matches for centroid).
  cv::Rect window;        // The searched region.
};

// Stateful (remembers the last centre and scale for the next window). One per button.
//
//   ButtonTracker tracker(model, options);
//   StatusOr<ButtonTrack> t = tracker.Track(frame, prediction);  // prediction may be {}
//   if (t.ok() && t->found) Draw(t->center);
class ButtonTracker {
 public:
  ButtonTracker(std::shared_ptr<const ButtonModel> model, ButtonTrackerOptions options = {});

  // Finds the button in `image`. Without a valid prediction the window follows the last
  // found position (whole image after a loss). InvalidArgument for an empty image or invalid
  // options; a lost button is an ok result with found = false.
  StatusOr<ButtonTrack> Track(const cv::Mat& image, const TrackPrediction& prediction = {});

  const ButtonModel& model() const { return *model_; }
  // Keypoints in the model now (the detector's plus refreshed ones).
  int model_keypoints() const { return int(points_.size()); }
  // Forgets the last position: the next frame is searched whole.
  void Reset() { last_.reset(); }
  // Times the button was found again after being lost.
  int reacquisitions() const { return reacquisitions_; }

 private:
  // One frame without the lost/re-acquired bookkeeping; `lost`: the frames before were lost.
  StatusOr<ButtonTrack> TrackOnce(const cv::Mat& image, const TrackPrediction& prediction,
                                  bool lost);
  cv::Rect Window(cv::Size size, const TrackPrediction& p) const;
  // Adds keypoints near the tracked centre, mapped into the model frame by the inverse of the
  // similarity model_to_image (2x3).
  void Refresh(const std::vector<cv::KeyPoint>& keypoints, const cv::Mat& descriptors,
               cv::Point2f offset, const ButtonTrack& track, const cv::Mat& model_to_image);
  void RebuildIndex();
  // The scale of a similarity between the tap's own keypoints alone and this frame's (matched
  // apart from the refreshed ones, whose near-duplicate descriptors fail the ratio test); 0 with
  // fewer than anchor_min_matches consistent matches near `track`'s centre.
  double AnchorScale(const std::vector<cv::KeyPoint>& keypoints, const cv::Mat& descriptors,
                     cv::Point2f offset, const ButtonTrack& track) const;

  std::shared_ptr<const ButtonModel> model_;
  ButtonTrackerOptions options_;
  std::vector<cv::Point2f> points_;  // Model keypoints in the still frame's pixels.
  cv::Mat descriptors_;              // One row per model keypoint.
  cv::Ptr<cv::flann::Index> index_;  // Over descriptors_.
  double refresh_scale_ = 1.0;       // Scale at the last refresh.
  std::optional<TrackPrediction> last_;
  int lost_frames_ = 0;      // Consecutive lost frames (0 while tracking).
  double last_scale_ = 1.0;  // Scale of the last found frame.
  int reacquisitions_ = 0;
};

}  // namespace sightline
