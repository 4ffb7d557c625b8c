// OpenNi2Source playing the recorded ../shared/data/oni_livingroom/test.oni (12 depth + 12
// colour frames) through the installed OpenNI2 and its OniFile driver.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "core/sensors/driver_registry.h"
#include "core/sensors/openni2_runtime.h"
#include "core/sensors/openni2_source.h"
#include "tests/support/test_data.h"

namespace sightline {
namespace {

constexpr char kOni[] = "oni_livingroom/test.oni";

RgbdFrame GrabRgbd(Source* source) {
  const Status grabbed = source->Grab();
  EXPECT_TRUE(grabbed.ok()) << grabbed.ToString();
  if (!grabbed.ok()) return RgbdFrame();
  return std::get<RgbdFrame>(*source->Retrieve());
}

bool SameImage(const cv::Mat& a, const cv::Mat& b) {
  return a.size() == b.size() && a.type() == b.type() && cv::norm(a, b, cv::NORM_INF) == 0;
}

TEST(OpenNi2File, PlaysAllTwelveDepthAndColourFrames) {
  SIGHTLINE_REQUIRE_DATA(path, kOni);
  OpenNi2Source source(path, OpenNi2Options());
  const Status opened = source.Open();
  ASSERT_TRUE(opened.ok()) << opened.ToString();
  const SourceInfo& info = source.info();
  EXPECT_EQ(info.format, "OpenNI2 recording (.oni)");
  EXPECT_EQ(info.kind, SourceKind::kRgbd);
  EXPECT_FALSE(info.live);
  EXPECT_TRUE(info.seekable);
  EXPECT_EQ(info.frame_count, 12);
  EXPECT_EQ(info.width, 640);
  EXPECT_EQ(info.height, 480);
  EXPECT_EQ(info.rate_hz, 30);
  ASSERT_TRUE(info.rgbd.has_value());
  EXPECT_EQ(info.rgbd->depth_scale, 1000);
  ASSERT_TRUE(info.camera.has_value()) << "intrinsics from the depth stream's field of view";
  EXPECT_NEAR(info.camera->fx, 575.8, 1.0);

  double last_time = -1;
  int frames = 0;
  while (true) {
    const Status grabbed = source.Grab();
    if (grabbed.code() == StatusCode::kOutOfRange) break;
    ASSERT_TRUE(grabbed.ok()) << grabbed.ToString();
    const RgbdFrame frame = std::get<RgbdFrame>(*source.Retrieve());
    EXPECT_EQ(frame.stamp.sequence_id, frames);
    EXPECT_GT(frame.stamp.sensor_time_s, last_time);
    last_time = frame.stamp.sensor_time_s;
    ASSERT_EQ(frame.color.type(), CV_8UC3);
    ASSERT_EQ(frame.color.size(), cv::Size(640, 480));
    ASSERT_EQ(frame.depth_m.type(), CV_32FC1);
    ASSERT_EQ(frame.depth_m.size(), cv::Size(640, 480));
    int valid = 0, invalid = 0;
    for (int r = 0; r < frame.depth_m.rows; r += 4) {
      for (int c = 0; c < frame.depth_m.cols; c += 4) {
        const float d = frame.depth_m.at<float>(r, c);
        if (std::isnan(d)) {
          ++invalid;
        } else {
          ++valid;
          EXPECT_GT(d, 0.2f);
          EXPECT_LT(d, 12.0f);
        }
      }
    }
    EXPECT_GT(valid, invalid) << "a living room is mostly in range";
    EXPECT_GT(cv::mean(frame.color)[0] + cv::mean(frame.color)[2], 10) << "colour is not black";
    ++frames;
    ASSERT_LE(frames, 12);
  }
  EXPECT_EQ(frames, 12);
  EXPECT_EQ(source.Position(), 12);
  EXPECT_EQ(source.stats().frames_received, 12u);
  EXPECT_EQ(source.stats().unpaired_frames, 0u);
  EXPECT_EQ(source.Grab().code(), StatusCode::kOutOfRange) << "stays at the end";
}

TEST(OpenNi2File, SeeksToAnyFrame) {
  SIGHTLINE_REQUIRE_DATA(path, kOni);
  OpenNi2Source source(path, OpenNi2Options());
  ASSERT_TRUE(source.Open().ok());
  std::vector<RgbdFrame> all;
  for (int i = 0; i < 12; ++i) all.push_back(GrabRgbd(&source));

  ASSERT_TRUE(source.Seek(5).ok());
  EXPECT_EQ(source.Position(), 5);
  EXPECT_FALSE(source.Retrieve().ok()) << "no frame until the next Grab()";
  RgbdFrame fifth = GrabRgbd(&source);
  EXPECT_EQ(fifth.stamp.sequence_id, 5);
  EXPECT_EQ(source.Position(), 6);
  EXPECT_TRUE(SameImage(fifth.color, all[5].color));
  EXPECT_DOUBLE_EQ(fifth.stamp.sensor_time_s, all[5].stamp.sensor_time_s);

  ASSERT_TRUE(source.Seek(0).ok());
  EXPECT_TRUE(SameImage(GrabRgbd(&source).color, all[0].color));
  ASSERT_TRUE(source.Seek(12).ok());
  EXPECT_EQ(source.Grab().code(), StatusCode::kOutOfRange);
  EXPECT_EQ(source.Seek(13).code(), StatusCode::kOutOfRange);
  EXPECT_EQ(source.Seek(-1).code(), StatusCode::kOutOfRange);
  ASSERT_TRUE(source.Seek(11).ok());
  EXPECT_TRUE(SameImage(GrabRgbd(&source).color, all[11].color));
}

TEST(OpenNi2File, LoopsWhenAsked) {
  SIGHTLINE_REQUIRE_DATA(path, kOni);
  OpenNi2Options options;
  options.loop = true;
  OpenNi2Source source(path, options);
  ASSERT_TRUE(source.Open().ok());
  cv::Mat first_color;
  for (int i = 0; i < 30; ++i) {
    const RgbdFrame frame = GrabRgbd(&source);
    ASSERT_FALSE(frame.color.empty()) << "frame " << i;
    EXPECT_EQ(frame.stamp.sequence_id, i % 12);
    if (i == 0) first_color = frame.color.clone();
    if (i == 12 || i == 24) EXPECT_TRUE(SameImage(frame.color, first_color)) << i;
  }
  EXPECT_EQ(source.stats().unpaired_frames, 0u);
}

TEST(OpenNi2File, MissingFileIsNotFoundAndNamed) {
  OpenNi2Source source("/nonexistent/living.oni", OpenNi2Options());
  const Status opened = source.Open();
  EXPECT_EQ(opened.code(), StatusCode::kNotFound);
  EXPECT_NE(opened.message().find("/nonexistent/living.oni"), std::string::npos);
}

TEST(OpenNi2File, ThroughOpenSourceAndSharedRuntime) {
  SIGHTLINE_REQUIRE_DATA(path, kOni);
  EXPECT_EQ(OpenNi2Runtime::UseCount(), 0);
  {
    StatusOr<std::unique_ptr<Source>> a = OpenSource(path);
    ASSERT_TRUE(a.ok()) << a.status().ToString();
    StatusOr<std::unique_ptr<Source>> b = OpenSource("openni2://" + path);
    ASSERT_TRUE(b.ok()) << b.status().ToString();
    EXPECT_EQ(OpenNi2Runtime::UseCount(), 2) << "one OpenNI2 initialisation, two users";
    EXPECT_EQ(GrabRgbd(a->get()).stamp.sequence_id, 0);
    EXPECT_EQ(GrabRgbd(b->get()).stamp.sequence_id, 0);
    EXPECT_EQ(GrabRgbd(a->get()).stamp.sequence_id, 1);
  }
  EXPECT_EQ(OpenNi2Runtime::UseCount(), 0) << "OpenNI2 shut down with the last source";
  // A second session in the same process initialises OpenNI2 again.
  OpenNi2Source again(path, OpenNi2Options());
  ASSERT_TRUE(again.Open().ok());
  EXPECT_EQ(GrabRgbd(&again).color.cols, 640);
}

TEST(OpenNi2File, DriverIsAvailable) {
  EXPECT_TRUE(OpenNi2Source::Available().ok());
  EXPECT_TRUE(OpenNi2Source::IsRecordingPath("a/b/ROOM.Oni"));
  EXPECT_FALSE(OpenNi2Source::IsRecordingPath("1d27/0601@1/5"));
}

}  // namespace
}  // namespace sightline
