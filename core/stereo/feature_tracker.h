// Temporal feature tracking on the left image (the seed's Fig. 5): Shi-Tomasi corners, pyramidal
// Lucas-Kanade tracking from the previous left image with a forward-backward check, and new
// corners in the buckets of a grid that lack features, so that features cover the image.
#pragma once

#include <opencv2/core.hpp>
#include <string>
#include <vector>

#include "core/options/option_table.h"
#include "core/stereo/image_pyramid.h"

namespace sightline {

// Tracking and detection options. Keys "stereo.tracking.*".
struct FeatureTrackerOptions {
  int max_features = 1000;       // Features kept per frame (tracked + new).
  int bucket_size_px = 48;       // Side of the square buckets of the detection grid [px].
  double refill_fraction = 1.0;  // A bucket is refilled when it holds fewer than this fraction
                                 // of its share of max_features (1 = whenever not full).
  double min_eigenvalue = 5e-4;  // Shi-Tomasi: smallest accepted minimum eigenvalue of the
                                 // gradient covariance (cv::cornerMinEigenVal units).
  double min_distance_px = 7;    // Shi-Tomasi: minimum distance between corners [px].
  int block_size = 3;            // Shi-Tomasi: window of the gradient covariance [px].
  int window_px = 9;             // KLT window side [px] (odd).
  int pyramid_levels = 3;        // KLT pyramid levels above full resolution.
  // When fewer than this fraction of the points track, relative to the fraction that tracked
  // in the previous frame (the motion prediction was poor: a turn begins, the first frames),
  // the lost ones are tracked again with retrack_pyramid_levels, which reaches about
  // 2^levels times further; 0 = never.
  double retrack_fraction = 0.6;
  int retrack_pyramid_levels = 5;  // Pyramid levels of that second attempt.
  // When still fewer than turn_search_fraction times the usual share (StereoOdometry keeps a
  // slow average of the tracked fraction) of the points track (a sharp
  // turn, or a turn at a low frame rate, moves the image by more than the pyramid reaches), the
  // camera's rotation is searched on copies of the two images turn_search_width_px wide
  // (core/stereo/turn_search.h, yaw within turn_search_max_deg) and the points are tracked
  // again from where it puts them; the attempt that tracks more points is kept. 0 = never.
  double turn_search_fraction = 0.5;
  int turn_search_width_px = 160;
  double turn_search_max_deg = 60;
  int max_iterations = 20;   // KLT iterations per level.
  double epsilon_px = 0.01;  // KLT stops when the update is smaller [px].
  double max_forward_backward_px =
      0.5;                   // Tracked back to the start within this [px]; 0 = no check.
  int border_px = 8;         // Features closer to the image border are dropped [px].
  int detection_level = 0;   // Pyramid level corners are detected on (0 = full
                             // resolution; fine corners track best with small windows).
  int refine_window_px = 2;  // Half-size of the full-resolution sub-pixel corner refinement
                             // of corners detected on a reduced level [px]; 0 = none.

  bool IsValid(std::string* error) const;
  static OptionTable<FeatureTrackerOptions> Describe();
};

// Stateless per call: the caller (StereoOdometry) owns the features and pyramids.
//
//   FeatureTracker tracker(options);
//   tracker.Track(previous_left, left, points, &tracked, &ok);
//   std::vector<cv::Point2f> fresh = tracker.Detect(left.image, surviving_points);
class FeatureTracker {
 public:
  explicit FeatureTracker(FeatureTrackerOptions options = {}) : options_(options) {}
  const FeatureTrackerOptions& options() const { return options_; }

  // Tracks `points` from `previous` into `current`, starting from `predicted` (same size; empty
  // = no prediction, start where the points were); ok[i] is 0 where a point was lost (KLT
  // failure, forward-backward disagreement, or too close to the border). Returns whether the
  // lost points were tracked a second time with more pyramid levels: when fewer than
  // retrack_fraction * usual_fraction of the points tracked at first (usual_fraction: the
  // fraction that usually tracks, e.g. in the previous frame).
  bool Track(const ImagePyramid& previous, const ImagePyramid& current,
             const std::vector<cv::Point2f>& points, const std::vector<cv::Point2f>& predicted,
             std::vector<cv::Point2f>* tracked, std::vector<unsigned char>* ok,
             double usual_fraction = 1.0) const;

  // New Shi-Tomasi corners (local maxima of the minimum eigenvalue), strongest first within each
  // bucket that holds fewer than its share of max_features, at least min_distance_px away from
  // `existing` and each other; at most max_features - existing.size(). Only the buckets that
  // need corners are searched, which keeps detection cheap while most features are tracked.
  std::vector<cv::Point2f> Detect(const ImagePyramid& image,
                                  const std::vector<cv::Point2f>& existing) const;

 private:
  // One KLT pass over points[index] with `levels` pyramid levels: forward from `start`, the
  // backward check, the border; sets (*tracked)[i] and (*ok)[i] for those points.
  void TrackPass(const ImagePyramid& previous, const ImagePyramid& current,
                 const std::vector<cv::Point2f>& points, const std::vector<cv::Point2f>& start,
                 const std::vector<size_t>& index, int levels, std::vector<cv::Point2f>* tracked,
                 std::vector<unsigned char>* ok) const;

  FeatureTrackerOptions options_;
};

}  // namespace sightline
