// Two-view initialisation (PTAM's stereo initialisation, the seed's sideways move): ORB matches
// between a first frame and the current one, an essential matrix and a homography by RANSAC,
// the model chosen by its share of inliers (as ORB-SLAM does), the motion recovered from it
// (cheirality over the decompositions), triangulation with parallax and reprojection checks,
// and the baseline set to `baseline` map units.
#pragma once

#include <Eigen/Geometry>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "core/common/camera.h"
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
};

// Holds the first frame and tries each later one against it.
//
//   TwoViewInitializer init(options.init, camera);
//   init.SetFirst(features);
//   std::string why;
//   if (auto r = init.TryInitialize(next_features, &why)) { ... }
class TwoViewInitializer {
 public:
  TwoViewInitializer(const MonoInitOptions& options, const PinholeCamera& camera,
                     double scale_factor);

  void SetFirst(FrameFeatures first);
  bool has_first() const { return has_first_; }
  const FrameFeatures& first() const { return first_; }
  int frames_tried() const { return frames_tried_; }

  // An initialisation from the first frame and `current`, or nullopt with the reason in *why
  // (too few matches, too little parallax, ambiguous motion, too few points).
  std::optional<TwoViewResult> TryInitialize(const FrameFeatures& current, std::string* why);

 private:
  MonoInitOptions options_;
  PinholeCamera camera_;
  double scale_factor_;
  FrameFeatures first_;
  bool has_first_ = false;
  int frames_tried_ = 0;
};

// One-to-one ORB matches a -> b with a ratio test and a distance limit (brute force).
std::vector<std::pair<int, int>> MatchDescriptors(const cv::Mat& a, const cv::Mat& b,
                                                  int max_distance, double ratio);

}  // namespace sightline
