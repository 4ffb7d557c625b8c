// replay://: a recording played as a live camera through LiveSource's capture thread and
// drop-oldest queue, with the real TUM reader underneath.
#include "core/sensors/replay_source.h"

#include <gtest/gtest.h>

#include <chrono>
#include <thread>

#include "core/io/dataset.h"
#include "core/sensors/driver_registry.h"
#include "tests/support/test_data.h"

namespace sightline {
namespace {

ReplayOptions Options(double fps, bool loop, int capacity) {
  ReplayOptions options;
  options.fps = fps;
  options.loop = loop;
  options.live.latest_only = false;
  options.live.queue_capacity = capacity;
  return options;
}

TEST(ReplaySource, ParsesTheUriQueryAndNamesBadKeys) {
  auto parsed = ReplaySource::ParseUri("/data/rec?fps=15&loop=1", ReplayOptions());
  ASSERT_TRUE(parsed.ok()) << parsed.status().ToString();
  EXPECT_EQ(parsed->first, "/data/rec");
  EXPECT_DOUBLE_EQ(parsed->second.fps, 15);
  EXPECT_TRUE(parsed->second.loop);
  EXPECT_EQ(ReplaySource::ParseUri("/data/rec", ReplayOptions())->first, "/data/rec");
  const auto unknown = ReplaySource::ParseUri("/data/rec?speed=2", ReplayOptions());
  EXPECT_NE(unknown.status().message().find("unknown key 'speed'"), std::string::npos);
  const auto bad = ReplaySource::ParseUri("/data/rec?fps=fast", ReplayOptions());
  EXPECT_NE(bad.status().message().find("bad value 'fast'"), std::string::npos);
  EXPECT_FALSE(ReplaySource::ParseUri("?fps=1", ReplayOptions()).ok());
  EXPECT_FALSE(ReplaySource::ParseUri("/x?fps=-1", ReplayOptions()).ok());
}

TEST(ReplaySource, PlaysEveryFrameAsALiveCameraThenEnds) {
  SIGHTLINE_REQUIRE_DATA(tum, "tum_fr1_desk");
  StatusOr<std::unique_ptr<Source>> original = OpenDataset(tum);
  ASSERT_TRUE(original.ok());
  ReplaySource camera(tum, Options(100, false, 16));
  ASSERT_TRUE(camera.Open().ok());
  EXPECT_TRUE(camera.info().live);
  EXPECT_EQ(camera.info().kind, SourceKind::kRgbd);
  EXPECT_EQ(camera.info().frame_count, -1);
  for (int i = 0; i < 9; ++i) {
    ASSERT_TRUE(camera.Grab().ok()) << i;
    ASSERT_TRUE((*original)->Grab().ok());
    const auto live = std::get<RgbdFrame>(*camera.Retrieve());
    const auto recorded = std::get<RgbdFrame>(*(*original)->Retrieve());
    EXPECT_EQ(live.stamp.sequence_id, i);
    EXPECT_DOUBLE_EQ(live.stamp.sensor_time_s, recorded.stamp.sensor_time_s);
    EXPECT_GT(live.stamp.host_time_s, 0);
    EXPECT_EQ(cv::norm(live.color, recorded.color, cv::NORM_INF), 0);
  }
  const Status end = camera.Grab();
  EXPECT_EQ(end.code(), StatusCode::kOutOfRange) << end.ToString();
  EXPECT_NE(end.message().find("after 9 frames"), std::string::npos) << end.message();
  const SensorStats stats = camera.stats();
  EXPECT_EQ(stats.frames_received, 9u);
  EXPECT_EQ(stats.frames_grabbed, 9u);
  EXPECT_EQ(stats.frames_dropped, 0u);
}

TEST(ReplaySource, LoopsWithTimesThatKeepIncreasing) {
  SIGHTLINE_REQUIRE_DATA(tum, "tum_fr1_desk");
  ReplaySource camera(tum, Options(200, true, 32));
  ASSERT_TRUE(camera.Open().ok());
  std::vector<RgbdFrame> frames;
  for (int i = 0; i < 20; ++i) {
    ASSERT_TRUE(camera.Grab().ok()) << i;
    frames.push_back(std::get<RgbdFrame>(*camera.Retrieve()));
    if (i > 0) EXPECT_GT(frames[i].stamp.sensor_time_s, frames[i - 1].stamp.sensor_time_s) << i;
  }
  for (int i = 0; i < 9; ++i) {
    EXPECT_EQ(cv::norm(frames[i].color, frames[i + 9].color, cv::NORM_INF), 0) << i;
  }
}

TEST(ReplaySource, ASlowConsumerLosesTheOldestFramesAndTheyAreCounted) {
  SIGHTLINE_REQUIRE_DATA(tum, "tum_fr1_desk");
  ReplaySource camera(tum, Options(500, false, 2));
  ASSERT_TRUE(camera.Open().ok());
  // Grab nothing until the whole recording has been captured and queued (bounded wait): a frame
  // is counted as received before it is queued, so wait for the queue's seventh drop too.
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(30);
  while ((camera.stats().frames_received < 9 || camera.stats().frames_dropped < 7) &&
         std::chrono::steady_clock::now() < deadline) {
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  ASSERT_EQ(camera.stats().frames_received, 9u);
  ASSERT_EQ(camera.stats().frames_dropped, 7u);
  ASSERT_TRUE(camera.Grab().ok());
  EXPECT_EQ(std::get<RgbdFrame>(*camera.Retrieve()).stamp.sequence_id, 7) << "the newest two";
  ASSERT_TRUE(camera.Grab().ok());
  EXPECT_EQ(std::get<RgbdFrame>(*camera.Retrieve()).stamp.sequence_id, 8);
  EXPECT_EQ(camera.Grab().code(), StatusCode::kOutOfRange);
  EXPECT_EQ(camera.stats().frames_dropped, 7u);
}

TEST(ReplaySource, OpensThroughTheRegistryAndReportsAMissingRecording) {
  SIGHTLINE_REQUIRE_DATA(tum, "tum_fr1_desk");
  StatusOr<std::unique_ptr<Source>> source = OpenSource("replay://" + tum + "?fps=50");
  ASSERT_TRUE(source.ok()) << source.status().ToString();
  EXPECT_TRUE((*source)->info().live);
  EXPECT_EQ((*source)->info().format, "replayed TUM RGB-D");
  EXPECT_TRUE(IsSensorUri("replay:///x"));
  const auto missing = OpenSource("replay:///nonexistent/recording");
  EXPECT_FALSE(missing.ok());
  EXPECT_NE(missing.status().message().find("/nonexistent/recording"), std::string::npos);
}

}  // namespace
}  // namespace sightline
