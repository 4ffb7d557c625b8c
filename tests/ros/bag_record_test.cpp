// The recorder's "bag" format: frames recorded into DIR/recording.bag read back through
// BagSource as the same frames, camera and (shifted) times.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <limits>

#include "core/record/recorder.h"
#include "core/ros/bag_source.h"
#include "tests/support/test_data.h"

namespace sightline {
namespace {

PinholeCamera SmallCamera() {
  PinholeCamera camera;
  camera.width = 32;
  camera.height = 24;
  camera.fx = camera.fy = 30;
  camera.cx = 15.5;
  camera.cy = 11.5;
  return camera;
}

RgbdFrame MakeRgbd(int i) {
  RgbdFrame f;
  f.stamp.sequence_id = i;
  f.stamp.sensor_time_s = 0.1 * i;  // Starts at 0: the bag shifts it.
  f.color = cv::Mat(24, 32, CV_8UC3, cv::Scalar(10 * i, 20, 30));
  f.depth_m = cv::Mat(24, 32, CV_32FC1, cv::Scalar(1.0f + 0.25f * i));
  f.depth_m.at<float>(3, 4) = std::numeric_limits<float>::quiet_NaN();
  return f;
}

TEST(BagRecording, RgbdFramesComeBackFromTheRecordedBag) {
  const std::string dir = testing::TempDir("bag_record") + "/rec";
  SourceInfo info;
  info.path = "test";
  info.kind = SourceKind::kRgbd;
  info.rgbd = RgbdCalibration{SmallCamera(), 1000, 10};
  RecorderOptions options;
  options.format = "bag";
  options.block_when_full = true;
  auto recorder = Recorder::Start(dir, info, options);
  ASSERT_TRUE(recorder.ok()) << recorder.status().ToString();
  for (int i = 0; i < 5; ++i) ASSERT_TRUE((*recorder)->Push(MakeRgbd(i)));
  ASSERT_TRUE((*recorder)->Stop().ok()) << (*recorder)->status().ToString();
  EXPECT_EQ((*recorder)->stats().frames_written, 5u);
  EXPECT_EQ((*recorder)->folder(), dir + "/recording.bag");
  ASSERT_EQ((*recorder)->notes().size(), 1u);
  EXPECT_NE((*recorder)->notes()[0].find("+ 1 s"), std::string::npos);

  BagSource bag(dir + "/recording.bag");
  ASSERT_TRUE(bag.Open().ok());
  ASSERT_EQ(bag.info().kind, SourceKind::kRgbd);
  ASSERT_EQ(bag.info().frame_count, 5);
  ASSERT_TRUE(bag.info().rgbd.has_value());
  EXPECT_DOUBLE_EQ(bag.info().rgbd->color.fx, 30);
  EXPECT_DOUBLE_EQ(bag.info().rgbd->color.cx, 15.5);
  for (int i = 0; i < 5; ++i) {
    ASSERT_TRUE(bag.Grab().ok());
    StatusOr<Frame> frame = bag.Retrieve();
    ASSERT_TRUE(frame.ok()) << frame.status().ToString();
    const RgbdFrame& got = std::get<RgbdFrame>(*frame);
    const RgbdFrame want = MakeRgbd(i);
    EXPECT_NEAR(got.stamp.sensor_time_s, want.stamp.sensor_time_s + 1, 1e-6);
    EXPECT_EQ(cv::norm(got.color, want.color, cv::NORM_INF), 0) << i;
    EXPECT_TRUE(std::isnan(got.depth_m.at<float>(3, 4)));
    EXPECT_FLOAT_EQ(got.depth_m.at<float>(10, 10), want.depth_m.at<float>(10, 10));
  }
}

TEST(BagRecording, AnExistingBagIsKeptUnlessOverwriteAndBadFormatsAreNamed) {
  const std::string dir = testing::TempDir("bag_record_twice") + "/rec";
  SourceInfo info;
  info.path = "test";
  info.kind = SourceKind::kMono;
  info.camera = SmallCamera();
  RecorderOptions options;
  options.format = "bag";
  auto first = Recorder::Start(dir, info, options);
  ASSERT_TRUE(first.ok());
  ASSERT_TRUE((*first)->Stop().ok());
  auto second = Recorder::Start(dir, info, options);
  ASSERT_FALSE(second.ok());
  EXPECT_NE(second.status().message().find("recording.bag"), std::string::npos)
      << second.status().ToString();
  options.overwrite = true;
  EXPECT_TRUE(Recorder::Start(dir, info, options).ok());
  options.format = "mcap";
  auto bad = Recorder::Start(dir, info, options);
  ASSERT_FALSE(bad.ok());
  EXPECT_NE(bad.status().message().find("record.format"), std::string::npos);
  // Without calibration a bag's camera_info would be empty: refused, naming the source.
  options.format = "bag";
  info.camera.reset();
  auto uncalibrated = Recorder::Start(testing::TempDir("bag_record_nocam") + "/rec", info, options);
  ASSERT_FALSE(uncalibrated.ok());
  EXPECT_NE(uncalibrated.status().message().find("without calibration"), std::string::npos);
}

}  // namespace
}  // namespace sightline
