#include "core/mono/two_view_initializer.h"

#include <algorithm>
#include <cmath>
#include <opencv2/calib3d.hpp>
#include <opencv2/core/eigen.hpp>

#include "core/mono/features.h"

namespace sightline {

std::vector<std::pair<int, int>> MatchDescriptors(const cv::Mat& a, const cv::Mat& b,
                                                  int max_distance, double ratio) {
  std::vector<std::pair<int, int>> out;
  if (a.empty() || b.empty()) return out;
  std::vector<int> best_for_b(b.rows, -1), best_distance_b(b.rows, 1 << 30);
  std::vector<std::pair<int, int>> candidates;
  std::vector<int> distances;
  for (int i = 0; i < a.rows; ++i) {
    int best = 1 << 30, second = 1 << 30, best_j = -1;
    const uint8_t* da = a.ptr<uint8_t>(i);
    for (int j = 0; j < b.rows; ++j) {
      const int d = DescriptorDistance(da, b.ptr<uint8_t>(j));
      if (d < best) {
        second = best;
        best = d;
        best_j = j;
      } else if (d < second) {
        second = d;
      }
    }
    if (best_j < 0 || best > max_distance || best > ratio * second) continue;
    candidates.emplace_back(i, best_j);
    distances.push_back(best);
    if (best < best_distance_b[best_j]) {
      best_distance_b[best_j] = best;
      best_for_b[best_j] = i;
    }
  }
  for (size_t k = 0; k < candidates.size(); ++k) {
    if (best_for_b[candidates[k].second] == candidates[k].first) out.push_back(candidates[k]);
  }
  return out;
}

TwoViewInitializer::TwoViewInitializer(const MonoInitOptions& options, const PinholeCamera& camera,
                                       double scale_factor)
    : options_(options), camera_(camera), scale_factor_(scale_factor) {}

void TwoViewInitializer::SetFirst(FrameFeatures first, FrameStamp stamp, int64_t number) {
  references_.clear();
  AddReference(std::move(first), stamp, number);
}

void TwoViewInitializer::AddReference(FrameFeatures features, FrameStamp stamp, int64_t number) {
  references_.push_back({std::move(features), stamp, number});
  while (static_cast<int>(references_.size()) > options_.reference_frames) {
    references_.pop_front();
  }
  used_ = 0;
  frames_tried_ = 0;
  newest_matches_ = 0;
}

std::vector<std::pair<int, int>> MatchAlongEpipolarLines(const FrameFeatures& a,
                                                         const FrameFeatures& b,
                                                         const Eigen::Matrix3d& E,
                                                         const PinholeCamera& camera, double max_px,
                                                         int max_distance, double ratio) {
  std::vector<Eigen::Vector3d> nb;
  nb.reserve(b.size());
  for (const Eigen::Vector2d& p : b.pixels) nb.push_back(Normalised(camera, p).homogeneous());
  const double max_normalised = max_px / std::max(camera.fx, camera.fy);
  std::vector<int> best_for_b(b.size(), -1), best_distance_b(b.size(), 1 << 30);
  std::vector<std::pair<int, int>> candidates;
  for (size_t i = 0; i < a.size(); ++i) {
    const Eigen::Vector3d line = E * Normalised(camera, a.pixels[i]).homogeneous();
    const double norm = line.head<2>().norm();
    if (!(norm > 1e-12)) continue;
    int best = 1 << 30, second = 1 << 30, best_j = -1;
    const uint8_t* da = a.descriptors.ptr<uint8_t>(static_cast<int>(i));
    for (size_t j = 0; j < b.size(); ++j) {
      if (std::abs(nb[j].dot(line)) > max_normalised * norm) continue;
      const int d = DescriptorDistance(da, b.descriptors.ptr<uint8_t>(static_cast<int>(j)));
      if (d < best) {
        second = best;
        best = d;
        best_j = static_cast<int>(j);
      } else if (d < second) {
        second = d;
      }
    }
    if (best_j < 0 || best > max_distance || best > ratio * second) continue;
    candidates.emplace_back(static_cast<int>(i), best_j);
    if (best < best_distance_b[best_j]) {
      best_distance_b[best_j] = best;
      best_for_b[best_j] = static_cast<int>(i);
    }
  }
  std::vector<std::pair<int, int>> out;
  for (const auto& [i, j] : candidates) {
    if (best_for_b[j] == i) out.emplace_back(i, j);
  }
  return out;
}

std::vector<std::pair<int, int>> TwoViewInitializer::Matches(const FrameFeatures& first,
                                                             const FrameFeatures& current,
                                                             bool* guided) const {
  *guided = false;
  std::vector<std::pair<int, int>> seeds =
      MatchDescriptors(first.descriptors, current.descriptors, 64, 0.8);
  const int n = static_cast<int>(seeds.size());
  if (n >= options_.min_matches || n < options_.min_seed_matches) return seeds;
  // Large motion: few descriptor matches survive the ratio test over the whole image; an
  // essential matrix fitted to them restricts the search to epipolar lines.
  std::vector<cv::Point2f> pa, pb;
  for (const auto& [i, j] : seeds) {
    pa.emplace_back(first.pixels[i].x(), first.pixels[i].y());
    pb.emplace_back(current.pixels[j].x(), current.pixels[j].y());
  }
  const cv::Mat K =
      (cv::Mat_<double>(3, 3) << camera_.fx, 0, camera_.cx, 0, camera_.fy, camera_.cy, 0, 0, 1);
  std::vector<uchar> mask;
  cv::theRNG().state = 0x6e1d;  // Deterministic RANSAC.
  const cv::Mat E =
      cv::findEssentialMat(pa, pb, K, cv::RANSAC, 0.999, 2 * options_.ransac_threshold_px, mask);
  if (E.rows != 3 || E.cols != 3 || cv::countNonZero(mask) < options_.min_seed_matches / 2) {
    return seeds;
  }
  Eigen::Matrix3d e;
  cv::cv2eigen(E, e);
  std::vector<std::pair<int, int>> matches = MatchAlongEpipolarLines(
      first, current, e, camera_, options_.guided_epipolar_px, 64, options_.guided_ratio);
  if (matches.size() <= seeds.size()) return seeds;
  *guided = true;
  return matches;
}

std::optional<TwoViewResult> TwoViewInitializer::TryInitialize(const FrameFeatures& current,
                                                               std::string* why) {
  if (references_.empty()) {
    if (why) *why = "no first frame";
    return std::nullopt;
  }
  ++frames_tried_;
  std::string reason;
  for (size_t r = 0; r < references_.size(); ++r) {
    int matched = 0;
    std::optional<TwoViewResult> result =
        TryPair(references_[r].features, current, &reason, &matched);
    if (r + 1 == references_.size()) newest_matches_ = matched;
    if (result) {
      used_ = r;
      return result;
    }
  }
  if (why) *why = reason;
  return std::nullopt;
}

namespace {

struct Candidate {
  Eigen::Isometry3d second_from_first;
  std::vector<int> accepted;  // Indices into the matches.
  std::vector<Eigen::Vector3d> points;
};

Candidate Evaluate(const PinholeCamera& camera, const cv::Mat& R, const cv::Mat& t,
                   const std::vector<std::pair<int, int>>& matches,
                   const std::vector<uchar>& inlier, const FrameFeatures& a, const FrameFeatures& b,
                   double scale_factor, const MonoInitOptions& options) {
  Candidate c;
  Eigen::Matrix3d r;
  Eigen::Vector3d tv;
  cv::cv2eigen(R, r);
  cv::cv2eigen(t, tv);
  c.second_from_first = Eigen::Isometry3d::Identity();
  c.second_from_first.linear() = r;
  c.second_from_first.translation() = tv.normalized();
  const Eigen::Isometry3d first = Eigen::Isometry3d::Identity();
  for (size_t k = 0; k < matches.size(); ++k) {
    if (!inlier[k]) continue;
    const auto [i, j] = matches[k];
    Eigen::Vector3d x;
    if (!Triangulate(first, c.second_from_first, Normalised(camera, a.pixels[i]),
                     Normalised(camera, b.pixels[j]), &x)) {
      continue;
    }
    if (!AcceptTriangulated(camera, x, first, c.second_from_first, a.pixels[i], b.pixels[j],
                            std::pow(scale_factor, a.keypoints[i].octave),
                            std::pow(scale_factor, b.keypoints[j].octave),
                            options.min_point_parallax_deg, options.max_reprojection_px)) {
      continue;
    }
    c.accepted.push_back(static_cast<int>(k));
    c.points.push_back(x);
  }
  return c;
}

// The accepted initialisation of `best` (unit baseline) scaled to `baseline` map units, with
// its median parallax and baseline / median depth.
TwoViewResult ResultOf(const Candidate& best, const std::vector<std::pair<int, int>>& matches,
                       double baseline) {
  TwoViewResult result;
  result.second_from_first = best.second_from_first;
  result.second_from_first.translation() *= baseline;  // Unit length before.
  std::vector<double> parallax;
  const Eigen::Vector3d centre_b = best.second_from_first.inverse().translation();
  for (size_t k = 0; k < best.accepted.size(); ++k) {
    result.matches.push_back(matches[best.accepted[k]]);
    result.points.push_back(best.points[k] * baseline);
    parallax.push_back(ParallaxDeg(best.points[k], Eigen::Vector3d::Zero(), centre_b));
  }
  std::nth_element(parallax.begin(), parallax.begin() + parallax.size() / 2, parallax.end());
  result.median_parallax_deg = parallax[parallax.size() / 2];
  std::vector<double> depths;
  for (const Eigen::Vector3d& x : best.points) depths.push_back(x.z());
  std::nth_element(depths.begin(), depths.begin() + depths.size() / 2, depths.end());
  result.baseline_ratio = 1.0 / depths[depths.size() / 2];  // The baseline has unit length here.
  return result;
}

}  // namespace

std::optional<TwoViewResult> TwoViewInitializer::TryPair(const FrameFeatures& first,
                                                         const FrameFeatures& current,
                                                         std::string* why, int* matched) {
  auto fail = [&](const std::string& m) -> std::optional<TwoViewResult> {
    if (why) *why = m;
    return std::nullopt;
  };
  bool guided = false;
  const std::vector<std::pair<int, int>> matches = Matches(first, current, &guided);
  *matched = static_cast<int>(matches.size());
  if (static_cast<int>(matches.size()) < options_.min_matches) {
    return fail(std::to_string(matches.size()) + " matches with the first frame");
  }
  std::vector<cv::Point2f> pa, pb;
  std::vector<double> angles;
  for (const auto& [i, j] : matches) {
    pa.emplace_back(first.pixels[i].x(), first.pixels[i].y());
    pb.emplace_back(current.pixels[j].x(), current.pixels[j].y());
    const Eigen::Vector3d ra = Normalised(camera_, first.pixels[i]).homogeneous().normalized();
    const Eigen::Vector3d rb = Normalised(camera_, current.pixels[j]).homogeneous().normalized();
    angles.push_back(std::acos(std::clamp(ra.dot(rb), -1.0, 1.0)) * 180 / M_PI);
  }
  std::nth_element(angles.begin(), angles.begin() + angles.size() / 2, angles.end());
  if (angles[angles.size() / 2] < options_.min_median_parallax_deg) {
    return fail("too little parallax yet (median " + std::to_string(angles[angles.size() / 2]) +
                " deg); move the camera sideways");
  }
  const cv::Mat K =
      (cv::Mat_<double>(3, 3) << camera_.fx, 0, camera_.cx, 0, camera_.fy, camera_.cy, 0, 0, 1);
  std::vector<uchar> mask_e, mask_h;
  cv::RNG& rng = cv::theRNG();
  rng.state = 0x5151;  // Deterministic RANSAC.
  const cv::Mat E =
      cv::findEssentialMat(pa, pb, K, cv::RANSAC, 0.999, options_.ransac_threshold_px, mask_e);
  const cv::Mat H =
      cv::findHomography(pa, pb, cv::RANSAC, options_.ransac_threshold_px, mask_h, 2000, 0.999);
  const int ne = E.rows == 3 && E.cols == 3 ? cv::countNonZero(mask_e) : 0;
  const int nh = H.empty() ? 0 : cv::countNonZero(mask_h);
  if (ne + nh == 0) return fail("neither an essential matrix nor a homography fits");
  const bool use_h = static_cast<double>(nh) / (nh + ne) > options_.homography_ratio;

  std::vector<Candidate> candidates;
  if (use_h) {
    std::vector<cv::Mat> Rs, ts, normals;
    cv::decomposeHomographyMat(H, K, Rs, ts, normals);
    for (size_t s = 0; s < Rs.size(); ++s) {
      if (cv::norm(ts[s]) < 1e-9) continue;  // Pure rotation: no baseline.
      candidates.push_back(Evaluate(camera_, Rs[s], ts[s], matches, mask_h, first, current,
                                    scale_factor_, options_));
    }
  } else {
    cv::Mat R1, R2, t;
    cv::decomposeEssentialMat(E.rowRange(0, 3), R1, R2, t);
    for (const cv::Mat& R : {R1, R2}) {
      for (double sign : {1.0, -1.0}) {
        candidates.push_back(Evaluate(camera_, R, sign * t, matches, mask_e, first, current,
                                      scale_factor_, options_));
      }
    }
  }
  std::sort(candidates.begin(), candidates.end(), [](const Candidate& a, const Candidate& b) {
    return a.accepted.size() > b.accepted.size();
  });
  if (candidates.empty() || static_cast<int>(candidates[0].accepted.size()) < options_.min_points) {
    return fail(std::string(use_h ? "homography" : "essential matrix") + ": " +
                std::to_string(candidates.empty() ? 0 : candidates[0].accepted.size()) +
                " points triangulate well (need " + std::to_string(options_.min_points) + ")");
  }
  if (candidates.size() > 1 &&
      candidates[1].accepted.size() > 0.75 * candidates[0].accepted.size()) {
    return fail("two motions explain the matches equally well; keep moving");
  }
  TwoViewResult result = ResultOf(candidates[0], matches, options_.baseline);
  result.model = use_h ? "homography" : "essential";
  result.guided = guided;
  result.homography_inliers = nh;
  result.essential_inliers = ne;
  if (result.baseline_ratio < options_.min_baseline_ratio) {
    return fail("baseline still short (" + std::to_string(result.baseline_ratio) +
                " of the median depth); keep moving sideways");
  }
  return result;
}

}  // namespace sightline
