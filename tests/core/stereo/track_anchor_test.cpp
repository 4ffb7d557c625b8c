#include "core/stereo/track_anchor.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>
#include <random>

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
        worst_unwarped =
            std::max(worst_unwarped,
                     static_cast<double>(std::hypot(unwarped.x - truth.x, unwarped.y - truth.y)));
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
  std::cout << aligned << " aligned, median " << errors[errors.size() / 2] << " px, worst " << worst
            << " px; unwarped: " << aligned_unwarped << " aligned, worst " << worst_unwarped
            << " px\n";
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

// The floor 1.2 m below a camera that drives 0.6 m forward: the patch of a floor point is
// squeezed vertically much more than a patch facing the camera would be. With the floor's normal
// fitted from the neighbouring tracks the alignment lands on the truth; assuming the patch faces
// the camera it does not.
TEST(TrackAnchors, AWarpOnTheFittedSurfaceFollowsASlantedFloor) {
  const RectifiedStereoCamera camera = testing::TestCamera();
  const cv::Mat anchor_image = testing::TexturedImage(cv::Size(640, 480), 5);
  const Eigen::Vector3d normal(0, -1, 0);  // Floor y = 1.2 (optical frame: y down).
  const double height = 1.2;
  Eigen::Isometry3d world_from_current = Eigen::Isometry3d::Identity();
  world_from_current.translation().z() = 0.6;
  const Eigen::Isometry3d current_from_anchor = world_from_current.inverse();
  // Pixels of the current image from those of the anchor image: the floor's homography.
  Eigen::Matrix3d K;
  K << camera.f, 0, camera.cx, 0, camera.f, camera.cy, 0, 0, 1;
  const Eigen::Matrix3d H = K *
                            (current_from_anchor.linear() +
                             current_from_anchor.translation() * normal.transpose() / -height) *
                            K.inverse();
  cv::Mat Hcv(3, 3, CV_64F);
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) Hcv.at<double>(r, c) = H(r, c);
  }
  cv::Mat current_image;
  cv::warpPerspective(anchor_image, current_image, Hcv, anchor_image.size(), cv::INTER_LINEAR,
                      cv::BORDER_REFLECT);
  auto floor_point = [&](const cv::Point2f& p) {
    const Eigen::Vector3d ray((p.x - camera.cx) / camera.f, (p.y - camera.cy) / camera.f, 1);
    return Eigen::Vector3d(ray * (height / ray.y()));
  };
  // Corners on the floor's image (below the horizon, within 3..12 m).
  std::vector<cv::Point2f> corners;
  cv::goodFeaturesToTrack(anchor_image(cv::Rect(120, 300, 400, 150)), corners, 60, 0.01, 8);
  ASSERT_GE(corners.size(), 30u);
  std::vector<Eigen::Vector3d> points;
  std::vector<cv::Point2f> pixels;
  std::vector<size_t> all;
  for (cv::Point2f& c : corners) {
    c += cv::Point2f(120, 300);
    pixels.push_back(c);
    points.push_back(floor_point(c));
    all.push_back(all.size());
  }
  TrackAnchorOptions options;
  options.normal_radius_px = 80;
  const std::vector<Eigen::Vector3f> normals = SurfaceNormals(points, pixels, all, options);
  TrackAnchors anchors(options);
  anchors.AddFrame(0, anchor_image, Eigen::Isometry3d::Identity());
  std::vector<double> fitted_errors, facing_errors;
  int fitted = 0;
  for (size_t i = 0; i < corners.size(); ++i) {
    const Eigen::Vector3d y = current_from_anchor * points[i];
    const cv::Point2f truth(static_cast<float>(camera.f * y.x() / y.z() + camera.cx),
                            static_cast<float>(camera.f * y.y() / y.z() + camera.cy));
    if (truth.x < 20 || truth.y < 20 || truth.x > 620 || truth.y > 460) continue;
    const float disparity = static_cast<float>(camera.f * camera.baseline_m / points[i].z());
    if (normals[i].squaredNorm() > 0) {
      ++fitted;
      EXPECT_GT(std::abs(normals[i].cast<double>().dot(normal)), 0.99) << "track " << i;
    }
    for (bool use_normal : {true, false}) {
      if (use_normal && normals[i].squaredNorm() == 0) continue;
      TrackAnchor anchor{0, corners[i], disparity,
                         use_normal ? normals[i] : Eigen::Vector3f::Zero()};
      cv::Point2f position = truth + cv::Point2f(0.3f, 0.3f);
      if (anchors.Align(camera, anchor, 2, current_image, world_from_current, &position) !=
          AnchorAlignment::kAligned) {
        continue;
      }
      (use_normal ? fitted_errors : facing_errors)
          .push_back(std::hypot(position.x - truth.x, position.y - truth.y));
    }
  }
  EXPECT_GE(fitted, static_cast<int>(corners.size()) / 2);
  ASSERT_GE(fitted_errors.size(), 20u);
  std::sort(fitted_errors.begin(), fitted_errors.end());
  std::sort(facing_errors.begin(), facing_errors.end());
  const double fitted_median = fitted_errors[fitted_errors.size() / 2];
  const double facing_median = facing_errors.empty() ? 99 : facing_errors[facing_errors.size() / 2];
  std::cout << fitted_errors.size() << " aligned on the fitted floor, median " << fitted_median
            << " px; " << facing_errors.size() << " assuming the patch faces the camera, median "
            << facing_median << " px\n";
  EXPECT_LT(fitted_median, 0.08);
  EXPECT_LT(2 * fitted_median, facing_median);
}

TEST(TrackAnchors, NoSurfaceIsFittedToTooFewOrScatteredNeighbours) {
  std::vector<Eigen::Vector3d> points;
  std::vector<cv::Point2f> pixels;
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> spread(-0.5, 0.5);
  for (int i = 0; i < 12; ++i) {  // A cloud 4 m ahead, no plane.
    points.emplace_back(spread(rng), spread(rng), 4 + spread(rng));
    pixels.emplace_back(300 + 3 * i, 200 + 2 * i);
  }
  points.emplace_back(0, 0, 4);
  pixels.emplace_back(900, 900);  // Alone.
  TrackAnchorOptions options;
  const std::vector<Eigen::Vector3f> normals = SurfaceNormals(points, pixels, {0, 12}, options);
  EXPECT_EQ(normals[0], Eigen::Vector3f::Zero());
  EXPECT_EQ(normals[1], Eigen::Vector3f::Zero());
  options.normal_radius_px = 0;  // Off.
  EXPECT_EQ(SurfaceNormals(points, pixels, {0}, options)[0], Eigen::Vector3f::Zero());
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
  o = TrackAnchorOptions();
  o.normal_min_points = 2;
  EXPECT_FALSE(o.IsValid(&error));
  EXPECT_NE(error.find("stereo.anchor.normal_min_points"), std::string::npos);
}

}  // namespace
}  // namespace sightline
