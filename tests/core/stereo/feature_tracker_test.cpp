#include "core/stereo/feature_tracker.h"

#include <gtest/gtest.h>

#include <set>

#include "stereo_test_util.h"

namespace sightline {
namespace {

TEST(FeatureTracker, FollowsAShiftedTexturedImage) {
  const cv::Mat first = testing::TexturedImage(cv::Size(640, 480), 1);
  const cv::Mat second = testing::Shifted(first, 3.5, -2.25);
  FeatureTracker tracker;
  const std::vector<cv::Point2f> corners = tracker.Detect(BuildImagePyramid(first, 15, 3), {});
  ASSERT_GT(corners.size(), 500u);
  const ImagePyramid a = BuildImagePyramid(first, 15, 3), b = BuildImagePyramid(second, 15, 3);
  std::vector<cv::Point2f> tracked;
  std::vector<unsigned char> ok;
  tracker.Track(a, b, corners, {}, &tracked, &ok);
  int good = 0, accurate = 0;
  for (size_t i = 0; i < corners.size(); ++i) {
    if (!ok[i]) continue;
    ++good;
    const cv::Point2f d = tracked[i] - corners[i];
    accurate += std::abs(d.x - 3.5f) < 0.1f && std::abs(d.y + 2.25f) < 0.1f;
  }
  EXPECT_GT(good, 0.9 * corners.size());
  EXPECT_GT(accurate, 0.9 * good);
}

TEST(FeatureTracker, BucketingSpreadsFeaturesAndRespectsExisting) {
  const cv::Mat image = testing::TexturedImage(cv::Size(640, 480), 2);
  FeatureTrackerOptions options;
  options.max_features = 300;
  options.bucket_size_px = 80;  // 8 x 6 buckets, at most 7 each.
  FeatureTracker tracker(options);
  const std::vector<cv::Point2f> corners = tracker.Detect(BuildImagePyramid(image, 15, 3), {});
  ASSERT_LE(corners.size(), 300u);
  std::set<int> buckets;
  for (const cv::Point2f& p : corners)
    buckets.insert(static_cast<int>(p.y) / 80 * 8 + static_cast<int>(p.x) / 80);
  EXPECT_GE(buckets.size(), 40u);  // A bucket may lack texture.
  // With 250 features given, at most 50 new ones, none on top of the given ones.
  std::vector<cv::Point2f> existing(corners.begin(),
                                    corners.begin() + std::min<size_t>(250, corners.size()));
  const std::vector<cv::Point2f> more = tracker.Detect(BuildImagePyramid(image, 15, 3), existing);
  EXPECT_LE(more.size() + existing.size(), 300u);
  for (const cv::Point2f& p : more) {
    for (const cv::Point2f& q : existing) ASSERT_GT(cv::norm(p - q), options.min_distance_px - 2);
  }
}

TEST(FeatureTracker, FindsNothingOnABlackImage) {
  FeatureTracker tracker;
  EXPECT_TRUE(
      tracker.Detect(BuildImagePyramid(cv::Mat::zeros(480, 640, CV_8UC1), 15, 3), {}).empty());
}

}  // namespace
}  // namespace sightline
