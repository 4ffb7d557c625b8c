// Stereo matching of left-image features in a rectified pair: a coarse SAD search along the
// same row of a reduced pyramid level where no disparity is known, then pyramidal KLT from left
// to right (sub-pixel), the row constraint, disparity limits and a right-to-left consistency
// check.
#pragma once

#include <opencv2/core.hpp>
#include <string>
#include <vector>

#include "core/options/option_table.h"
#include "core/stereo/image_pyramid.h"

namespace sightline {

// Matching options. Keys "stereo.matching.*".
struct StereoMatcherOptions {
  double min_disparity_px = 1.0;  // Smaller disparities (points too far to help) are rejected [px].
  double max_disparity_px = 160.0;  // Largest disparity searched and accepted [px].
  double max_row_error_px = 0.5;    // |v_right - v_left| above this rejects a match [px].
  double max_left_right_px = 0.5;   // Right-to-left KLT must return within this [px]; 0 = no check.
  int window_px = 9;                // KLT window side [px] (odd).
  int klt_levels = 0;               // KLT pyramid levels used from the disparity guess.
  int max_iterations = 10;          // KLT iterations per level.
  int coarse_level = 2;             // Pyramid level of the SAD search for unknown disparities.
  int coarse_window_px = 7;         // SAD window side at that level [px] (odd).
  double max_coarse_sad = 20;       // Mean absolute difference above this rejects a match [grey].

  bool IsValid(std::string* error) const;
  static OptionTable<StereoMatcherOptions> Describe();
};

// Finds each left feature in the right image.
//
//   StereoMatcher matcher(options);
//   matcher.Match(left, right, points, guesses, &right_points, &ok);
class StereoMatcher {
 public:
  explicit StereoMatcher(StereoMatcherOptions options = {}) : options_(options) {}
  const StereoMatcherOptions& options() const { return options_; }

  // Right-image positions of `left_points`. disparity_guess[i] is the expected disparity, or NaN
  // (or a missing entry) when unknown, which triggers the coarse row search; a feature whose
  // guess finds no consistent match is tried again from the row search. ok[i] is 0 where no
  // consistent match within the limits exists. The right point's row is set to the left one's
  // (rectified images), its column is sub-pixel.
  void Match(const ImagePyramid& left, const ImagePyramid& right,
             const std::vector<cv::Point2f>& left_points, const std::vector<float>& disparity_guess,
             std::vector<cv::Point2f>* right_points, std::vector<unsigned char>* ok) const;

 private:
  // KLT from left_points[index[k]] - (start[k], 0) and the checks; sets right_points and ok of
  // the features that pass.
  void MatchFrom(const ImagePyramid& left, const ImagePyramid& right,
                 const std::vector<cv::Point2f>& left_points, const std::vector<size_t>& index,
                 const std::vector<float>& start, std::vector<cv::Point2f>* right_points,
                 std::vector<unsigned char>* ok) const;
  // Best disparity along the row at the coarse level, NaN when no window fits or matches.
  float CoarseDisparity(const cv::Mat& left, const cv::Mat& right, cv::Point2f p, int scale) const;

  StereoMatcherOptions options_;
};

}  // namespace sightline
