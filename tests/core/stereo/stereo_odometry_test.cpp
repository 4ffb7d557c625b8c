// The orchestrator on bad input: black frames, a lens cap, identical left and right images, a
// missing image, a wrong baseline sign. Each gives a clear status, the gate holds the pose and
// nothing crashes. Then the same on a real sequence with a frame removed.
#include "core/stereo/stereo_odometry.h"

#include <gtest/gtest.h>

#include "core/io/dataset.h"
#include "core/options/option_set.h"
#include "stereo_test_util.h"
#include "tests/support/test_data.h"

namespace sightline {
namespace {

StereoRig TestRig(double baseline_sign = 1) {
  StereoRig rig;
  rig.left.width = rig.right.width = 640;
  rig.left.height = rig.right.height = 480;
  rig.left.fx = rig.left.fy = rig.right.fx = rig.right.fy = 500;
  rig.left.cx = rig.right.cx = 320;
  rig.left.cy = rig.right.cy = 240;
  rig.right_from_left.translation() = Eigen::Vector3d(-0.12 * baseline_sign, 0, 0);
  rig.rectified = true;
  return rig;
}

StereoFrame MakeFrame(int index, cv::Mat left, cv::Mat right) {
  StereoFrame f;
  f.stamp.sequence_id = index;
  f.stamp.sensor_time_s = 0.1 * index;
  f.left = std::move(left);
  f.right = std::move(right);
  return f;
}

// Runs frames and checks every result: no error, finite pose at identity, gated with a status
// that contains `status_part`.
void ExpectHeld(const std::vector<StereoFrame>& frames, const std::string& status_part) {
  StereoOdometry vo;
  ASSERT_TRUE(vo.Configure(TestRig()).ok());
  for (size_t i = 0; i < frames.size(); ++i) {
    auto r = vo.Process(frames[i]);
    ASSERT_TRUE(r.ok()) << r.status().ToString();
    EXPECT_TRUE((*r)->world_from_camera.isApprox(Eigen::Isometry3d::Identity())) << "frame " << i;
    if (i > 0) {
      EXPECT_TRUE((*r)->stats.gated) << "frame " << i;
      EXPECT_NE((*r)->stats.status.find(status_part), std::string::npos) << (*r)->stats.status;
      EXPECT_NE((*r)->stats.status.find("pose held"), std::string::npos) << (*r)->stats.status;
    }
  }
}

TEST(StereoOdometry, BlackFramesHoldThePose) {
  std::vector<StereoFrame> frames;
  for (int i = 0; i < 4; ++i) {
    frames.push_back(
        MakeFrame(i, cv::Mat::zeros(480, 640, CV_8UC1), cv::Mat::zeros(480, 640, CV_8UC1)));
  }
  ExpectHeld(frames, "no stereo matches");
}

TEST(StereoOdometry, LensCapHoldsThePose) {
  // A lens cap: dark, slightly noisy, no structure.
  std::vector<StereoFrame> frames;
  for (int i = 0; i < 4; ++i) {
    cv::Mat l(480, 640, CV_8UC1), r(480, 640, CV_8UC1);
    cv::randn(l, 12, 1);
    cv::randn(r, 12, 1);
    frames.push_back(MakeFrame(i, l, r));
  }
  StereoOdometry vo;
  ASSERT_TRUE(vo.Configure(TestRig()).ok());
  for (const StereoFrame& f : frames) {
    auto r = vo.Process(f);
    ASSERT_TRUE(r.ok());
    EXPECT_LT((*r)->world_from_camera.translation().norm(), 1e-9);
    if (f.stamp.sequence_id > 0) EXPECT_TRUE((*r)->stats.gated);
  }
}

TEST(StereoOdometry, IdenticalLeftAndRightHoldThePose) {
  std::vector<StereoFrame> frames;
  for (int i = 0; i < 4; ++i) {
    const cv::Mat image =
        testing::Shifted(testing::TexturedImage(cv::Size(640, 480), 9), -2.0 * i, 0);
    frames.push_back(MakeFrame(i, image, image.clone()));
  }
  ExpectHeld(frames, "no stereo matches");
}

TEST(StereoOdometry, MissingImageIsABadInputNotACrash) {
  std::vector<StereoFrame> frames;
  frames.push_back(MakeFrame(0, cv::Mat(), cv::Mat()));
  frames.push_back(MakeFrame(1, cv::Mat::zeros(480, 640, CV_8UC1), cv::Mat()));
  ExpectHeld(frames, "empty");
}

TEST(StereoOdometry, WrongBaselineSignIsRefusedAtConfigure) {
  StereoOdometry vo;
  const Status s = vo.Configure(TestRig(-1));
  ASSERT_FALSE(s.ok());
  EXPECT_NE(s.message().find("wrong baseline sign"), std::string::npos) << s.message();
  EXPECT_FALSE(vo.Process(MakeFrame(0, cv::Mat(), cv::Mat())).ok());
}

TEST(StereoOdometry, InvalidOptionsNameTheKey) {
  StereoOdometryOptions options;
  options.ransac.inlier_threshold_px = -1;
  StereoOdometry vo(options);
  const Status s = vo.Configure(TestRig());
  EXPECT_NE(s.message().find("stereo.ransac.inlier_threshold_px"), std::string::npos);
}

TEST(StereoOdometry, DescribeCoversEveryStage) {
  OptionSet set;
  ASSERT_TRUE(set.Declare(StereoOdometryOptions::Describe()).ok());
  for (const char* key :
       {"stereo.tracking.max_features", "stereo.matching.max_left_right_px",
        "stereo.ransac.rigidity_tolerance_m", "stereo.ransac.max_iterations",
        "stereo.refine.huber_px", "stereo.gate.max_speed_mps", "stereo.rectify.alpha"}) {
    EXPECT_TRUE(set.Has(key)) << key;
  }
}

// Real frames with bad ones spliced in: a missing frame, a black frame, a dropped frame.
TEST(StereoOdometry, RecoversAfterBadFramesOnRealData) {
  SIGHTLINE_REQUIRE_DATA(path, "kitti_clip1");
  auto source = OpenDataset(path, SourceKind::kStereo);
  ASSERT_TRUE(source.ok()) << source.status().ToString();
  StereoOdometry vo;
  ASSERT_TRUE(vo.Configure(*(*source)->info().stereo).ok());
  const Trajectory& gt = *(*source)->ground_truth();
  Eigen::Isometry3d last = Eigen::Isometry3d::Identity();
  for (int i = 0; i <= 12; ++i) {
    ASSERT_TRUE((*source)->Grab().ok());
    auto frame = (*source)->Retrieve();
    ASSERT_TRUE(frame.ok());
    StereoFrame f = std::get<StereoFrame>(*frame);
    if (i == 6) continue;            // Dropped: the next frame is tracked over two frame periods.
    if (i == 4) f.left = cv::Mat();  // Missing image.
    if (i == 8) f.left = f.right = cv::Mat::zeros(f.left.size(), CV_8UC1);  // Black.
    auto r = vo.Process(f);
    ASSERT_TRUE(r.ok()) << r.status().ToString();
    const FrameStats& s = (*r)->stats;
    if (i == 4 || i == 8) {
      EXPECT_TRUE(s.gated);
      EXPECT_FALSE(s.status.empty());
      // The fallback predicts no more than one frame's motion (~1.2 m).
      EXPECT_LT(((*r)->world_from_camera.translation() - last.translation()).norm(), 2.0);
    } else if (i > 0) {
      EXPECT_FALSE(s.gated) << "frame " << i << ": " << s.status;
      last = (*r)->world_from_camera;
    }
  }
  // After the bad frames the pose still follows the ground truth (12 frames, ~14 m).
  const Eigen::Isometry3d truth = gt.poses()[12].world_from_sensor;
  EXPECT_LT((last.translation() - truth.translation()).norm(), 0.02 * 14.4);
}

}  // namespace
}  // namespace sightline
