#include "core/mapping/feature_motion.h"

#include <cmath>
#include <opencv2/calib3d.hpp>

namespace sightline {

FeatureMotion::FeatureMotion(int max_features, int min_inliers)
    : orb_(cv::ORB::create(max_features)), min_inliers_(min_inliers) {}

FeatureFrame FeatureMotion::Detect(const cv::Mat& gray, const cv::Mat& depth_m,
                                   const cv::Mat& mask) {
  FeatureFrame frame;
  frame.depth_m = depth_m;
  orb_->detectAndCompute(gray, mask, frame.keypoints, frame.descriptors);  // Empty: everywhere.
  return frame;
}

std::optional<Eigen::Isometry3d> FeatureMotion::Estimate(const FeatureFrame& reference,
                                                         const FeatureFrame& current,
                                                         const PinholeCamera& camera,
                                                         int* inliers) const {
  *inliers = 0;
  if (reference.descriptors.empty() || current.descriptors.empty()) return std::nullopt;
  cv::BFMatcher matcher(cv::NORM_HAMMING, /*crossCheck=*/true);
  std::vector<cv::DMatch> matches;
  matcher.match(reference.descriptors, current.descriptors, matches);
  std::vector<cv::Point3f> points;
  std::vector<cv::Point2f> pixels;
  for (const cv::DMatch& m : matches) {
    if (m.distance > 64) continue;  // Of 256 bits: clearly different corners.
    const cv::Point2f& p = reference.keypoints[m.queryIdx].pt;
    const int u = static_cast<int>(std::lround(p.x)), v = static_cast<int>(std::lround(p.y));
    if (u < 0 || v < 0 || u >= reference.depth_m.cols || v >= reference.depth_m.rows) continue;
    const float z = reference.depth_m.at<float>(v, u);
    if (!(z > 0)) continue;
    const Eigen::Vector3d x = camera.Unproject(p.x, p.y, z);
    points.emplace_back(static_cast<float>(x.x()), static_cast<float>(x.y()),
                        static_cast<float>(x.z()));
    pixels.push_back(current.keypoints[m.trainIdx].pt);
  }
  if (static_cast<int>(points.size()) < min_inliers_) return std::nullopt;
  const cv::Matx33d k(camera.fx, 0, camera.cx, 0, camera.fy, camera.cy, 0, 0, 1);
  cv::Mat rvec, tvec;
  std::vector<int> inlier_index;
  const bool solved = cv::solvePnPRansac(points, pixels, k, cv::noArray(), rvec, tvec, false, 200,
                                         2.0f, 0.99, inlier_index, cv::SOLVEPNP_EPNP);
  *inliers = static_cast<int>(inlier_index.size());
  if (!solved || *inliers < min_inliers_) return std::nullopt;
  cv::Mat r;
  cv::Rodrigues(rvec, r);
  Eigen::Isometry3d current_from_reference = Eigen::Isometry3d::Identity();
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) current_from_reference.linear()(i, j) = r.at<double>(i, j);
    current_from_reference.translation()(i) = tvec.at<double>(i);
  }
  if (!current_from_reference.matrix().allFinite()) return std::nullopt;
  return current_from_reference;
}

}  // namespace sightline
