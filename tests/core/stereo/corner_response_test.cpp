#include "core/stereo/corner_response.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <opencv2/imgproc.hpp>
#include <vector>

#include "core/stereo/image_pyramid.h"
#include "stereo_test_util.h"

namespace sightline {
namespace {

// The response from the pyramid's Scharr derivatives stands in for cv::cornerMinEigenVal: same
// units (so stereo.tracking.min_eigenvalue keeps its meaning) and the same strong corners.
TEST(CornerResponse, MatchesOpenCvMinEigenValues) {
  const cv::Mat image = testing::TexturedImage(cv::Size(320, 240), 5);
  const ImagePyramid pyramid = BuildImagePyramid(image, 15, 2);
  const cv::Rect region(20, 30, 200, 150);
  cv::Mat ours, reference;
  MinEigenResponse(pyramid.Derivatives(0), region, 3, &ours);
  ASSERT_EQ(ours.size(), region.size());
  cv::cornerMinEigenVal(image, reference, 3, 3);
  reference = reference(region);
  // Ratio at clearly cornered pixels: Scharr and Sobel differ in smoothing, not in scale.
  std::vector<float> ratios;
  for (int y = 0; y < region.height; ++y) {
    for (int x = 0; x < region.width; ++x) {
      if (reference.at<float>(y, x) > 5e-3f) {
        ratios.push_back(ours.at<float>(y, x) / reference.at<float>(y, x));
      }
    }
  }
  ASSERT_GT(ratios.size(), 1000u);
  std::nth_element(ratios.begin(), ratios.begin() + ratios.size() / 2, ratios.end());
  const float median = ratios[ratios.size() / 2];
  EXPECT_GT(median, 0.8f);
  EXPECT_LT(median, 1.25f);
  // The strongest response of each 20 x 20 cell lies within a pixel of OpenCV's.
  int cells = 0, same = 0;
  for (int y = 0; y + 20 <= region.height; y += 20) {
    for (int x = 0; x + 20 <= region.width; x += 20) {
      cv::Point a, b;
      double max_a = 0, max_b = 0;
      cv::minMaxLoc(ours(cv::Rect(x, y, 20, 20)), nullptr, &max_a, nullptr, &a);
      cv::minMaxLoc(reference(cv::Rect(x, y, 20, 20)), nullptr, &max_b, nullptr, &b);
      if (max_b < 5e-3) continue;
      ++cells;
      same += std::abs(a.x - b.x) <= 1 && std::abs(a.y - b.y) <= 1;
    }
  }
  ASSERT_GT(cells, 50);
  EXPECT_GT(same, 0.8 * cells);
}

// The eight-column AVX2 loops give the same values as the SSE and scalar ones, bit for bit, for
// the compiled block sizes and regions whose widths leave remainders.
TEST(CornerResponse, VectorPathsGiveIdenticalValues) {
  const cv::Mat image = testing::TexturedImage(cv::Size(331, 203), 7);
  const ImagePyramid pyramid = BuildImagePyramid(image, 15, 1);
  for (const int block : {3, 5}) {
    for (const cv::Rect& region : {cv::Rect(0, 0, 331, 203), cv::Rect(13, 9, 117, 61)}) {
      SCOPED_TRACE(::testing::Message() << "block " << block << ", region " << region);
      cv::Mat wide, narrow;
      const bool has_avx2 = SetCornerResponseAvx2(true);
      MinEigenResponse(pyramid.Derivatives(0), region, block, &wide);
      SetCornerResponseAvx2(false);
      MinEigenResponse(pyramid.Derivatives(0), region, block, &narrow);
      SetCornerResponseAvx2(true);
      if (!has_avx2) GTEST_SKIP() << "this CPU has no AVX2";
      ASSERT_EQ(wide.size(), narrow.size());
      EXPECT_EQ(cv::countNonZero(wide != narrow), 0);
      EXPECT_GT(cv::countNonZero(wide > 1e-3), 100);
    }
  }
}

TEST(CornerResponse, ZeroOnUniformImagesAndAtTheBorder) {
  const ImagePyramid flat = BuildImagePyramid(cv::Mat(120, 160, CV_8UC1, cv::Scalar(90)), 15, 1);
  cv::Mat response;
  MinEigenResponse(flat.Derivatives(0), cv::Rect(0, 0, 160, 120), 3, &response);
  EXPECT_EQ(cv::countNonZero(response), 0);
  const ImagePyramid textured =
      BuildImagePyramid(testing::TexturedImage(cv::Size(160, 120), 3), 15, 1);
  MinEigenResponse(textured.Derivatives(0), cv::Rect(0, 0, 160, 120), 5, &response);
  EXPECT_EQ(cv::countNonZero(response.row(0)), 0);
  EXPECT_EQ(cv::countNonZero(response.col(159)), 0);
  EXPECT_GT(cv::countNonZero(response), 160 * 120 / 2);
}

}  // namespace
}  // namespace sightline
