#include "core/stereo/stereo_matcher.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <opencv2/video/tracking.hpp>
#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "core/stereo/option_check.h"

namespace sightline {

using stereo_internal::Invalid;

bool StereoMatcherOptions::IsValid(std::string* error) const {
  if (!(min_disparity_px >= 0))
    return Invalid(error, "stereo.matching.min_disparity_px must be >= 0");
  if (!(max_disparity_px > min_disparity_px)) {
    return Invalid(error, "stereo.matching.max_disparity_px must exceed min_disparity_px");
  }
  if (!(max_row_error_px > 0))
    return Invalid(error, "stereo.matching.max_row_error_px must be > 0");
  if (!(max_left_right_px >= 0))
    return Invalid(error, "stereo.matching.max_left_right_px must be >= 0");
  if (window_px < 5 || window_px % 2 == 0) {
    return Invalid(error, "stereo.matching.window_px must be odd and >= 5");
  }
  if (klt_levels < 0 || klt_levels > 6)
    return Invalid(error, "stereo.matching.klt_levels must lie in [0, 6]");
  if (max_iterations < 1) return Invalid(error, "stereo.matching.max_iterations must be >= 1");
  if (coarse_level < 0 || coarse_level > 6) {
    return Invalid(error, "stereo.matching.coarse_level must lie in [0, 6]");
  }
  if (coarse_window_px < 3 || coarse_window_px % 2 == 0) {
    return Invalid(error, "stereo.matching.coarse_window_px must be odd and >= 3");
  }
  if (!(max_coarse_sad > 0)) return Invalid(error, "stereo.matching.max_coarse_sad must be > 0");
  return true;
}

OptionTable<StereoMatcherOptions> StereoMatcherOptions::Describe() {
  using O = StereoMatcherOptions;
  return OptionTable<O>("stereo.matching")
      .Double("min_disparity_px", &O::min_disparity_px, "px", 0, 100, 0.1,
              "Matches with a smaller disparity (too far to triangulate) are rejected.")
      .Double("max_disparity_px", &O::max_disparity_px, "px", 1, 1000, 1,
              "Largest disparity searched and accepted.")
      .Double("max_row_error_px", &O::max_row_error_px, "px", 0.01, 20, 0.1,
              "Epipolar (row) constraint: largest row difference of a match.")
      .Double("max_left_right_px", &O::max_left_right_px, "px", 0, 20, 0.1,
              "Left-right check: the right point tracked back must land this close; 0 = no check.")
      .Int("window_px", &O::window_px, "px", 5, 61, 2, "KLT window side (odd).")
      .Int("klt_levels", &O::klt_levels, "levels", 0, 6, 1,
           "KLT pyramid levels used around the disparity guess.")
      .Int("max_iterations", &O::max_iterations, "", 1, 200, 1, "KLT iterations per level.")
      .Int("coarse_level", &O::coarse_level, "level", 0, 6, 1,
           "Pyramid level of the row search for features without a disparity guess.")
      .Int("coarse_window_px", &O::coarse_window_px, "px", 3, 31, 2,
           "SAD window side of the row search, at its level.")
      .Double("max_coarse_sad", &O::max_coarse_sad, "grey", 1, 255, 1,
              "Row search: mean absolute difference above this means no match.");
}

namespace {

// Sum of absolute differences of the (2h + 1)^2 windows at l and r (row steps given).
int WindowSad(const unsigned char* l, size_t l_step, const unsigned char* r, size_t r_step, int h,
              int bound) {
  int sad = 0;
  for (int dy = 0; dy <= 2 * h && sad < bound; ++dy) {
    const unsigned char* lr = l + dy * l_step;
    const unsigned char* rr = r + dy * r_step;
    for (int dx = 0; dx <= 2 * h; ++dx) sad += std::abs(static_cast<int>(lr[dx]) - rr[dx]);
  }
  return sad;
}

#if defined(__SSE2__)
// The 7 x 7 row search with one psadbw per two window rows: the left window stays in registers,
// only the right one is loaded per disparity. Each row reads 8 bytes, the eighth masked off,
// so the caller keeps one byte readable after every window row. Same result as the scalar
// search (the first disparity with the smallest SAD).
void RowSearch7(const unsigned char* l, size_t l_step, const unsigned char* r, size_t r_step,
                int d_min, int d_max, int* best_d, int* best) {
  const __m128i mask = _mm_set_epi8(0, -1, -1, -1, -1, -1, -1, -1, 0, -1, -1, -1, -1, -1, -1, -1);
  const auto pair = [&](const unsigned char* p, size_t step, int row) {
    const __m128i a = _mm_loadl_epi64(reinterpret_cast<const __m128i*>(p + row * step));
    const __m128i b = row + 1 < 7
                          ? _mm_loadl_epi64(reinterpret_cast<const __m128i*>(p + (row + 1) * step))
                          : _mm_setzero_si128();
    return _mm_and_si128(_mm_unpacklo_epi64(a, b), mask);
  };
  const __m128i l0 = pair(l, l_step, 0), l1 = pair(l, l_step, 2), l2 = pair(l, l_step, 4),
                l3 = pair(l, l_step, 6);
  for (int d = d_min; d <= d_max; ++d) {
    const unsigned char* rd = r - d;
    __m128i sum = _mm_sad_epu8(l0, pair(rd, r_step, 0));
    sum = _mm_add_epi64(sum, _mm_sad_epu8(l1, pair(rd, r_step, 2)));
    sum = _mm_add_epi64(sum, _mm_sad_epu8(l2, pair(rd, r_step, 4)));
    sum = _mm_add_epi64(sum, _mm_sad_epu8(l3, pair(rd, r_step, 6)));
    const int sad = _mm_cvtsi128_si32(sum) + _mm_cvtsi128_si32(_mm_srli_si128(sum, 8));
    if (sad < *best) {
      *best = sad;
      *best_d = d;
    }
  }
}
#endif

}  // namespace

float StereoMatcher::CoarseDisparity(const cv::Mat& left, const cv::Mat& right, cv::Point2f p,
                                     int scale) const {
  const int h = options_.coarse_window_px / 2;
  const int x = cvRound(p.x / scale), y = cvRound(p.y / scale);
  if (x - h < 0 || y - h < 0 || x + h >= left.cols || y + h >= left.rows) {
    return std::numeric_limits<float>::quiet_NaN();
  }
  const int d_min = std::max(0, static_cast<int>(std::floor(options_.min_disparity_px / scale)));
  const int d_max = std::min(x - h, static_cast<int>(std::ceil(options_.max_disparity_px / scale)));
  int best_d = -1;
  int best = std::numeric_limits<int>::max();
  const unsigned char* l = left.ptr<unsigned char>(y - h) + (x - h);
  const unsigned char* r = right.ptr<unsigned char>(y - h) + (x - h);
  const size_t l_step = left.step[0], r_step = right.step[0];
#if defined(__SSE2__)
  // The vector search reads one byte past each window row: inside the row unless the window
  // touches the image's last column.
  if (h == 3 && x + h + 1 < left.cols && x + h + 1 < right.cols) {
    RowSearch7(l, l_step, r, r_step, d_min, d_max, &best_d, &best);
  } else
#endif
  {
    for (int d = d_min; d <= d_max; ++d) {
      const int sad = WindowSad(l, l_step, r - d, r_step, h, best);
      if (sad < best) {
        best = sad;
        best_d = d;
      }
    }
  }
  const int n = (2 * h + 1) * (2 * h + 1);
  if (best_d < 0 || best > options_.max_coarse_sad * n)
    return std::numeric_limits<float>::quiet_NaN();
  return static_cast<float>(best_d * scale);
}

void StereoMatcher::Match(const ImagePyramid& left, const ImagePyramid& right,
                          const std::vector<cv::Point2f>& left_points,
                          const std::vector<float>& disparity_guess,
                          std::vector<cv::Point2f>* right_points,
                          std::vector<unsigned char>* ok) const {
  const size_t n = left_points.size();
  right_points->assign(n, cv::Point2f(0, 0));
  ok->assign(n, 0);
  if (n == 0 || left.empty() || right.empty()) return;
  const int coarse = std::min({options_.coarse_level, left.max_level, right.max_level});
  const int scale = 1 << coarse;
  const auto row_search = [&](size_t i) {
    return CoarseDisparity(left.Level(coarse), right.Level(coarse), left_points[i], scale);
  };
  // Only features with a disparity (guessed or found by the row search) go to KLT.
  std::vector<size_t> index;
  std::vector<float> start;
  index.reserve(n);
  start.reserve(n);
  std::vector<unsigned char> guessed(n, 0);
  for (size_t i = 0; i < n; ++i) {
    float d =
        i < disparity_guess.size() ? disparity_guess[i] : std::numeric_limits<float>::quiet_NaN();
    guessed[i] = std::isfinite(d);
    if (!guessed[i]) d = row_search(i);
    if (!std::isfinite(d)) continue;
    index.push_back(i);
    start.push_back(d);
  }
  MatchFrom(left, right, left_points, index, start, right_points, ok);
  // A guess (the motion's prediction) can be further off than KLT reaches on the levels it
  // uses: such features are tried again from the row search's disparity.
  std::vector<size_t> again;
  std::vector<float> again_start;
  for (size_t k = 0; k < index.size(); ++k) {
    const size_t i = index[k];
    if ((*ok)[i] || !guessed[i]) continue;
    const float d = row_search(i);
    if (!std::isfinite(d) || std::abs(d - start[k]) < 0.5f * scale) continue;
    again.push_back(i);
    again_start.push_back(d);
  }
  MatchFrom(left, right, left_points, again, again_start, right_points, ok);
}

void StereoMatcher::MatchFrom(const ImagePyramid& left, const ImagePyramid& right,
                              const std::vector<cv::Point2f>& left_points,
                              const std::vector<size_t>& index, const std::vector<float>& start,
                              std::vector<cv::Point2f>* right_points,
                              std::vector<unsigned char>* ok) const {
  if (index.empty()) return;
  std::vector<cv::Point2f> from, to;
  from.reserve(index.size());
  to.reserve(index.size());
  for (size_t k = 0; k < index.size(); ++k) {
    const cv::Point2f& p = left_points[index[k]];
    from.push_back(p);
    to.emplace_back(p.x - start[k], p.y);
  }
  const cv::Size window(options_.window_px, options_.window_px);
  const int levels = std::min({options_.klt_levels, left.max_level, right.max_level});
  const cv::TermCriteria criteria(cv::TermCriteria::COUNT | cv::TermCriteria::EPS,
                                  options_.max_iterations, 0.01);
  std::vector<unsigned char> status;
  cv::calcOpticalFlowPyrLK(left.levels, right.levels, from, to, status, cv::noArray(), window,
                           levels, criteria, cv::OPTFLOW_USE_INITIAL_FLOW, 1e-4);
  // The forward match's own checks first, so only the matches that pass them are tracked back.
  std::vector<size_t> passed;
  passed.reserve(index.size());
  for (size_t k = 0; k < index.size(); ++k) {
    if (!status[k]) continue;
    const cv::Point2f& r = to[k];
    const cv::Point2f& l = from[k];
    const double disparity = l.x - r.x;
    if (!(disparity >= options_.min_disparity_px && disparity <= options_.max_disparity_px))
      continue;
    if (!(std::abs(r.y - l.y) <= options_.max_row_error_px)) continue;
    if (r.x < 0 || r.x > right.image.cols - 1) continue;
    passed.push_back(k);
  }
  std::vector<unsigned char> back_status;
  std::vector<cv::Point2f> back_from, back;
  if (options_.max_left_right_px > 0 && !passed.empty()) {
    back_from.reserve(passed.size());
    back.reserve(passed.size());
    for (size_t k : passed) {
      back_from.push_back(to[k]);
      back.push_back(from[k]);
    }
    cv::calcOpticalFlowPyrLK(right.levels, left.levels, back_from, back, back_status, cv::noArray(),
                             window, 0, criteria, cv::OPTFLOW_USE_INITIAL_FLOW, 1e-4);
  }
  const double max_lr2 = options_.max_left_right_px * options_.max_left_right_px;
  for (size_t j = 0; j < passed.size(); ++j) {
    const size_t k = passed[j];
    const cv::Point2f& l = from[k];
    if (!back.empty()) {
      if (!back_status[j]) continue;
      const cv::Point2f d = back[j] - l;
      if (d.x * d.x + d.y * d.y > max_lr2) continue;
    }
    (*right_points)[index[k]] = cv::Point2f(to[k].x, l.y);
    (*ok)[index[k]] = 1;
  }
}

}  // namespace sightline
