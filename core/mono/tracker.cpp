#include "core/mono/tracker.h"

#include <cmath>
#include <opencv2/calib3d.hpp>
#include <opencv2/core/eigen.hpp>
#include <unordered_map>

#include "core/mono/features.h"
#include "core/mono/pose_optimizer.h"
#include "core/mono/two_view_initializer.h"

namespace sightline {

const char* TrackingQualityName(TrackingQuality quality) {
  switch (quality) {
    case TrackingQuality::kInitialising:
      return "initialising";
    case TrackingQuality::kGood:
      return "good";
    case TrackingQuality::kPoor:
      return "poor";
    case TrackingQuality::kLost:
      return "lost";
  }
  return "?";
}

Tracker::Tracker(const MonoTrackingOptions& options, const PinholeCamera& camera,
                 double scale_factor)
    : options_(options), camera_(camera), scale_factor_(scale_factor) {}

TrackingQuality Tracker::QualityOf(const TrackOutcome& outcome) const {
  const int inliers = outcome.inliers;
  if (!outcome.predicted.empty() &&
      inliers < options_.min_found_fraction * static_cast<double>(outcome.predicted.size())) {
    return TrackingQuality::kLost;
  }
  if (inliers >= options_.good_inliers) return TrackingQuality::kGood;
  if (inliers >= options_.min_inliers) return TrackingQuality::kPoor;
  return TrackingQuality::kLost;
}

std::vector<PointMatch> Tracker::SearchByProjection(const FrameFeatures& features,
                                                    const std::vector<LocalPoint>& points,
                                                    const Eigen::Isometry3d& camera_from_map,
                                                    double radius,
                                                    std::vector<int64_t>* predicted) const {
  // Best match per keypoint, so that two points cannot claim one keypoint.
  std::vector<int> best_distance(features.size(), 1 << 30);
  std::vector<int> best_point(features.size(), -1);
  std::vector<int> window;
  for (size_t p = 0; p < points.size(); ++p) {
    const Eigen::Vector3d x = camera_from_map * points[p].position;
    if (x.z() <= 1e-6) continue;
    const Eigen::Vector2d uv = ProjectToPixel(camera_, x);
    if (uv.x() < 0 || uv.y() < 0 || uv.x() >= features.width || uv.y() >= features.height) continue;
    if (predicted) predicted->push_back(points[p].id);
    int best = 1 << 30, second = 1 << 30, best_k = -1;
    const uint8_t* dp = points[p].descriptor.ptr<uint8_t>();
    features.InWindow(uv.x(), uv.y(), radius, &window);
    for (int k : window) {
      const int d = DescriptorDistance(dp, features.descriptors.ptr<uint8_t>(k));
      if (d < best) {
        second = best;
        best = d;
        best_k = k;
      } else if (d < second) {
        second = d;
      }
    }
    if (best_k < 0 || best > options_.max_descriptor_distance) continue;
    if (second < (1 << 30) && best > options_.match_ratio * second) continue;
    if (best < best_distance[best_k]) {
      best_distance[best_k] = best;
      best_point[best_k] = static_cast<int>(p);
    }
  }
  std::vector<PointMatch> matches;
  for (size_t k = 0; k < features.size(); ++k) {
    if (best_point[k] >= 0) matches.push_back({static_cast<int>(k), best_point[k], false});
  }
  return matches;  // `point` holds the index into `points` until Track() maps it to ids.
}

double Tracker::Optimise(const FrameFeatures& features, const std::vector<LocalPoint>& points,
                         std::vector<PointMatch>* matches, Eigen::Isometry3d* camera_from_map,
                         int* inliers) const {
  std::vector<PoseObservation> observations;
  for (const PointMatch& m : *matches) {
    observations.push_back({points[m.point].position, features.pixels[m.keypoint],
                            std::pow(scale_factor_, features.keypoints[m.keypoint].octave)});
  }
  const PoseEstimate estimate =
      OptimizePose(camera_, *camera_from_map, observations, options_.huber_px, options_.outlier_px);
  *inliers = estimate.inlier_count;
  if (estimate.inlier_count >= 6) *camera_from_map = estimate.camera_from_map;
  for (size_t i = 0; i < matches->size(); ++i) (*matches)[i].inlier = estimate.inliers[i];
  return estimate.rms_px;
}

TrackOutcome Tracker::Track(const FrameFeatures& features, const std::vector<LocalPoint>& points,
                            const Eigen::Isometry3d& predicted_camera_from_map,
                            double coarse_radius_px) const {
  TrackOutcome out;
  out.camera_from_map = predicted_camera_from_map;
  if (features.size() == 0 || points.empty()) return out;
  // Coarse pass in the normal window, widened when it finds too little.
  const double coarse = coarse_radius_px > 0 ? coarse_radius_px : options_.search_radius_px;
  std::vector<PointMatch> matches =
      SearchByProjection(features, points, out.camera_from_map, coarse, nullptr);
  if (static_cast<int>(matches.size()) < 2 * options_.min_inliers &&
      coarse < options_.wide_radius_px) {
    matches =
        SearchByProjection(features, points, out.camera_from_map, options_.wide_radius_px, nullptr);
  }
  int inliers = 0;
  Optimise(features, points, &matches, &out.camera_from_map, &inliers);
  if (inliers < options_.min_inliers / 2) {
    out.inliers = inliers;
    return out;
  }
  // Fine pass from the refined pose.
  matches = SearchByProjection(features, points, out.camera_from_map, options_.fine_radius_px,
                               &out.predicted);
  out.rms_px = Optimise(features, points, &matches, &out.camera_from_map, &inliers);
  out.inliers = inliers;
  double depth = 0;
  for (PointMatch& m : matches) {
    if (m.inlier) depth += (out.camera_from_map * points[m.point].position).z();
    m.point = points[m.point].id;
  }
  out.mean_depth = inliers > 0 ? depth / inliers : 0;
  out.matches = std::move(matches);
  return out;
}

bool Tracker::Relocalise(const FrameFeatures& features, const KeyFrame& keyframe,
                         const std::vector<LocalPoint>& keyframe_points,
                         const std::vector<LocalPoint>& local_points, TrackOutcome* outcome) const {
  if (keyframe_points.size() < static_cast<size_t>(options_.reloc_min_matches)) return false;
  cv::Mat descriptors(static_cast<int>(keyframe_points.size()), 32, CV_8U);
  for (size_t i = 0; i < keyframe_points.size(); ++i) {
    keyframe_points[i].descriptor.copyTo(descriptors.row(static_cast<int>(i)));
  }
  const auto matches =
      MatchDescriptors(descriptors, features.descriptors, options_.max_descriptor_distance, 0.8);
  if (static_cast<int>(matches.size()) < options_.reloc_min_matches) return false;
  std::vector<cv::Point3f> object;
  std::vector<cv::Point2f> image;
  for (const auto& [p, k] : matches) {
    const Eigen::Vector3d& x = keyframe_points[p].position;
    object.emplace_back(x.x(), x.y(), x.z());
    image.emplace_back(features.pixels[k].x(), features.pixels[k].y());
  }
  const cv::Mat K =
      (cv::Mat_<double>(3, 3) << camera_.fx, 0, camera_.cx, 0, camera_.fy, camera_.cy, 0, 0, 1);
  cv::Mat rvec, tvec;
  std::vector<int> inliers;
  cv::theRNG().state = 0x7e1;
  if (!cv::solvePnPRansac(object, image, K, cv::noArray(), rvec, tvec, false, 200,
                          static_cast<float>(options_.outlier_px), 0.99, inliers,
                          cv::SOLVEPNP_EPNP) ||
      static_cast<int>(inliers.size()) < options_.reloc_min_matches) {
    return false;
  }
  cv::Mat R;
  cv::Rodrigues(rvec, R);
  Eigen::Matrix3d r;
  Eigen::Vector3d t;
  cv::cv2eigen(R, r);
  cv::cv2eigen(tvec, t);
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.linear() = r;
  pose.translation() = t;
  *outcome = Track(features, local_points, pose);
  return outcome->inliers >= options_.reloc_min_inliers &&
         QualityOf(*outcome) != TrackingQuality::kLost;
}

}  // namespace sightline
