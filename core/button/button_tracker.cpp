#include "core/button/button_tracker.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <opencv2/calib3d.hpp>
#include <opencv2/features2d.hpp>
#include <opencv2/imgproc.hpp>

#include "core/button/button_detector.h"
#include "core/button/option_check.h"

namespace sightline {

using button_internal::Invalid;

const char* TrackStateName(TrackState state) {
  switch (state) {
    case TrackState::kTracking:
      return "tracking";
    case TrackState::kReacquired:
      return "reacquired";
    case TrackState::kLost:
      return "lost";
  }
  return "?";
}

bool ButtonTrackerOptions::IsValid(std::string* error) const {
  if (!(ratio > 0 && ratio <= 1)) return Invalid(error, "button.track.ratio must lie in (0, 1]");
  if (!(gate_px > 0)) return Invalid(error, "button.track.gate_px must be > 0");
  if (!(gate_radius >= 0)) return Invalid(error, "button.track.gate_radius must be >= 0");
  if (!(window_px >= 8)) return Invalid(error, "button.track.window_px must be >= 8");
  if (!(window_radius >= 0)) return Invalid(error, "button.track.window_radius must be >= 0");
  if (min_matches < 2) return Invalid(error, "button.track.min_matches must be >= 2");
  if (centre != "similarity" && centre != "centroid") {
    return Invalid(error, "button.track.centre must be similarity or centroid");
  }
  if (!(ransac_px > 0)) return Invalid(error, "button.track.ransac_px must be > 0");
  if (!(sift_contrast > 0 && sift_contrast < 1)) {
    return Invalid(error, "button.track.sift_contrast must lie in (0, 1)");
  }
  if (flann_trees < 1 || flann_trees > 64)
    return Invalid(error, "button.track.flann_trees must lie in [1, 64]");
  if (flann_checks < 1) return Invalid(error, "button.track.flann_checks must be >= 1");
  if (!(refresh_scale_step > 1))
    return Invalid(error, "button.track.refresh_scale_step must be > 1");
  if (!(refresh_radius > 0)) return Invalid(error, "button.track.refresh_radius must be > 0");
  if (!(refresh_min_confidence >= 0 && refresh_min_confidence <= 1)) {
    return Invalid(error, "button.track.refresh_min_confidence must lie in [0, 1]");
  }
  if (max_model_keypoints < 2)
    return Invalid(error, "button.track.max_model_keypoints must be >= 2");
  if (reacquire_min_inliers < 2)
    return Invalid(error, "button.track.reacquire_min_inliers must be >= 2");
  if (!(reacquire_max_scale >= 1))
    return Invalid(error, "button.track.reacquire_max_scale must be >= 1");
  if (reacquire_min_face < 0) return Invalid(error, "button.track.reacquire_min_face must be >= 0");
  if (!(reacquire_face_radius > 0))
    return Invalid(error, "button.track.reacquire_face_radius must be > 0");
  if (!(reacquire_ambiguity > 0 && reacquire_ambiguity <= 1))
    return Invalid(error, "button.track.reacquire_ambiguity must lie in (0, 1]");
  if (!(view_margin_px >= 0)) return Invalid(error, "button.track.view_margin_px must be >= 0");
  if (anchor_min_matches < 2) return Invalid(error, "button.track.anchor_min_matches must be >= 2");
  return true;
}

OptionTable<ButtonTrackerOptions> ButtonTrackerOptions::Describe() {
  using O = ButtonTrackerOptions;
  return OptionTable<O>("button.track")
      .Double("ratio", &O::ratio, "", 0.1, 1, 0.01,
              "Lowe's ratio test: best over second-best descriptor distance must be below this.")
      .Double("gate_px", &O::gate_px, "px", 1, 5000, 1,
              "Distance gate: a match farther than this from the predicted centre is dropped.")
      .Double("gate_radius", &O::gate_radius, "radii", 0, 100, 0.1,
              "The gate grows to this many predicted button radii when that is larger.")
      .Bool("use_window", &O::use_window,
            "Compute SIFT only in a window around the predicted centre (fast).")
      .Double("window_px", &O::window_px, "px", 8, 5000, 4, "Half size of the search window.")
      .Double("window_radius", &O::window_radius, "radii", 0, 100, 0.1,
              "The window grows to this many predicted button radii when that is larger.")
      .Int("min_matches", &O::min_matches, "", 2, 1000, 1,
           "Fewer consistent matches: the button is lost.")
      .Choice("centre", &O::centre, {"similarity", "centroid"},
              "New centre: the model centre through a RANSAC similarity of the matches, or the "
              "matched keypoints' centroid (the published rule).")
      .Double("ransac_px", &O::ransac_px, "px", 0.1, 50, 0.1, "Similarity RANSAC inlier distance.")
      .Double("sift_contrast", &O::sift_contrast, "", 0.001, 0.5, 0.005, "SIFT contrast threshold.")
      .Int("flann_trees", &O::flann_trees, "", 1, 64, 1, "FLANN randomised kd-trees.")
      .Int("flann_checks", &O::flann_checks, "", 1, 100000, 8, "FLANN leaf checks per query.")
      .Bool("refresh", &O::refresh,
            "Add features of confidently tracked frames to the model when the button's apparent "
            "size has changed.")
      .Double("refresh_scale_step", &O::refresh_scale_step, "", 1.01, 10, 0.05,
              "Size change since the last refresh that triggers the next.")
      .Double("refresh_radius", &O::refresh_radius, "radii", 0.1, 20, 0.1,
              "Features within this many button radii of the centre are added.")
      .Double("refresh_min_confidence", &O::refresh_min_confidence, "", 0, 1, 0.05,
              "Only frames tracked at least this confidently refresh the model.")
      .Int("max_model_keypoints", &O::max_model_keypoints, "", 2, 100000, 100,
           "The model never grows beyond this many keypoints.")
      .Bool("reacquire", &O::reacquire,
            "After a loss, search whole frames and re-acquire the button only on a confident "
            "match at a plausible size.")
      .Int("reacquire_min_inliers", &O::reacquire_min_inliers, "", 2, 1000, 1,
           "Consistent matches needed to re-acquire a lost button.")
      .Double("reacquire_max_scale", &O::reacquire_max_scale, "", 1, 10, 0.05,
              "Largest size change (either way) since the last tracked frame at re-acquisition.")
      .Int("reacquire_min_face", &O::reacquire_min_face, "", 0, 1000, 1,
           "Of the re-acquiring matches, at least this many lie on the button itself.")
      .Double("reacquire_face_radius", &O::reacquire_face_radius, "radii", 0.1, 10, 0.1,
              "On the button: within this many radii of its centre.")
      .Double("reacquire_ambiguity", &O::reacquire_ambiguity, "", 0.01, 1, 0.05,
              "Re-acquisition is refused when the other matches support a second similarity "
              "with this fraction of the inliers (another button of a repeated panel).")
      .Double("view_margin_px", &O::view_margin_px, "px", 0, 1000, 1,
              "A button centre farther than this outside the image is out of view (lost).")
      .Int("anchor_min_matches", &O::anchor_min_matches, "matches", 2, 1000, 1,
           "The size from the tap's own keypoints alone (not the refreshed ones, whose scale "
           "drifts; the looming in button.triangulate.*) needs this many consistent matches.");
}

ButtonTracker::ButtonTracker(std::shared_ptr<const ButtonModel> model, ButtonTrackerOptions options)
    : model_(std::move(model)), options_(std::move(options)) {
  if (!model_) return;
  for (const cv::KeyPoint& k : model_->keypoints) points_.push_back(k.pt);
  descriptors_ = model_->descriptors.clone();
  RebuildIndex();
}

void ButtonTracker::RebuildIndex() {
  index_.release();
  if (descriptors_.rows >= 2) {
    index_ = cv::makePtr<cv::flann::Index>(descriptors_,
                                           cv::flann::KDTreeIndexParams(options_.flann_trees));
  }
}

void ButtonTracker::Refresh(const std::vector<cv::KeyPoint>& keypoints, const cv::Mat& descriptors,
                            cv::Point2f offset, const ButtonTrack& track,
                            const cv::Mat& model_to_image) {
  cv::Mat image_to_model;
  cv::invertAffineTransform(model_to_image, image_to_model);
  const double reach = options_.refresh_radius * track.radius_px;
  const cv::Matx23d m(image_to_model);
  for (size_t i = 0; i < keypoints.size(); ++i) {
    if (descriptors_.rows >= options_.max_model_keypoints) break;
    const cv::Point2f at = keypoints[i].pt + offset;
    if (std::hypot(at.x - track.center.x, at.y - track.center.y) > reach) continue;
    points_.emplace_back(float(m(0, 0) * at.x + m(0, 1) * at.y + m(0, 2)),
                         float(m(1, 0) * at.x + m(1, 1) * at.y + m(1, 2)));
    descriptors_.push_back(descriptors.row(int(i)));
  }
  refresh_scale_ = track.scale;
  RebuildIndex();
}

double ButtonTracker::AnchorScale(const std::vector<cv::KeyPoint>& keypoints,
                                  const cv::Mat& descriptors, cv::Point2f offset,
                                  const ButtonTrack& track) const {
  const cv::Mat& tap = model_->descriptors;
  if (keypoints.empty() || tap.rows < options_.anchor_min_matches) return 0;
  std::vector<std::vector<cv::DMatch>> knn;
  cv::BFMatcher(cv::NORM_L2).knnMatch(descriptors, tap, knn, 2);
  const double reach = options_.refresh_radius * track.radius_px + options_.ransac_px;
  std::vector<int> best(tap.rows, -1);
  std::vector<float> best_distance(tap.rows, 0);
  for (const std::vector<cv::DMatch>& m : knn) {
    if (m.size() < 2 || !(m[0].distance < options_.ratio * m[1].distance)) continue;
    const cv::Point2f at = keypoints[m[0].queryIdx].pt + offset;
    if (std::hypot(at.x - track.center.x, at.y - track.center.y) > reach) continue;
    const int k = m[0].trainIdx;
    if (best[k] < 0 || m[0].distance < best_distance[k]) {
      best[k] = m[0].queryIdx;
      best_distance[k] = m[0].distance;
    }
  }
  std::vector<cv::Point2f> from, to;
  for (int k = 0; k < tap.rows; ++k) {
    if (best[k] < 0) continue;
    from.push_back(model_->keypoints[k].pt);
    to.push_back(keypoints[best[k]].pt + offset);
  }
  if (static_cast<int>(from.size()) < options_.anchor_min_matches) return 0;
  std::vector<uchar> mask;
  const cv::Mat s =
      cv::estimateAffinePartial2D(from, to, mask, cv::RANSAC, options_.ransac_px, 2000, 0.995, 10);
  if (s.empty()) return 0;
  if (std::count(mask.begin(), mask.end(), uchar(1)) < options_.anchor_min_matches) return 0;
  return std::hypot(s.at<double>(0, 0), s.at<double>(1, 0));
}

cv::Rect ButtonTracker::Window(cv::Size size, const TrackPrediction& p) const {
  const cv::Rect whole(0, 0, size.width, size.height);
  if (!options_.use_window || !p.valid) return whole;
  const double half =
      std::max(options_.window_px, options_.window_radius * model_->RadiusPx() * p.scale);
  const cv::Rect window(int(std::floor(p.center.x - half)), int(std::floor(p.center.y - half)),
                        int(std::ceil(2 * half)), int(std::ceil(2 * half)));
  return window & whole;
}

namespace {

struct Match {
  int model = 0;
  cv::Point2f at;
  float distance = 0;
};

}  // namespace

StatusOr<ButtonTrack> ButtonTracker::Track(const cv::Mat& image,
                                           const TrackPrediction& prediction) {
  const bool was_lost = lost_frames_ > 0;
  StatusOr<ButtonTrack> result = TrackOnce(image, prediction, was_lost);
  if (!result.ok()) return result;
  ButtonTrack& track = *result;
  if (track.found) {
    track.state = was_lost ? TrackState::kReacquired : TrackState::kTracking;
    if (was_lost) ++reacquisitions_;
    lost_frames_ = 0;
    last_scale_ = track.scale;
  } else {
    track.state = TrackState::kLost;
    ++lost_frames_;
    last_.reset();
  }
  track.lost_frames = lost_frames_;
  track.reacquisitions = reacquisitions_;
  return result;
}

StatusOr<ButtonTrack> ButtonTracker::TrackOnce(const cv::Mat& image,
                                               const TrackPrediction& prediction, bool lost) {
  std::string error;
  if (!options_.IsValid(&error)) return InvalidArgument(error);
  if (!model_ || !index_)
    return FailedPrecondition("button tracker: the button model has no features");
  if (image.empty()) return InvalidArgument("button tracker: empty image");
  const cv::Mat grey = ToGrey(image);
  if (grey.empty()) return InvalidArgument("button tracker: image must be 8-bit grey, BGR or BGRA");

  const TrackPrediction p = prediction.valid ? prediction : last_.value_or(TrackPrediction{});
  ButtonTrack track;
  track.window = Window(grey.size(), p);
  if (track.window.area() <= 0) {
    track.reason = "predicted window lies outside the image";
    last_.reset();
    return track;
  }
  cv::Ptr<cv::SIFT> sift = cv::SIFT::create(0, 3, options_.sift_contrast);
  std::vector<cv::KeyPoint> keypoints;
  cv::Mat descriptors;
  sift->detectAndCompute(grey(track.window), cv::noArray(), keypoints, descriptors);
  track.keypoints = int(keypoints.size());

  // Ratio test, distance gate, and one match per model keypoint (the closest descriptor).
  std::vector<Match> best(points_.size(), Match{-1, {}, 0});
  if (!keypoints.empty() && points_.size() >= 2) {
    cv::Mat indices, dists;
    index_->knnSearch(descriptors, indices, dists, 2,
                      cv::flann::SearchParams(options_.flann_checks));
    const double gate =
        std::max(options_.gate_px, options_.gate_radius * model_->RadiusPx() * p.scale);
    const float ratio2 = float(options_.ratio * options_.ratio);  // Distances are squared.
    for (int i = 0; i < indices.rows; ++i) {
      const int m = indices.at<int>(i, 0);
      const float d0 = dists.at<float>(i, 0), d1 = dists.at<float>(i, 1);
      if (m < 0 || !(d0 < ratio2 * d1)) continue;
      const cv::Point2f at = keypoints[i].pt + cv::Point2f(track.window.tl());
      if (p.valid && std::hypot(at.x - p.center.x, at.y - p.center.y) > gate) continue;
      if (best[m].model < 0 || d0 < best[m].distance) best[m] = Match{m, at, d0};
    }
  }
  std::vector<cv::Point2f> from, to;
  for (const Match& m : best) {
    if (m.model < 0) continue;
    from.push_back(points_[m.model]);
    to.push_back(m.at);
  }
  track.matches = int(to.size());
  if (track.matches < options_.min_matches) {
    track.reason = "lost: " + std::to_string(track.matches) + " matches (needs " +
                   std::to_string(options_.min_matches) + ")";
    last_.reset();
    return track;
  }
  cv::Mat similarity;
  if (options_.centre == "centroid") {
    cv::Point2d sum(0, 0);
    for (const cv::Point2f& q : to) sum += cv::Point2d(q);
    track.center = sum / double(to.size());
    track.inliers = track.matches;
    track.scale = p.valid ? p.scale : 1.0;
  } else {
    std::vector<uchar> inlier_mask;
    const cv::Mat s = cv::estimateAffinePartial2D(from, to, inlier_mask, cv::RANSAC,
                                                  options_.ransac_px, 2000, 0.995, 10);
    track.inliers = int(std::count(inlier_mask.begin(), inlier_mask.end(), uchar(1)));
    if (s.empty() || track.inliers < options_.min_matches) {
      track.reason = "lost: " + std::to_string(track.inliers) + " consistent matches (needs " +
                     std::to_string(options_.min_matches) + ")";
      last_.reset();
      return track;
    }
    similarity = s;
    const double a = s.at<double>(0, 0), b = s.at<double>(1, 0);
    track.scale = std::hypot(a, b);
    const cv::Point2d c = model_->center;
    track.center = {a * c.x - b * c.y + s.at<double>(0, 2), b * c.x + a * c.y + s.at<double>(1, 2)};
  }
  if (lost && options_.reacquire && options_.centre == "similarity") {
    const double change = std::max(track.scale / last_scale_, last_scale_ / track.scale);
    // Inliers on the button's own face, and a second similarity among the other matches.
    const double face = options_.reacquire_face_radius * model_->RadiusPx() * track.scale;
    int on_face = 0, second = 0;
    {
      std::vector<cv::Point2f> rest_from, rest_to;
      const cv::Matx23d s(similarity);
      for (size_t i = 0; i < to.size(); ++i) {
        const cv::Point2f& q = from[i];
        const cv::Point2d mapped(s(0, 0) * q.x + s(0, 1) * q.y + s(0, 2),
                                 s(1, 0) * q.x + s(1, 1) * q.y + s(1, 2));
        const bool inlier = cv::norm(mapped - cv::Point2d(to[i])) <= options_.ransac_px;
        if (inlier) {
          on_face += cv::norm(cv::Point2d(to[i]) - track.center) <= face ? 1 : 0;
        } else {
          rest_from.push_back(from[i]);
          rest_to.push_back(to[i]);
        }
      }
      if (int(rest_to.size()) >= options_.min_matches) {
        std::vector<uchar> rest_mask;
        const cv::Mat s2 = cv::estimateAffinePartial2D(rest_from, rest_to, rest_mask, cv::RANSAC,
                                                       options_.ransac_px, 2000, 0.995, 10);
        if (!s2.empty()) second = int(std::count(rest_mask.begin(), rest_mask.end(), uchar(1)));
      }
    }
    const bool ambiguous =
        second >= options_.min_matches && second >= options_.reacquire_ambiguity * track.inliers;
    if (track.inliers < options_.reacquire_min_inliers || on_face < options_.reacquire_min_face ||
        change > options_.reacquire_max_scale || ambiguous) {
      char text[200];
      std::snprintf(text, sizeof(text),
                    "lost: re-acquisition refused (%d consistent matches, needs %d; %d on the "
                    "button, needs %d; size x%.2f, at most x%.2f; second fit %d)",
                    track.inliers, options_.reacquire_min_inliers, on_face,
                    options_.reacquire_min_face, change, options_.reacquire_max_scale, second);
      track.reason = text;
      return track;
    }
  }
  const double m = options_.view_margin_px;
  if (track.center.x < -m || track.center.y < -m || track.center.x > grey.cols - 1 + m ||
      track.center.y > grey.rows - 1 + m) {
    track.reason = "lost: the button lies outside the view";
    return track;
  }
  track.radius_px = model_->RadiusPx() * track.scale;
  if (!similarity.empty()) {
    track.anchor_scale = AnchorScale(keypoints, descriptors, cv::Point2f(track.window.tl()), track);
  }
  const double fraction = double(track.inliers) / std::max(1, track.matches);
  const double support = std::min(1.0, double(track.inliers) / (2.0 * options_.min_matches));
  track.confidence = fraction * support;
  track.found = true;
  last_ = TrackPrediction{true, track.center, track.scale};
  const double change = std::max(track.scale / refresh_scale_, refresh_scale_ / track.scale);
  if (options_.refresh && !lost && !similarity.empty() &&
      track.confidence >= options_.refresh_min_confidence &&
      change >= options_.refresh_scale_step) {
    Refresh(keypoints, descriptors, cv::Point2f(track.window.tl()), track, similarity);
  }
  return track;
}

}  // namespace sightline
