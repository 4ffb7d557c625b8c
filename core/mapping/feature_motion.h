// A coarse camera motion from ORB features and depth, used by the RGB-D odometry
// (rgbd_odometry.h) as the starting guess of its dense alignment when the motion between two
// frames is too large for the image pyramid (a robot turning at 5 Hz: 20 deg per frame).
#pragma once

#include <Eigen/Geometry>
#include <opencv2/core.hpp>
#include <opencv2/features2d.hpp>
#include <optional>
#include <vector>

#include "core/common/camera.h"

namespace sightline {

// One frame's ORB features and the depth they are lifted with.
struct FeatureFrame {
  std::vector<cv::KeyPoint> keypoints;
  cv::Mat descriptors;
  cv::Mat depth_m;  // CV_32FC1, 0 = none.
};

// Finds features and estimates motions between two FeatureFrames.
//
//   FeatureMotion features(500, 20);
//   FeatureFrame a = features.Detect(gray_a, depth_a), b = features.Detect(gray_b, depth_b);
//   std::optional<Eigen::Isometry3d> b_from_a = features.Estimate(a, b, camera, &inliers);
class FeatureMotion {
 public:
  FeatureMotion(int max_features, int min_inliers);

  // Features where `mask` (CV_8UC1, optional) is non-zero.
  FeatureFrame Detect(const cv::Mat& gray, const cv::Mat& depth_m, const cv::Mat& mask = {});
  // current_from_reference by PnP RANSAC on the reference's features lifted with its depth;
  // nullopt with fewer than min_inliers inliers. `camera` matches the images' size.
  std::optional<Eigen::Isometry3d> Estimate(const FeatureFrame& reference,
                                            const FeatureFrame& current,
                                            const PinholeCamera& camera, int* inliers) const;

 private:
  cv::Ptr<cv::ORB> orb_;
  int min_inliers_;
};

}  // namespace sightline
