#include "core/stereo/track_anchor.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>

#include "stereo_test_util.h"

namespace sightline {
namespace {

// A textured wall 4 m ahead, facing the camera, seen at frame 0 from the origin and at frame 2
// after driving straight towards it: the image grows by `scale` about the principal point.
struct Approach {
  RectifiedStereoCamera camera = testing::TestCamera();
  double depth_m = 4;
  cv::Mat anchor_image, current_image;
  Eigen::Isometry3d world_from_current = Eigen::Isometry3d::Identity();

  explicit Approach(double scale) {
    anchor_image = testing::TexturedImage(cv::Size(640, 480), 3);
    world_from_current.translation().z() = depth_m * (1 - 1 / scale);
    cv::Mat grow = (cv::Mat_<double>(2, 3) << scale, 0, camera.cx * (1 - scale), 0, scale,
                    camera.cy * (1 - scale));
    cv::warpAffine(anchor_image, current_image, grow, anchor_image.size(), cv::INTER_LINEAR,
                   cv::BORDER_REFLECT);
  }
  TrackAnchor AnchorAt(float u, float v) const {
    return {0, cv::Point2f(u, v), static_cast<float>(camera.f * camera.baseline_m / depth_m)};
  }
  cv::Point2f Truth(const TrackAnchor& a, double scale) const {
    return cv::Point2f(static_cast<float>(camera.cx + scale * (a.left.x - camera.cx)),
                       static_cast<float>(camera.cy + scale * (a.left.y - camera.cy)));
  }
};

TEST(TrackAnchors, AlignsTracksToTheirAnchorThroughAScaleChange) {
  const double scale = 1.2;
  const Approach a(scale);
  TrackAnchors anchors;
  anchors.AddFrame(0, a.anchor_image, Eigen::Isometry3d::Identity());
  // Corners, as the tracker detects them, where the grown image still covers the patch.
  std::vector<cv::Point2f> corners;
  cv::goodFeaturesToTrack(a.anchor_image(cv::Rect(160, 120, 320, 240)), corners, 40, 0.01, 10);
  ASSERT_GE(corners.size(), 30u);
  int aligned = 0, aligned_unwarped = 0;
  double worst = 0, worst_unwarped = 0;
  std::vector<double> errors;
  for (const cv::Point2f& corner : corners) {
    {
      const TrackAnchor anchor = a.AnchorAt(corner.x + 160, corner.y + 120);
      const cv::Point2f truth = a.Truth(anchor, scale);
      // Where frame-to-frame KLT might have drifted to.
      cv::Point2f position = truth + cv::Point2f(0.4f, -0.3f);
      const AnchorAlignment result =
          anchors.Align(a.camera, anchor, 2, a.current_image, a.world_from_current, &position);
      // The same without the motion (the patch not warped), for contrast.
      cv::Point2f unwarped = truth + cv::Point2f(0.4f, -0.3f);
      if (anchors.Align(a.camera, anchor, 2, a.current_image, Eigen::Isometry3d::Identity(),
                        &unwarped) == AnchorAlignment::kAligned) {
        ++aligned_unwarped;
        worst_unwarped = std::max(worst_unwarped, static_cast<double>(std::hypot(
                                                      unwarped.x - truth.x, unwarped.y - truth.y)));
      }
      if (result != AnchorAlignment::kAligned) continue;
      ++aligned;
      errors.push_back(std::hypot(position.x - truth.x, position.y - truth.y));
      worst = std::max(worst, errors.back());
    }
  }
  EXPECT_GE(aligned, static_cast<int>(corners.size()) - 2);
  std::sort(errors.begin(), errors.end());
  ASSERT_FALSE(errors.empty());
  EXPECT_LT(errors[errors.size() / 2], 0.04) << "px from the truth after aligning from 0.5 px off";
  EXPECT_LT(worst, 0.15);
  std::cout << aligned << " aligned, median " << errors[errors.size() / 2] << " px, worst "
            << worst << " px; unwarped: " << aligned_unwarped << " aligned, worst "
            << worst_unwarped << " px\n";
}

TEST(TrackAnchors, TheAnchorImageIsCopiedNotShared) {
  const Approach a(1.1);
  TrackAnchors anchors;
  cv::Mat reused = a.anchor_image.clone();
  anchors.AddFrame(0, reused, Eigen::Isometry3d::Identity());
  reused.setTo(0);  // A source reusing its buffer for the next frame.
  const TrackAnchor anchor = a.AnchorAt(300, 220);
  const cv::Point2f truth = a.Truth(anchor, 1.1);
  cv::Point2f position = truth + cv::Point2f(-0.3f, 0.3f);
  ASSERT_EQ(anchors.Align(a.camera, anchor, 2, a.current_image, a.world_from_current, &position),
            AnchorAlignment::kAligned);
  EXPECT_LT(std::hypot(position.x - truth.x, position.y - truth.y), 0.08);
}

TEST(TrackAnchors, SaysWhenATrackNeedsANewAnchor) {
  const Approach a(1.2);
  TrackAnchorOptions options;
  options.max_frames = 5;
  TrackAnchors anchors(options);
  anchors.AddFrame(0, a.anchor_image, Eigen::Isometry3d::Identity());
  const TrackAnchor anchor = a.AnchorAt(300, 220);
  const cv::Point2f start = a.Truth(anchor, 1.2) + cv::Point2f(0.2f, 0.2f);
  auto align = [&](const TrackAnchor& which, int64_t frame, const cv::Mat& image,
                   const Eigen::Isometry3d& pose) {
    cv::Point2f position = start;
    const AnchorAlignment result = anchors.Align(a.camera, which, frame, image, pose, &position);
    if (result != AnchorAlignment::kAligned) EXPECT_EQ(position, start) << "moved though refused";
    return result;
  };
  EXPECT_EQ(align(anchor, 2, a.current_image, a.world_from_current), AnchorAlignment::kAligned);
  // The anchor is the previous frame: KLT measured against it already.
  EXPECT_EQ(align(anchor, 1, a.current_image, a.world_from_current), AnchorAlignment::kUnchanged);
  EXPECT_EQ(align(TrackAnchor(), 2, a.current_image, a.world_from_current),
            AnchorAlignment::kUnchanged);
  // Older than max_frames.
  EXPECT_EQ(align(anchor, 6, a.current_image, a.world_from_current), AnchorAlignment::kRenew);
  // The camera came so close that the patch doubled (beyond max_scale_change).
  Eigen::Isometry3d closer = Eigen::Isometry3d::Identity();
  closer.translation().z() = a.depth_m / 2;
  EXPECT_EQ(align(anchor, 2, a.current_image, closer), AnchorAlignment::kRenew);
  // Predicted 0.3 m aside: the viewing direction changed by about 5 deg. Fine by default (30);
  // refused with max_view_change_deg 3.
  Eigen::Isometry3d aside = a.world_from_current;
  aside.translation().x() = 0.3;
  EXPECT_EQ(align(anchor, 2, a.current_image, aside), AnchorAlignment::kAligned);
  TrackAnchorOptions strict = options;
  strict.max_view_change_deg = 3;
  TrackAnchors strict_anchors(strict);
  strict_anchors.AddFrame(0, a.anchor_image, Eigen::Isometry3d::Identity());
  cv::Point2f untouched = start;
  EXPECT_EQ(strict_anchors.Align(a.camera, anchor, 2, a.current_image, aside, &untouched),
            AnchorAlignment::kRenew);
  EXPECT_EQ(untouched, start);
  // Something else now covers the point (occlusion).
  EXPECT_EQ(align(anchor, 2, testing::TexturedImage(cv::Size(640, 480), 99), a.world_from_current),
            AnchorAlignment::kRenew);
  // No depth, or a frame never kept.
  TrackAnchor no_depth = anchor;
  no_depth.disparity_px = 0;
  EXPECT_EQ(align(no_depth, 2, a.current_image, a.world_from_current), AnchorAlignment::kRenew);
  TrackAnchor unknown_frame = anchor;
  unknown_frame.frame = 3;  // Recent enough, but never kept.
  EXPECT_EQ(align(unknown_frame, 5, a.current_image, a.world_from_current),
            AnchorAlignment::kRenew);
  // Frames no anchor can use any more are dropped: frame 0 is gone once frame 5 is added.
  anchors.AddFrame(5, a.anchor_image, Eigen::Isometry3d::Identity());
  EXPECT_FALSE(anchors.Usable(0, 6));
  EXPECT_TRUE(anchors.Usable(5, 6));
}

TEST(TrackAnchorOptions, RejectsAbsurdValuesNamingTheKey) {
  std::string error;
  TrackAnchorOptions o;
  EXPECT_TRUE(o.IsValid(&error));
  o.patch_px = 8;
  EXPECT_FALSE(o.IsValid(&error));
  EXPECT_NE(error.find("stereo.anchor.patch_px"), std::string::npos);
  o = TrackAnchorOptions();
  o.max_scale_change = 1.5;
  EXPECT_FALSE(o.IsValid(&error));
  EXPECT_NE(error.find("stereo.anchor.max_scale_change"), std::string::npos);
  o = TrackAnchorOptions();
  o.max_frames = 0;
  EXPECT_FALSE(o.IsValid(&error));
  EXPECT_NE(error.find("stereo.anchor.max_frames"), std::string::npos);
  o = TrackAnchorOptions();
  o.max_view_change_deg = 0;
  EXPECT_FALSE(o.IsValid(&error));
  EXPECT_NE(error.find("stereo.anchor.max_view_change_deg"), std::string::npos);
}

}  // namespace
}  // namespace sightline
