// The recorder with real components: simulated recordings replayed through the live path
// (ReplaySource: capture thread, drop-oldest queue), the project's own readers for the round
// trip, and the kernel's file size limit for a full disk.
#include "core/record/recorder.h"

#include <gtest/gtest.h>
#include <sys/resource.h>

#include <csignal>
#include <fstream>
#include <random>
#include <sstream>

#include "core/common/text_file.h"
#include "core/io/dataset.h"
#include "core/record/record_session.h"
#include "core/sensors/replay_source.h"
#include "core/sim/simulate.h"
#include "tests/core/record/record_test_util.h"
#include "tests/support/test_data.h"

namespace sightline {
namespace {

using ::sightline::testing::ExpectRecordedFramesMatch;
using ::sightline::testing::ReadAllFrames;

// A simulated corridor (RGB-D 320x240, stereo 320x240), made once for all tests.
const std::string& Corridor() {
  static const std::string dir = [] {
    const std::string path = testing::TempDir("record_corridor") + "/corridor";
    sim::SimulationOptions options = sim::SimulationOptions::ForScene("corridor");
    options.frames = 300;
    options.sensors = "rgbd";
    options.rgbd.resolution = "320x240";
    const auto done = sim::Simulate(options, path);
    EXPECT_TRUE(done.ok()) << done.status().ToString();
    return path;
  }();
  return dir;
}

ReplayOptions FastReplay(double fps) {
  ReplayOptions options;
  options.fps = fps;
  options.live.latest_only = false;  // Recording: every frame, in order.
  options.live.queue_capacity = 512;
  return options;
}

TEST(Recorder, Records300SimulatedFramesThroughTheLivePathAndReadsThemBackExactly) {
  ReplaySource camera(Corridor() + "/rgbd", FastReplay(200));
  ASSERT_TRUE(camera.Open().ok());
  EXPECT_TRUE(camera.info().live);
  RecorderOptions options;
  options.queue_capacity = 512;  // Larger than the recording: nothing can be dropped.
  const std::string out = testing::TempDir("record_live") + "/rec";
  int64_t acknowledged = 0;
  RecordCallbacks callbacks;
  callbacks.written = [&](const WrittenFrame& w) {
    EXPECT_EQ(w.index, acknowledged);
    ++acknowledged;
  };
  StatusOr<RecordSummary> summary = RecordSource(&camera, out, options, {}, callbacks);
  ASSERT_TRUE(summary.ok()) << summary.status().ToString();
  EXPECT_TRUE(summary->write_status.ok()) << summary->write_status.ToString();
  EXPECT_EQ(summary->end_reason, "end of recording");
  EXPECT_EQ(summary->format, "TUM RGB-D");
  EXPECT_EQ(summary->recorder.frames_offered, 300u);
  EXPECT_EQ(summary->recorder.frames_written, 300u);
  EXPECT_EQ(summary->TotalDropped(), 0u);
  ASSERT_TRUE(summary->sensor.has_value());
  EXPECT_EQ(summary->sensor->frames_received, 300u);
  EXPECT_EQ(acknowledged, 300);
  EXPECT_GT(summary->recorder.bytes_written, 300 * 1000);

  const std::vector<Frame> original = ReadAllFrames(Corridor() + "/rgbd");
  const std::vector<Frame> recorded = ReadAllFrames(out);  // The recording folder: finds rgbd/.
  ASSERT_EQ(recorded.size(), 300u);
  EXPECT_EQ(ExpectRecordedFramesMatch(original, recorded), 300);
  // The calibration travels with the frames.
  StatusOr<std::unique_ptr<Source>> reopened = OpenDataset(out);
  ASSERT_TRUE(reopened.ok());
  StatusOr<std::unique_ptr<Source>> source = OpenDataset(Corridor() + "/rgbd");
  ASSERT_TRUE((*reopened)->info().rgbd && (*source)->info().rgbd);
  EXPECT_DOUBLE_EQ((*reopened)->info().rgbd->color.fx, (*source)->info().rgbd->color.fx);
  EXPECT_DOUBLE_EQ((*reopened)->info().rgbd->color.cy, (*source)->info().rgbd->color.cy);
}

TEST(Recorder, StereoAndMonoRoundTripWithTheirCalibration) {
  const std::string sim_dir = testing::TempDir("record_stereo_mono") + "/sim";
  sim::SimulationOptions options = sim::SimulationOptions::ForScene("corridor");
  options.frames = 12;
  options.sensors = "stereo";
  options.stereo.width = 320;
  options.stereo.height = 200;
  ASSERT_TRUE(sim::Simulate(options, sim_dir).ok());
  sim::SimulationOptions panel = sim::SimulationOptions::ForScene("panel");
  panel.frames = 12;
  panel.mono.width = 160;
  panel.mono.height = 120;
  ASSERT_TRUE(sim::Simulate(panel, sim_dir + "_panel").ok());

  for (const std::string& sensor : {sim_dir + "/stereo", sim_dir + "_panel/mono"}) {
    SCOPED_TRACE(sensor);
    ReplaySource camera(sensor, FastReplay(100));
    ASSERT_TRUE(camera.Open().ok());
    const std::string out = testing::TempDir("record_stereo_mono") + "/rec";
    StatusOr<RecordSummary> summary = RecordSource(&camera, out, RecorderOptions(), {});
    ASSERT_TRUE(summary.ok()) << summary.status().ToString();
    EXPECT_EQ(summary->recorder.frames_written, 12u);
    const std::vector<Frame> recorded = ReadAllFrames(out);
    ASSERT_EQ(recorded.size(), 12u);
    // EuRoC stores nanoseconds: times agree to a nanosecond.
    EXPECT_EQ(ExpectRecordedFramesMatch(ReadAllFrames(sensor), recorded, 2e-9), 12);
    StatusOr<std::unique_ptr<Source>> a = OpenDataset(sensor), b = OpenDataset(out);
    ASSERT_TRUE(a.ok() && b.ok());
    ASSERT_TRUE((*a)->info().camera && (*b)->info().camera);
    EXPECT_NEAR((*a)->info().camera->fx, (*b)->info().camera->fx, 1e-9);
    if ((*a)->info().stereo) {
      ASSERT_TRUE((*b)->info().stereo);
      EXPECT_EQ((*b)->info().format, "EuRoC MAV");
      EXPECT_NEAR((*a)->info().stereo->BaselineM(), (*b)->info().stereo->BaselineM(), 1e-9);
    }
  }
}

MonoFrame NoiseFrame(int index, std::mt19937* random) {
  MonoFrame frame;
  frame.stamp.sequence_id = index;
  frame.stamp.sensor_time_s = 0.05 * (index + 1);
  frame.image.create(24, 32, CV_8UC3);
  std::uniform_int_distribution<int> byte(0, 255);
  for (auto it = frame.image.begin<cv::Vec3b>(); it != frame.image.end<cv::Vec3b>(); ++it) {
    *it = cv::Vec3b(byte(*random), byte(*random), byte(*random));
  }
  return frame;
}

SourceInfo MonoInfo() {
  SourceInfo info;
  info.kind = SourceKind::kMono;
  info.width = 32;
  info.height = 24;
  info.live = true;
  return info;
}

TEST(Recorder, EveryFrameIsWrittenOrCountedAsDroppedWhenTheQueueOverflows) {
  RecorderOptions options;
  options.queue_capacity = 2;  // Far less than the burst below: the oldest frames drop.
  const std::string out = testing::TempDir("record_overflow") + "/rec";
  StatusOr<std::unique_ptr<Recorder>> recorder = Recorder::Start(out, MonoInfo(), options);
  ASSERT_TRUE(recorder.ok()) << recorder.status().ToString();
  std::mt19937 random(7);
  std::vector<Frame> pushed;
  for (int i = 0; i < 200; ++i) {
    pushed.push_back(NoiseFrame(i, &random));
    (*recorder)->Push(pushed.back());
  }
  ASSERT_TRUE((*recorder)->Stop().ok());
  const RecorderStats stats = (*recorder)->stats();
  EXPECT_EQ(stats.frames_offered, 200u);
  EXPECT_EQ(stats.frames_written + stats.frames_dropped, 200u);
  EXPECT_GT(stats.frames_written, 0u);
  const std::vector<Frame> recorded = ReadAllFrames(out);
  EXPECT_EQ(recorded.size(), stats.frames_written);
  EXPECT_EQ(ExpectRecordedFramesMatch(pushed, recorded), static_cast<int>(recorded.size()));
}

// Records `count` noise frames into `out`; the recorder's status.
Status RecordNoise(const std::string& out, int count, bool overwrite) {
  RecorderOptions options;
  options.block_when_full = true;
  options.overwrite = overwrite;
  StatusOr<std::unique_ptr<Recorder>> recorder = Recorder::Start(out, MonoInfo(), options);
  if (!recorder.ok()) return recorder.status();
  std::mt19937 random(5);
  for (int i = 0; i < count; ++i) (*recorder)->Push(NoiseFrame(i, &random));
  return (*recorder)->Stop();
}

TEST(Recorder, AFolderThatHoldsARecordingIsRefusedUnlessOverwriting) {
  const std::string out = testing::TempDir("record_again") + "/rec";
  ASSERT_TRUE(RecordNoise(out, 5, false).ok());
  const std::string times_before = testing::ReadAll(out + "/mono/times.txt");
  ASSERT_EQ(ReadAllFrames(out).size(), 5u);

  // Again into the same folder: refused before anything is written.
  const Status again = RecordNoise(out, 2, false);
  EXPECT_EQ(again.code(), StatusCode::kFailedPrecondition);
  EXPECT_NE(again.message().find("cannot record into " + out), std::string::npos)
      << again.message();
  EXPECT_NE(again.message().find("record.overwrite"), std::string::npos) << again.message();
  EXPECT_EQ(testing::ReadAll(out + "/mono/times.txt"), times_before);
  EXPECT_EQ(ReadAllFrames(out).size(), 5u);

  // Any file counts, not only a recording; a file given as the folder is refused too.
  const std::string other = testing::TempDir("record_other");
  std::ofstream(other + "/notes.txt") << "mine\n";
  EXPECT_EQ(RecordNoise(other, 1, false).code(), StatusCode::kFailedPrecondition);
  EXPECT_EQ(RecordNoise(other + "/notes.txt", 1, false).code(), StatusCode::kFailedPrecondition);
  EXPECT_EQ(testing::ReadAll(other + "/notes.txt"), "mine\n");

  // Overwriting replaces the sensor folder as a whole: no image of the longer recording stays.
  std::ofstream(out + "/keep.txt") << "kept\n";
  ASSERT_TRUE(RecordNoise(out, 2, true).ok());
  EXPECT_EQ(ReadAllFrames(out).size(), 2u);
  EXPECT_FALSE(FileExists(out + "/mono/000004.png"));
  EXPECT_EQ(testing::ReadAll(out + "/keep.txt"), "kept\n");
}

TEST(Recorder, FramesWithoutIncreasingTimesAreDroppedAndCounted) {
  const std::string out = testing::TempDir("record_order") + "/rec";
  RecorderOptions options;
  options.block_when_full = true;
  StatusOr<std::unique_ptr<Recorder>> recorder = Recorder::Start(out, MonoInfo(), options);
  ASSERT_TRUE(recorder.ok());
  std::mt19937 random(3);
  EXPECT_TRUE((*recorder)->Push(NoiseFrame(1, &random)));
  EXPECT_FALSE((*recorder)->Push(NoiseFrame(0, &random)));
  EXPECT_TRUE((*recorder)->Push(NoiseFrame(2, &random)));
  ASSERT_TRUE((*recorder)->Stop().ok());
  EXPECT_EQ((*recorder)->stats().frames_written, 2u);
  EXPECT_EQ((*recorder)->stats().frames_out_of_order, 1u);
  EXPECT_EQ((*recorder)->stats().frames_dropped, 1u);
}

// A file size limit (RLIMIT_FSIZE, SIGXFSZ ignored) makes the kernel refuse writes with EFBIG,
// like a full disk refuses them with ENOSPC. Images here are ~2.4 kB, times.txt reaches the
// 4 kB limit after ~200 frames.
TEST(Recorder, AFullDiskStopsWithAClearErrorAndLeavesAReadablePartialRecording) {
  const std::string out = testing::TempDir("record_full") + "/rec";
  RecorderOptions options;
  options.block_when_full = true;
  StatusOr<std::unique_ptr<Recorder>> recorder = Recorder::Start(out, MonoInfo(), options);
  ASSERT_TRUE(recorder.ok());
  std::mt19937 random(11);
  std::vector<Frame> pushed;
  Status stopped;
  {
    rlimit saved{};
    ASSERT_EQ(getrlimit(RLIMIT_FSIZE, &saved), 0);
    auto* previous = std::signal(SIGXFSZ, SIG_IGN);
    rlimit limit = saved;
    limit.rlim_cur = 4096;
    ASSERT_EQ(setrlimit(RLIMIT_FSIZE, &limit), 0);
    for (int i = 0; i < 300; ++i) {
      pushed.push_back(NoiseFrame(i, &random));
      (*recorder)->Push(pushed.back());
    }
    stopped = (*recorder)->Stop();
    setrlimit(RLIMIT_FSIZE, &saved);
    std::signal(SIGXFSZ, previous);
  }
  ASSERT_FALSE(stopped.ok());
  EXPECT_EQ(stopped.code(), StatusCode::kUnavailable);
  EXPECT_NE(stopped.message().find(out + "/mono/times.txt"), std::string::npos)
      << stopped.message();
  EXPECT_NE(stopped.message().find("file size limit"), std::string::npos) << stopped.message();
  const RecorderStats stats = (*recorder)->stats();
  EXPECT_TRUE(stats.failed);
  EXPECT_GT(stats.frames_written, 100u);
  EXPECT_LT(stats.frames_written, 300u);
  EXPECT_EQ(stats.frames_written + stats.frames_dropped, 300u);
  const std::vector<Frame> recorded = ReadAllFrames(out);
  EXPECT_EQ(recorded.size(), stats.frames_written);
  EXPECT_EQ(ExpectRecordedFramesMatch(pushed, recorded), static_cast<int>(stats.frames_written));
}

TEST(Recorder, RefusesPointCloudsAndInvalidOptions) {
  SourceInfo info;
  info.kind = SourceKind::kCloud;
  const auto cloud = Recorder::Start(testing::TempDir("record_bad"), info, RecorderOptions());
  EXPECT_EQ(cloud.status().code(), StatusCode::kInvalidArgument);
  RecorderOptions bad;
  bad.png_compression = 12;
  const auto invalid = Recorder::Start(testing::TempDir("record_bad"), MonoInfo(), bad);
  EXPECT_NE(invalid.status().message().find("record.png_compression"), std::string::npos);
}

}  // namespace
}  // namespace sightline
