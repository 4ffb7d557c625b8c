#include "core/stereo/feature_tracker.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <opencv2/imgproc.hpp>
#include <opencv2/video/tracking.hpp>
#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "core/stereo/corner_response.h"
#include "core/stereo/option_check.h"

namespace sightline {

using stereo_internal::Invalid;

bool FeatureTrackerOptions::IsValid(std::string* error) const {
  if (max_features < 8) return Invalid(error, "stereo.tracking.max_features must be >= 8");
  if (bucket_size_px < 8) return Invalid(error, "stereo.tracking.bucket_size_px must be >= 8");
  if (!(min_eigenvalue > 0)) return Invalid(error, "stereo.tracking.min_eigenvalue must be > 0");
  if (!(min_distance_px >= 1))
    return Invalid(error, "stereo.tracking.min_distance_px must be >= 1");
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
  if (!(retrack_fraction >= 0 && retrack_fraction <= 1)) {
    return Invalid(error, "stereo.tracking.retrack_fraction must lie in [0, 1]");
  }
  if (retrack_pyramid_levels < 0 || retrack_pyramid_levels > 8) {
    return Invalid(error, "stereo.tracking.retrack_pyramid_levels must lie in [0, 8]");
  }
  if (refine_window_px < 0) return Invalid(error, "stereo.tracking.refine_window_px must be >= 0");
  if (!(turn_search_fraction >= 0 && turn_search_fraction <= 1)) {
    return Invalid(error, "stereo.tracking.turn_search_fraction must lie in [0, 1]");
  }
  if (turn_search_width_px < 32 || turn_search_width_px > 1024) {
    return Invalid(error, "stereo.tracking.turn_search_width_px must lie in [32, 1024]");
  }
  if (!(turn_search_max_deg >= 1 && turn_search_max_deg <= 85)) {
    return Invalid(error, "stereo.tracking.turn_search_max_deg must lie in [1, 85]");
  }
  if (!(refill_fraction > 0 && refill_fraction <= 1)) {
    return Invalid(error, "stereo.tracking.refill_fraction must lie in (0, 1]");
  }
  if (detection_level < 0 || detection_level > pyramid_levels) {
    return Invalid(error, "stereo.tracking.detection_level must lie in [0, pyramid_levels]");
  }
  return true;
}

OptionTable<FeatureTrackerOptions> FeatureTrackerOptions::Describe() {
  using O = FeatureTrackerOptions;
  return OptionTable<O>("stereo.tracking")
      .Int("max_features", &O::max_features, "features", 8, 20000, 50,
           "Features kept per frame, tracked plus new.")
      .Int("bucket_size_px", &O::bucket_size_px, "px", 8, 1000, 4,
           "Side of the detection grid's buckets; each holds at most its share of max_features.")
      .Double("min_eigenvalue", &O::min_eigenvalue, "", 1e-7, 1, 1e-4,
              "Shi-Tomasi: smallest minimum eigenvalue of a corner (cv::cornerMinEigenVal units).")
      .Double("min_distance_px", &O::min_distance_px, "px", 1, 100, 1,
              "Minimum distance between corners.")
      .Int("block_size", &O::block_size, "px", 3, 31, 2, "Shi-Tomasi gradient window.")
      .Int("window_px", &O::window_px, "px", 5, 61, 2, "KLT window side (odd).")
      .Int("pyramid_levels", &O::pyramid_levels, "levels", 0, 6, 1,
           "KLT pyramid levels above full resolution (shared with stereo matching).")
      .Double("retrack_fraction", &O::retrack_fraction, "", 0, 1, 0.05,
              "When fewer tracks survive than this fraction of the share that survived in the "
              "previous frame (poor motion prediction), the lost ones are tracked again with "
              "retrack_pyramid_levels; 0 = never.")
      .Int("retrack_pyramid_levels", &O::retrack_pyramid_levels, "levels", 0, 8, 1,
           "Pyramid levels of the second tracking attempt (reaches about 2^levels further).")
      .Double("turn_search_fraction", &O::turn_search_fraction, "", 0, 1, 0.05,
              "When even after that fewer tracks survive than this fraction of the share that "
              "usually survives (a slow average over the last frames; a sharp turn, or a turn at "
              "a low frame rate), the camera's rotation is searched by comparing the two images "
              "and the points are tracked again from where it puts them; the better attempt is "
              "kept. 0 = never.")
      .Int("turn_search_width_px", &O::turn_search_width_px, "px", 32, 1024, 16,
           "Width of the reduced copies of the two images compared in that search.")
      .Double("turn_search_max_deg", &O::turn_search_max_deg, "deg", 1, 85, 5,
              "Largest turn between two frames that search looks for.")
      .Int("max_iterations", &O::max_iterations, "", 1, 200, 1, "KLT iterations per level.")
      .Double("epsilon_px", &O::epsilon_px, "px", 1e-4, 1, 0.001,
              "KLT stops when its update is smaller than this.")
      .Double("max_forward_backward_px", &O::max_forward_backward_px, "px", 0, 20, 0.1,
              "A track must return to its start within this when tracked backwards; 0 = no check.")
      .Int("border_px", &O::border_px, "px", 0, 200, 1,
           "Features this close to the border are dropped.")
      .Int("detection_level", &O::detection_level, "level", 0, 6, 1,
           "Pyramid level Shi-Tomasi corners are detected on (0 = full resolution).")
      .Double("refill_fraction", &O::refill_fraction, "", 0.01, 1, 0.05,
              "A bucket gets new corners only when it holds fewer than this fraction of its "
              "share of max_features (1 = whenever it is not full).")
      .Int("refine_window_px", &O::refine_window_px, "px", 0, 20, 1,
           "Half-size of the sub-pixel corner refinement at full resolution after detection on a "
           "reduced level; 0 = none.");
}

bool FeatureTracker::Track(const ImagePyramid& previous, const ImagePyramid& current,
                           const std::vector<cv::Point2f>& points,
                           const std::vector<cv::Point2f>& predicted,
                           std::vector<cv::Point2f>* tracked, std::vector<unsigned char>* ok,
                           double usual_fraction) const {
  const std::vector<cv::Point2f>& start = predicted.size() == points.size() ? predicted : points;
  *tracked = start;
  ok->assign(points.size(), 0);
  if (points.empty() || previous.empty() || current.empty()) return false;
  std::vector<size_t> index(points.size());
  for (size_t i = 0; i < index.size(); ++i) index[i] = i;
  const int max_level = std::min(previous.max_level, current.max_level);
  const int levels = std::min(options_.pyramid_levels, max_level);
  TrackPass(previous, current, points, start, index, levels, tracked, ok);
  const int retrack_levels = std::min(options_.retrack_pyramid_levels, max_level);
  const size_t good = static_cast<size_t>(std::count(ok->begin(), ok->end(), 1));
  if (retrack_levels <= levels ||
      !(static_cast<double>(good) <
        options_.retrack_fraction * usual_fraction * static_cast<double>(points.size()))) {
    return false;
  }
  index.clear();
  for (size_t i = 0; i < points.size(); ++i) {
    if (!(*ok)[i]) index.push_back(i);
  }
  TrackPass(previous, current, points, start, index, retrack_levels, tracked, ok);
  return true;
}

void FeatureTracker::TrackPass(const ImagePyramid& previous, const ImagePyramid& current,
                               const std::vector<cv::Point2f>& points,
                               const std::vector<cv::Point2f>& start,
                               const std::vector<size_t>& index, int levels,
                               std::vector<cv::Point2f>* tracked,
                               std::vector<unsigned char>* ok) const {
  if (index.empty()) return;
  std::vector<cv::Point2f> from, to;
  from.reserve(index.size());
  to.reserve(index.size());
  for (size_t i : index) {
    from.push_back(points[i]);
    to.push_back(start[i]);
  }
  const cv::Size window(options_.window_px, options_.window_px);
  const cv::TermCriteria criteria(cv::TermCriteria::COUNT | cv::TermCriteria::EPS,
                                  options_.max_iterations, options_.epsilon_px);
  std::vector<unsigned char> status;
  cv::calcOpticalFlowPyrLK(previous.levels, current.levels, from, to, status, cv::noArray(), window,
                           levels, criteria, cv::OPTFLOW_USE_INITIAL_FLOW, 1e-4);
  const float border = static_cast<float>(options_.border_px);
  const float max_x = current.image.cols - 1 - border, max_y = current.image.rows - 1 - border;
  // The forward checks first, so only the tracks that pass them are tracked back.
  std::vector<size_t> passed;
  passed.reserve(index.size());
  for (size_t k = 0; k < index.size(); ++k) {
    (*tracked)[index[k]] = to[k];
    if (!status[k]) continue;
    const cv::Point2f& p = to[k];
    if (!(p.x >= border && p.y >= border && p.x <= max_x && p.y <= max_y)) continue;
    passed.push_back(k);
  }
  std::vector<unsigned char> back_status;
  std::vector<cv::Point2f> back_from, back;
  if (options_.max_forward_backward_px > 0 && !passed.empty()) {
    back_from.reserve(passed.size());
    back.reserve(passed.size());
    for (size_t k : passed) {
      back_from.push_back(to[k]);
      back.push_back(from[k]);
    }
    cv::calcOpticalFlowPyrLK(current.levels, previous.levels, back_from, back, back_status,
                             cv::noArray(), window, 1, criteria, cv::OPTFLOW_USE_INITIAL_FLOW,
                             1e-4);
  }
  const double max_fb2 = options_.max_forward_backward_px * options_.max_forward_backward_px;
  for (size_t j = 0; j < passed.size(); ++j) {
    const size_t k = passed[j];
    if (!back.empty()) {
      if (!back_status[j]) continue;
      const cv::Point2f d = back[j] - from[k];
      if (d.x * d.x + d.y * d.y > max_fb2) continue;
    }
    (*ok)[index[k]] = 1;
  }
}

namespace {

// The smallest float that is not below `value`.
float FloatAtLeast(double value) {
  float f = static_cast<float>(value);
  if (static_cast<double>(f) < value) f = std::nextafter(f, std::numeric_limits<float>::infinity());
  return f;
}

// One Detect() call: the grid of buckets with the corners they hold (existing and new), and
// the new corners, searched bucket row by bucket row on one pyramid level. Buckets and
// distances are in full-resolution pixels.
class CornerSearch {
 public:
  CornerSearch(const FeatureTrackerOptions& options, const ImagePyramid& pyramid,
               const std::vector<cv::Point2f>& existing, int wanted, int level)
      : options_(options),
        pyramid_(pyramid),
        wanted_(wanted),
        level_(level),
        scale_(static_cast<float>(1 << level)),
        image_(pyramid.Level(level)),
        bs_(options.bucket_size_px),
        cols_((pyramid.image.cols + bs_ - 1) / bs_),
        rows_((pyramid.image.rows + bs_ - 1) / bs_),
        per_bucket_(std::max(1, static_cast<int>(std::ceil(
                                    static_cast<double>(options.max_features) / (cols_ * rows_))))),
        in_bucket_(static_cast<size_t>(cols_ * rows_)),
        min_d2_(options.min_distance_px * options.min_distance_px),
        margin_(options.block_size / 2 + 2),
        // Buckets that need corners: fewer than refill_fraction of their share.
        refill_below_(
            std::max(1, static_cast<int>(std::ceil(options.refill_fraction * per_bucket_)))),
        threshold_(FloatAtLeast(options.min_eigenvalue)) {
    for (const cv::Point2f& p : existing) {
      const int bx = std::clamp(static_cast<int>(p.x) / bs_, 0, cols_ - 1);
      const int by = std::clamp(static_cast<int>(p.y) / bs_, 0, rows_ - 1);
      Bucket(bx, by).push_back(p);
    }
    const int border = static_cast<int>(std::ceil(options.border_px / scale_));
    inside_ = cv::Rect(border, border, image_.cols - 2 * border, image_.rows - 2 * border);
  }

  int rows() const { return rows_; }
  // Fewer new corners than wanted so far.
  bool Short() const { return static_cast<int>(fresh_.size()) < wanted_; }
  std::vector<cv::Point2f>& fresh() { return fresh_; }

  // Searches the bucket row `by`: one eigenvalue image per run of neighbouring buckets that
  // need corners.
  void SearchRow(int by) {
    for (int run_start = 0; run_start < cols_ && Short();) {
      while (run_start < cols_ && !Needy(run_start, by)) ++run_start;
      if (run_start >= cols_) break;
      int run_end = run_start;
      while (run_end + 1 < cols_ && Needy(run_end + 1, by)) ++run_end;
      const int first = run_start, last = run_end;
      run_start = run_end + 1;
      const cv::Rect span =
          cv::Rect(cvFloor(first * bs_ / scale_), cvFloor(by * bs_ / scale_),
                   cvCeil((last - first + 1) * bs_ / scale_), cvCeil(bs_ / scale_)) &
          inside_;
      if (span.width < 3 || span.height < 3) continue;
      const cv::Rect ext = cv::Rect(span.x - margin_, span.y - margin_, span.width + 2 * margin_,
                                    span.height + 2 * margin_) &
                           cv::Rect(0, 0, image_.cols, image_.rows);
      MinEigenResponse(pyramid_.Derivatives(level_), ext, options_.block_size, &eig_);
      for (int bx = first; bx <= last && Short(); ++bx) FillBucket(bx, by, span, ext);
    }
  }

 private:
  size_t Cell(int bx, int by) const {
    return static_cast<size_t>(by) * static_cast<size_t>(cols_) + static_cast<size_t>(bx);
  }
  std::vector<cv::Point2f>& Bucket(int bx, int by) { return in_bucket_[Cell(bx, by)]; }
  bool Needy(int bx, int by) const {
    return static_cast<int>(in_bucket_[Cell(bx, by)].size()) < refill_below_;
  }

  // No corner in the 3 x 3 buckets around (bx, by) closer to p than min_distance_px.
  bool FarFrom(const cv::Point2f& p, int bx, int by) const {
    for (int y = std::max(0, by - 1); y <= std::min(rows_ - 1, by + 1); ++y) {
      for (int x = std::max(0, bx - 1); x <= std::min(cols_ - 1, bx + 1); ++x) {
        for (const cv::Point2f& q : in_bucket_[Cell(x, y)]) {
          const cv::Point2f d = p - q;
          if (d.x * d.x + d.y * d.y < min_d2_) return false;
        }
      }
    }
    return true;
  }

  // Adds up to the bucket's missing share of corners from the eigenvalue image eig_ of `ext`.
  void FillBucket(int bx, int by, const cv::Rect& span, const cv::Rect& ext) {
    std::vector<cv::Point2f>& here = Bucket(bx, by);
    const int need = per_bucket_ - static_cast<int>(here.size());
    if (need <= 0) return;
    const cv::Rect cell = cv::Rect(cvFloor(bx * bs_ / scale_), cvFloor(by * bs_ / scale_),
                                   cvCeil(bs_ / scale_), cvCeil(bs_ / scale_)) &
                          span;
    if (cell.width < 1 || cell.height < 1) return;
    // Only the best `limit` maxima are kept, which skips most comparisons; if the distance test
    // then leaves the cell short, it is scanned again without a limit.
    const size_t limit = static_cast<size_t>(2 * need + 2 * here.size() + 8);
    Collect(cell, ext, limit);
    const size_t kept_before = here.size(), fresh_before = fresh_.size();
    const int added = Take(bx, by, need);
    if (added < need && candidates_.size() == limit && Short()) {
      // Undo and take from the full list, so the result equals an unlimited scan.
      here.resize(kept_before);
      fresh_.resize(fresh_before);
      Collect(cell, ext, 0);
      Take(bx, by, need);
    }
  }

  // The strongest local maxima of eig_ in `cell` into candidates_, strongest first; with
  // limit > 0 only the best `limit` (a min-heap).
  void Collect(const cv::Rect& cell, const cv::Rect& ext, size_t limit) {
    std::vector<std::pair<float, cv::Point>>& candidates = candidates_;
    candidates.clear();
    const auto weaker = [](const auto& a, const auto& b) { return a.first > b.first; };
    // Columns of eig_ with both neighbours inside it.
    const int x_begin = std::max(cell.x - ext.x, 1);
    const int x_end = std::min(cell.x + cell.width - ext.x, eig_.cols - 1);
    for (int y = cell.y; y < cell.y + cell.height; ++y) {
      const int ey = y - ext.y;
      if (ey < 1 || ey + 1 >= eig_.rows || x_begin >= x_end) continue;
      const float* up = eig_.ptr<float>(ey - 1);
      const float* row = eig_.ptr<float>(ey);
      const float* down = eig_.ptr<float>(ey + 1);
      LocalMaxima(up, row, down, x_begin, x_end, &maxima_);
      for (int ex : maxima_) {
        const float v = row[ex];
        if (limit > 0 && candidates.size() == limit && v <= candidates.front().first) continue;
        candidates.emplace_back(v, cv::Point(ex + ext.x, y));
        if (limit == 0) continue;
        std::push_heap(candidates.begin(), candidates.end(), weaker);
        if (candidates.size() > limit) {
          std::pop_heap(candidates.begin(), candidates.end(), weaker);
          candidates.pop_back();
        }
      }
    }
    std::sort(candidates.begin(), candidates.end(), weaker);
  }

  // Columns ex in [begin, end) of the middle row where the response reaches min_eigenvalue and
  // none of its eight neighbours is larger, left to right.
  void LocalMaxima(const float* up, const float* row, const float* down, int begin, int end,
                   std::vector<int>* out) const {
    out->clear();
    const auto is_maximum = [&](int ex) {
      const float v = row[ex];
      return v >= threshold_ && v >= row[ex - 1] && v >= row[ex + 1] && v >= up[ex - 1] &&
             v >= up[ex] && v >= up[ex + 1] && v >= down[ex - 1] && v >= down[ex] &&
             v >= down[ex + 1];
    };
    int ex = begin;
#if defined(__SSE2__)
    const __m128 threshold = _mm_set1_ps(threshold_);
    for (; ex + 4 <= end; ex += 4) {
      const __m128 v = _mm_loadu_ps(row + ex);
      __m128 keep = _mm_cmpge_ps(v, threshold);
      if (_mm_movemask_ps(keep) == 0) continue;
      keep = _mm_and_ps(keep, _mm_cmpge_ps(v, _mm_loadu_ps(row + ex - 1)));
      keep = _mm_and_ps(keep, _mm_cmpge_ps(v, _mm_loadu_ps(row + ex + 1)));
      keep = _mm_and_ps(keep, _mm_cmpge_ps(v, _mm_loadu_ps(up + ex - 1)));
      keep = _mm_and_ps(keep, _mm_cmpge_ps(v, _mm_loadu_ps(up + ex)));
      keep = _mm_and_ps(keep, _mm_cmpge_ps(v, _mm_loadu_ps(up + ex + 1)));
      keep = _mm_and_ps(keep, _mm_cmpge_ps(v, _mm_loadu_ps(down + ex - 1)));
      keep = _mm_and_ps(keep, _mm_cmpge_ps(v, _mm_loadu_ps(down + ex)));
      keep = _mm_and_ps(keep, _mm_cmpge_ps(v, _mm_loadu_ps(down + ex + 1)));
      for (int bits = _mm_movemask_ps(keep); bits != 0; bits &= bits - 1) {
        out->push_back(ex + __builtin_ctz(static_cast<unsigned>(bits)));
      }
    }
#endif
    for (; ex < end; ++ex) {
      if (is_maximum(ex)) out->push_back(ex);
    }
  }

  // Takes candidates far enough from the corners around, up to `need` and the wanted total;
  // returns how many.
  int Take(int bx, int by, int need) {
    std::vector<cv::Point2f>& here = Bucket(bx, by);
    int added = 0;
    for (const auto& [value, pixel] : candidates_) {
      if (added >= need || !Short()) break;
      const cv::Point2f p(pixel.x * scale_, pixel.y * scale_);
      if (!FarFrom(p, bx, by)) continue;
      here.push_back(p);
      fresh_.push_back(p);
      ++added;
    }
    return added;
  }

  const FeatureTrackerOptions& options_;
  const ImagePyramid& pyramid_;
  const int wanted_;
  const int level_;
  const float scale_;     // Of the level.
  const cv::Mat& image_;  // The level's image.
  const int bs_, cols_, rows_, per_bucket_;
  std::vector<std::vector<cv::Point2f>> in_bucket_;
  const double min_d2_;
  const int margin_;  // Around a span, for the eigenvalue image's window.
  const int refill_below_;
  cv::Rect inside_;  // The level's image without the border.
  // min_eigenvalue as the smallest float not below it, so that a float response v passes
  // v >= threshold_ exactly when v >= min_eigenvalue.
  const float threshold_;
  cv::Mat eig_;
  std::vector<std::pair<float, cv::Point>> candidates_;
  std::vector<int> maxima_;  // Scratch: one row's local maxima.
  std::vector<cv::Point2f> fresh_;
};

}  // namespace

std::vector<cv::Point2f> FeatureTracker::Detect(const ImagePyramid& pyramid,
                                                const std::vector<cv::Point2f>& existing) const {
  const int wanted = options_.max_features - static_cast<int>(existing.size());
  if (wanted <= 0 || pyramid.empty()) return {};
  const int level = std::min(options_.detection_level, pyramid.max_level);
  CornerSearch search(options_, pyramid, existing, wanted, level);
  for (int by = 0; by < search.rows() && search.Short(); ++by) search.SearchRow(by);
  std::vector<cv::Point2f> fresh = std::move(search.fresh());
  if (level > 0 && !fresh.empty() && options_.refine_window_px > 0) {
    // Corners found on a reduced level sit up to a pixel off the full-resolution corner; move
    // them onto it so KLT tracks a well-localised patch.
    const int w = options_.refine_window_px;
    cv::cornerSubPix(pyramid.image, fresh, cv::Size(w, w), cv::Size(-1, -1),
                     cv::TermCriteria(cv::TermCriteria::COUNT | cv::TermCriteria::EPS, 10, 0.01));
  }
  return fresh;
}

}  // namespace sightline
