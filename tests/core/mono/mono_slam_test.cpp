// The SLAM system on bad input: a textureless wall, pure rotation during initialisation, a
// black frame and a sudden jump. Tracking must say lost and relocalise, never crash, and never
// corrupt the map. Also errors for misuse.
#include "core/mono/mono_slam.h"

#include <gtest/gtest.h>

#include <opencv2/imgproc.hpp>

#include "tests/core/mono/mono_test_util.h"
#include "tests/support/test_camera.h"

namespace sightline {
namespace {

MonoFrame Frame(int64_t id, const cv::Mat& image) {
  MonoFrame f;
  f.stamp.sequence_id = id;
  f.stamp.sensor_time_s = id / 30.0;
  f.image = image;
  return f;
}

TEST(MonoSlam, TexturelessWallNeverInitialisesAndSaysWhy) {
  MonoSlam slam;
  ASSERT_TRUE(slam.Configure(testing::VgaCamera()).ok());
  for (int i = 0; i < 10; ++i) {
    auto r = slam.Process(Frame(i, cv::Mat(480, 640, CV_8UC3, cv::Scalar(128, 128, 128))));
    ASSERT_TRUE(r.ok());
    EXPECT_FALSE((*r)->tracked);
    EXPECT_EQ((*r)->quality, TrackingQuality::kInitialising);
    EXPECT_NE((*r)->stats.status.find("too few features"), std::string::npos) << (*r)->stats.status;
  }
  EXPECT_TRUE(slam.Snapshot()->points.empty());
}

TEST(MonoSlam, PureRotationDoesNotInitialise) {
  StatusOr<testing::PanelSequence> panel = testing::RenderPanel(1);
  ASSERT_TRUE(panel.ok());
  const cv::Mat first = panel->frames[0].image;
  const Eigen::Matrix3d K = panel->camera.K();
  MonoSlam slam;
  ASSERT_TRUE(slam.Configure(panel->camera).ok());
  for (int i = 0; i < 15; ++i) {
    // The camera turns about its vertical axis by 0.4 deg per frame without moving.
    const Eigen::Matrix3d R =
        Eigen::AngleAxisd(i * 0.4 * M_PI / 180, Eigen::Vector3d::UnitY()).toRotationMatrix();
    const Eigen::Matrix3d H = K * R * K.inverse();
    cv::Mat h(3, 3, CV_64F);
    for (int r = 0; r < 3; ++r) {
      for (int c = 0; c < 3; ++c) h.at<double>(r, c) = H(r, c);
    }
    cv::Mat turned;
    cv::warpPerspective(first, turned, h, first.size(), cv::INTER_LINEAR, cv::BORDER_REPLICATE);
    auto r = slam.Process(Frame(i, turned));
    ASSERT_TRUE(r.ok());
    EXPECT_FALSE((*r)->tracked) << "frame " << i << ": " << (*r)->stats.status;
  }
  EXPECT_FALSE(slam.initialised());
}

class MonoSlamOnPanel : public ::testing::Test {
 protected:
  // Renders the first `frames` frames of the approach.
  void Render(int frames) {
    StatusOr<testing::PanelSequence> panel = testing::RenderPanel(frames);
    ASSERT_TRUE(panel.ok()) << panel.status().ToString();
    panel_ = std::move(*panel);
    ASSERT_TRUE(slam_.Configure(panel_.camera).ok());
  }
  std::shared_ptr<const MonoSlamResult> Process(const MonoFrame& frame) {
    auto r = slam_.Process(frame);
    EXPECT_TRUE(r.ok());
    return r.ok() ? *r : nullptr;
  }

  testing::PanelSequence panel_;
  MonoSlam slam_;
};

TEST_F(MonoSlamOnPanel, BlackFrameIsLostWithoutCorruptingTheMap) {
  Render(74);
  for (int i = 0; i < 70; ++i) Process(panel_.frames[i]);
  ASSERT_TRUE(slam_.initialised());
  const std::shared_ptr<const MapSnapshot> before = slam_.Snapshot();
  auto black = Process(Frame(70, cv::Mat::zeros(480, 640, CV_8UC3)));
  ASSERT_TRUE(black);
  EXPECT_EQ(black->quality, TrackingQuality::kLost);
  EXPECT_FALSE(black->tracked);
  EXPECT_EQ(slam_.Snapshot(), before);  // No keyframe, no point moved.
  EXPECT_EQ(slam_.lost_frames(), 1);
  bool tracked_again = false;
  for (int i = 71; i < 74; ++i) tracked_again = tracked_again || Process(panel_.frames[i])->tracked;
  EXPECT_TRUE(tracked_again);
}

TEST_F(MonoSlamOnPanel, TexturelessWallWhileTrackingIsLostWithoutCorruptingTheMap) {
  // The camera sees a blank wall for three frames after the map is built, then the panel again.
  Render(78);
  for (int i = 0; i < 70; ++i) Process(panel_.frames[i]);
  ASSERT_TRUE(slam_.initialised());
  const std::shared_ptr<const MapSnapshot> before = slam_.Snapshot();
  const int lost_before = slam_.lost_frames();
  for (int i = 70; i < 73; ++i) {
    auto blank = Process(Frame(i, cv::Mat(480, 640, CV_8UC3, cv::Scalar(128, 128, 128))));
    ASSERT_TRUE(blank);
    EXPECT_EQ(blank->quality, TrackingQuality::kLost);
    EXPECT_FALSE(blank->tracked);
    EXPECT_EQ(blank->stats.keypoints, 0);
    EXPECT_EQ(slam_.Snapshot(), before);  // No keyframe, no point moved or removed.
  }
  EXPECT_EQ(slam_.lost_frames(), lost_before + 3);
  // The panel again, where the camera has moved on meanwhile: relocalised or tracked again.
  std::shared_ptr<const MonoSlamResult> back;
  for (int i = 73; i < 78 && !(back && back->tracked); ++i) back = Process(panel_.frames[i]);
  ASSERT_TRUE(back);
  EXPECT_TRUE(back->tracked) << back->stats.status;
  EXPECT_GE(slam_.Snapshot()->keyframes.size(), before->keyframes.size());
}

TEST_F(MonoSlamOnPanel, SuddenJumpIsLostThenRelocalisedAtTheRightPlace) {
  Render(110);
  Eigen::Vector3d centre_at_20 = Eigen::Vector3d::Zero();
  for (int i = 0; i < 110; ++i) {
    ASSERT_FALSE(HasFatalFailure());
    auto r = Process(panel_.frames[i]);
    if (i == 20) {
      ASSERT_TRUE(r->tracked);
      centre_at_20 = r->map_from_camera.translation();
    }
  }
  const Eigen::Vector3d centre_at_109 =
      slam_.Snapshot()->keyframes.back().map_from_camera.translation();
  // Jump back to the start of the approach (about 0.5 m further from the wall).
  MonoFrame jumped = panel_.frames[20];
  jumped.stamp.sequence_id = 110;
  const std::shared_ptr<const MapSnapshot> before = slam_.Snapshot();
  auto r = Process(jumped);
  ASSERT_TRUE(r);
  EXPECT_GE(slam_.relocalisations() + slam_.lost_frames(), 1);
  EXPECT_EQ(slam_.Snapshot(), before);  // The jump itself makes no keyframe and moves no point.
  if (!r->tracked) r = Process(jumped);
  ASSERT_TRUE(r->tracked) << r->stats.status;
  const double span = (centre_at_109 - centre_at_20).norm();
  EXPECT_LT((r->map_from_camera.translation() - centre_at_20).norm(), 0.05 * span);
}

TEST_F(MonoSlamOnPanel, ResetStartsOverAndInitialisesAgain) {
  Render(70);
  for (int i = 0; i < 30; ++i) Process(panel_.frames[i]);
  ASSERT_TRUE(slam_.initialised());
  slam_.Reset();
  EXPECT_FALSE(slam_.initialised());
  EXPECT_TRUE(slam_.Snapshot()->points.empty());
  for (int i = 30; i < 70; ++i) Process(panel_.frames[i]);
  EXPECT_TRUE(slam_.initialised());
}

TEST(MonoSlam, MisuseIsAnErrorNotACrash) {
  MonoSlam unconfigured;
  EXPECT_EQ(
      unconfigured.Process(Frame(0, cv::Mat(480, 640, CV_8UC1, cv::Scalar(0)))).status().code(),
      StatusCode::kFailedPrecondition);
  MonoSlam slam;
  ASSERT_TRUE(slam.Configure(testing::VgaCamera()).ok());
  auto wrong = slam.Process(Frame(0, cv::Mat(240, 320, CV_8UC1, cv::Scalar(0))));
  EXPECT_EQ(wrong.status().code(), StatusCode::kInvalidArgument);
  EXPECT_NE(wrong.status().message().find("320x240"), std::string::npos);
  auto empty = slam.Process(Frame(1, cv::Mat()));
  ASSERT_TRUE(empty.ok());
  EXPECT_FALSE((*empty)->tracked);
  MonoSlamOptions bad;
  bad.tracking.min_inliers = 2;
  MonoSlam invalid(bad);
  Status s = invalid.Configure(testing::VgaCamera());
  EXPECT_FALSE(s.ok());
  EXPECT_NE(s.message().find("mono.tracking"), std::string::npos);
}

TEST(MonoSlam, OptionsDescribeEveryStage) {
  const auto specs = MonoSlamOptions::Describe().Specs();
  int scale = 0, init = 0;
  for (const auto& s : specs) {
    scale += s.key.rfind("mono.scale.", 0) == 0;
    init += s.key.rfind("mono.init.", 0) == 0;
  }
  EXPECT_EQ(scale, 6);
  EXPECT_GE(init, 9);
  std::string error;
  EXPECT_TRUE(MonoSlamOptions{}.IsValid(&error)) << error;
}

}  // namespace
}  // namespace sightline
