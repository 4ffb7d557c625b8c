#include "core/stereo/feature_tracker.h"

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>
#include <opencv2/video/tracking.hpp>

#include "core/stereo/option_check.h"

namespace sightline {

using stereo_internal::Invalid;

bool FeatureTrackerOptions::IsValid(std::string* error) const {
  if (max_features < 8) return Invalid(error, "stereo.tracking.max_features must be >= 8");
  if (bucket_size_px < 8) return Invalid(error, "stereo.tracking.bucket_size_px must be >= 8");
  if (!(quality_level > 0 && quality_level < 1)) {
    return Invalid(error, "stereo.tracking.quality_level must lie in (0, 1)");
  }
  if (!(min_distance_px >= 1)) return Invalid(error, "stereo.tracking.min_distance_px must be >= 1");
  if (block_size < 3 || block_size % 2 == 0) {
    return Invalid(error, "stereo.tracking.block_size must be odd and >= 3");
  }
  if (window_px < 5 || window_px % 2 == 0) {
    return Invalid(error, "stereo.tracking.window_px must be odd and >= 5");
  }
  if (pyramid_levels < 0 || pyramid_levels > 6) {
    return Invalid(error, "stereo.tracking.pyramid_levels must lie in [0, 6]");
  }
  if (max_iterations < 1) return Invalid(error, "stereo.tracking.max_iterations must be >= 1");
  if (!(epsilon_px > 0)) return Invalid(error, "stereo.tracking.epsilon_px must be > 0");
  if (!(max_forward_backward_px >= 0)) {
    return Invalid(error, "stereo.tracking.max_forward_backward_px must be >= 0");
  }
  if (border_px < 0) return Invalid(error, "stereo.tracking.border_px must be >= 0");
  return true;
}

OptionTable<FeatureTrackerOptions> FeatureTrackerOptions::Describe() {
  using O = FeatureTrackerOptions;
  return OptionTable<O>("stereo.tracking")
      .Int("max_features", &O::max_features, "features", 8, 20000, 50,
           "Features kept per frame, tracked plus new.")
      .Int("bucket_size_px", &O::bucket_size_px, "px", 8, 1000, 4,
           "Side of the detection grid's buckets; each holds at most its share of max_features.")
      .Double("quality_level", &O::quality_level, "", 1e-5, 0.99, 0.001,
              "Shi-Tomasi quality: corners weaker than this times the strongest are dropped.")
      .Double("min_distance_px", &O::min_distance_px, "px", 1, 100, 1,
              "Minimum distance between corners.")
      .Int("block_size", &O::block_size, "px", 3, 31, 2, "Shi-Tomasi gradient window.")
      .Int("window_px", &O::window_px, "px", 5, 61, 2, "KLT window side (odd).")
      .Int("pyramid_levels", &O::pyramid_levels, "levels", 0, 6, 1,
           "KLT pyramid levels above full resolution (shared with stereo matching).")
      .Int("max_iterations", &O::max_iterations, "", 1, 200, 1, "KLT iterations per level.")
      .Double("epsilon_px", &O::epsilon_px, "px", 1e-4, 1, 0.001,
              "KLT stops when its update is smaller than this.")
      .Double("max_forward_backward_px", &O::max_forward_backward_px, "px", 0, 20, 0.1,
              "A track must return to its start within this when tracked backwards; 0 = no check.")
      .Int("border_px", &O::border_px, "px", 0, 200, 1, "Features this close to the border are dropped.");
}

void FeatureTracker::Track(const ImagePyramid& previous, const ImagePyramid& current,
                           const std::vector<cv::Point2f>& points,
                           std::vector<cv::Point2f>* tracked,
                           std::vector<unsigned char>* ok) const {
  tracked->clear();
  ok->assign(points.size(), 0);
  if (points.empty() || previous.empty() || current.empty()) return;
  const cv::Size window(options_.window_px, options_.window_px);
  const int levels = std::min({options_.pyramid_levels, previous.max_level, current.max_level});
  const cv::TermCriteria criteria(cv::TermCriteria::COUNT | cv::TermCriteria::EPS,
                                  options_.max_iterations, options_.epsilon_px);
  std::vector<float> error;
  std::vector<unsigned char> status;
  cv::calcOpticalFlowPyrLK(previous.levels, current.levels, points, *tracked, status, error, window,
                           levels, criteria, 0, 1e-4);
  std::vector<unsigned char> back_status;
  std::vector<cv::Point2f> back;
  if (options_.max_forward_backward_px > 0) {
    back = points;
    cv::calcOpticalFlowPyrLK(current.levels, previous.levels, *tracked, back, back_status, error,
                             window, 1, criteria, cv::OPTFLOW_USE_INITIAL_FLOW, 1e-4);
  }
  const float border = static_cast<float>(options_.border_px);
  const float max_x = current.image.cols - 1 - border, max_y = current.image.rows - 1 - border;
  const double max_fb2 = options_.max_forward_backward_px * options_.max_forward_backward_px;
  for (size_t i = 0; i < points.size(); ++i) {
    if (!status[i]) continue;
    const cv::Point2f& p = (*tracked)[i];
    if (!(p.x >= border && p.y >= border && p.x <= max_x && p.y <= max_y)) continue;
    if (!back.empty()) {
      if (!back_status[i]) continue;
      const cv::Point2f d = back[i] - points[i];
      if (d.x * d.x + d.y * d.y > max_fb2) continue;
    }
    (*ok)[i] = 1;
  }
}

std::vector<cv::Point2f> FeatureTracker::Detect(const cv::Mat& image,
                                                const std::vector<cv::Point2f>& existing) const {
  std::vector<cv::Point2f> fresh;
  const int wanted = options_.max_features - static_cast<int>(existing.size());
  if (wanted <= 0 || image.empty()) return fresh;
  const int bs = options_.bucket_size_px;
  const int cols = (image.cols + bs - 1) / bs, rows = (image.rows + bs - 1) / bs;
  const int per_bucket =
      std::max(1, static_cast<int>(std::ceil(static_cast<double>(options_.max_features) /
                                             (cols * rows))));
  std::vector<int> count(static_cast<size_t>(cols * rows), 0);
  cv::Mat mask(image.size(), CV_8UC1, cv::Scalar(0));
  const int b = options_.border_px;
  if (image.cols > 2 * b && image.rows > 2 * b) {
    mask(cv::Rect(b, b, image.cols - 2 * b, image.rows - 2 * b)).setTo(255);
  }
  const int radius = static_cast<int>(std::ceil(options_.min_distance_px));
  for (const cv::Point2f& p : existing) {
    const int bx = std::clamp(static_cast<int>(p.x) / bs, 0, cols - 1);
    const int by = std::clamp(static_cast<int>(p.y) / bs, 0, rows - 1);
    ++count[static_cast<size_t>(by * cols + bx)];
    cv::circle(mask, cv::Point(cvRound(p.x), cvRound(p.y)), radius, cv::Scalar(0), cv::FILLED);
  }
  // Buckets already full need no corners.
  for (int by = 0; by < rows; ++by) {
    for (int bx = 0; bx < cols; ++bx) {
      if (count[static_cast<size_t>(by * cols + bx)] < per_bucket) continue;
      const cv::Rect cell(bx * bs, by * bs, std::min(bs, image.cols - bx * bs),
                          std::min(bs, image.rows - by * bs));
      mask(cell).setTo(0);
    }
  }
  std::vector<cv::Point2f> corners;
  cv::goodFeaturesToTrack(image, corners, 4 * options_.max_features, options_.quality_level,
                          options_.min_distance_px, mask, options_.block_size);
  for (const cv::Point2f& p : corners) {
    if (static_cast<int>(fresh.size()) >= wanted) break;
    const int bx = std::clamp(static_cast<int>(p.x) / bs, 0, cols - 1);
    const int by = std::clamp(static_cast<int>(p.y) / bs, 0, rows - 1);
    int& c = count[static_cast<size_t>(by * cols + bx)];
    if (c >= per_bucket) continue;
    ++c;
    fresh.push_back(p);
  }
  if (!fresh.empty()) {
    cv::cornerSubPix(image, fresh, cv::Size(3, 3), cv::Size(-1, -1),
                     cv::TermCriteria(cv::TermCriteria::COUNT | cv::TermCriteria::EPS, 10, 0.03));
  }
  return fresh;
}

}  // namespace sightline
