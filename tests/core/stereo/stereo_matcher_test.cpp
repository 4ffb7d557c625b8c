#include "core/stereo/stereo_matcher.h"

#include <gtest/gtest.h>

#include "core/stereo/feature_tracker.h"
#include "stereo_test_util.h"

namespace sightline {
namespace {

// Matches the corners of a textured left image in a right image shifted by `disparity`, with
// guesses `guess_error` off when with_guess.
void MatchShift(double disparity, bool with_guess, int* matched, int* accurate, int* total,
                double guess_error = 3) {
  const cv::Mat left = testing::TexturedImage(cv::Size(640, 480), 3);
  const cv::Mat right = testing::Shifted(left, -disparity, 0);
  const ImagePyramid l = BuildImagePyramid(left, 15, 3), r = BuildImagePyramid(right, 15, 3);
  const std::vector<cv::Point2f> corners = FeatureTracker().Detect(l, {});
  std::vector<float> guesses;
  if (with_guess) guesses.assign(corners.size(), static_cast<float>(disparity + guess_error));
  std::vector<cv::Point2f> right_points;
  std::vector<unsigned char> ok;
  StereoMatcher().Match(l, r, corners, guesses, &right_points, &ok);
  *matched = *accurate = 0;
  *total = static_cast<int>(corners.size());
  for (size_t i = 0; i < corners.size(); ++i) {
    if (!ok[i]) continue;
    ++*matched;
    EXPECT_EQ(right_points[i].y, corners[i].y);  // Row constraint.
    *accurate += std::abs(corners[i].x - right_points[i].x - disparity) < 0.05;
  }
}

TEST(StereoMatcher, FindsAKnownDisparityWithoutAGuess) {
  int matched, accurate, total;
  MatchShift(37.3, false, &matched, &accurate, &total);
  EXPECT_GT(matched, 0.8 * total);  // Features near the left border have no match.
  EXPECT_GT(accurate, 0.9 * matched);
}

TEST(StereoMatcher, RefinesFromAGuess) {
  int matched, accurate, total;
  MatchShift(12.6, true, &matched, &accurate, &total);
  EXPECT_GT(matched, 0.85 * total);
  EXPECT_GT(accurate, 0.9 * matched);
}

TEST(StereoMatcher, FallsBackToTheRowSearchWhenTheGuessIsFarOff) {
  // A guess 14 px off (a poor motion prediction: a dropped frame, a sudden stop) is beyond
  // what KLT reaches on full resolution; the features are matched from the row search instead.
  for (const double error : {14.0, -14.0}) {
    SCOPED_TRACE(error);
    int matched, accurate, total;
    MatchShift(37.3, true, &matched, &accurate, &total, error);
    EXPECT_GT(matched, 0.8 * total);
    EXPECT_GT(accurate, 0.9 * matched);
  }
}

TEST(StereoMatcher, RejectsZeroDisparity) {
  // Identical left and right images: every point at infinity, nothing to triangulate.
  int matched, accurate, total;
  MatchShift(0.0, false, &matched, &accurate, &total);
  EXPECT_EQ(matched, 0);
}

}  // namespace
}  // namespace sightline
