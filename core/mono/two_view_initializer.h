// Two-view initialisation (PTAM's stereo initialisation, the seed's sideways move): ORB matches
// between a first frame and the current one, an essential matrix and a homography by RANSAC,
// the model chosen by its share of inliers (as ORB-SLAM does), the motion recovered from it
// (cheirality over the decompositions), triangulation with parallax and reprojection checks,
// and the baseline set to `baseline` map units. For sparse, large-motion input it keeps a ring of
// candidate first frames (tried oldest first) and, when the descriptor matches alone are too
// few, matches again along the epipolar lines of an essential matrix fitted to them.
#pragma once

#include <Eigen/Geometry>
#include <cstdint>
#include <deque>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "core/common/camera.h"
#include "core/common/frame.h"
#include "core/mono/mono_options.h"
#include "core/mono/slam_map.h"

namespace sightline {

// An accepted initialisation.
struct TwoViewResult {
  Eigen::Isometry3d second_from_first = Eigen::Isometry3d::Identity();  // |t| = baseline.
  std::vector<std::pair<int, int>> matches;  // (first keypoint, second keypoint) per point.
  std::vector<Eigen::Vector3d> points;       // x_in_first, one per match [map units].
  std::string model;                         // "homography" or "essential".
  int homography_inliers = 0, essential_inliers = 0;
  double median_parallax_deg = 0;  // Of the accepted points.
  double baseline_ratio = 0;       // Baseline / median depth of the accepted points.
  bool guided = false;             // The matches came from guided matching.
};

// A candidate first frame: its features, stamp and the caller's frame number.
struct InitReference {
  FrameFeatures features;
  FrameStamp stamp;
  int64_t number = 0;
};

// Holds candidate first frames (a ring of `reference_frames`) and tries each later frame
// against them.
//
//   TwoViewInitializer init(options.init, camera);
//   init.SetFirst(features);
//   std::string why;
//   if (auto r = init.TryInitialize(next_features, &why)) { ... init.first() ... }
class TwoViewInitializer {
 public:
  TwoViewInitializer(const MonoInitOptions& options, const PinholeCamera& camera,
                     double scale_factor);

  // Forgets every candidate and takes `first` as the only one.
  void SetFirst(FrameFeatures first, FrameStamp stamp = {}, int64_t number = 0);
  // Adds a candidate; the oldest leaves a full ring.
  void AddReference(FrameFeatures features, FrameStamp stamp = {}, int64_t number = 0);
  bool has_first() const { return !references_.empty(); }
  // The candidate of the last successful TryInitialize (else the oldest).
  const InitReference& reference() const { return references_[used_]; }
  const FrameFeatures& first() const { return reference().features; }
  // Frames tried since the newest candidate was added.
  int frames_tried() const { return frames_tried_; }
  // Descriptor matches of the last frame tried with the newest candidate.
  int newest_matches() const { return newest_matches_; }

  // An initialisation from a candidate (oldest first) and `current`, or nullopt with the
  // reason in *why (too few matches, too little parallax, ambiguous motion, too few points;
  // the newest candidate's reason when none succeeds).
  std::optional<TwoViewResult> TryInitialize(const FrameFeatures& current, std::string* why);

 private:
  std::optional<TwoViewResult> TryPair(const FrameFeatures& first, const FrameFeatures& current,
                                       std::string* why, int* matched);
  // The matches of `first` and `current`: descriptor matches, or guided ones when too few.
  std::vector<std::pair<int, int>> Matches(const FrameFeatures& first, const FrameFeatures& current,
                                           bool* guided) const;

  MonoInitOptions options_;
  PinholeCamera camera_;
  double scale_factor_;
  std::deque<InitReference> references_;
  size_t used_ = 0;
  int frames_tried_ = 0;
  int newest_matches_ = 0;
};

// Matches a -> b near the epipolar lines of the essential matrix `E` (b^T E a = 0 in
// normalised coordinates): per keypoint of a, the best descriptor within `max_px` of its line
// in b and `max_distance`, kept when better than `ratio` x the second; one-to-one.
std::vector<std::pair<int, int>> MatchAlongEpipolarLines(const FrameFeatures& a,
                                                         const FrameFeatures& b,
                                                         const Eigen::Matrix3d& E,
                                                         const PinholeCamera& camera, double max_px,
                                                         int max_distance, double ratio);

// One-to-one ORB matches a -> b with a ratio test and a distance limit (brute force).
std::vector<std::pair<int, int>> MatchDescriptors(const cv::Mat& a, const cv::Mat& b,
                                                  int max_distance, double ratio);

}  // namespace sightline
