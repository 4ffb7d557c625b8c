// OpenNi2Source's live-device path against Sightline's synthetic OpenNI2 driver, loaded by a
// private copy of libOpenNI2 in the build tree (see synthetic_openni2_driver/CMakeLists.txt):
// enumeration, frames with known values, mirroring, recording to .oni and playing it back, and
// devices that stall or unplug mid-stream.
#include <OniCAPI.h>
#include <dlfcn.h>
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdlib>
#include <string>
#include <thread>

#include "core/sensors/driver_registry.h"
#include "core/sensors/openni2_runtime.h"
#include "core/sensors/openni2_source.h"
#include "tests/core/sensors/synthetic_openni2_driver/synthetic_pattern.h"
#include "tests/support/test_data.h"

namespace sightline {
namespace {

namespace pattern = synthetic_openni2;
using Clock = std::chrono::steady_clock;

// Sets environment variables for one test and restores them after it.
class ScopedEnv {
 public:
  ScopedEnv(const char* name, const std::string& value) : name_(name) {
    setenv(name, value.c_str(), 1);
  }
  ~ScopedEnv() { unsetenv(name_); }

 private:
  const char* name_;
};

class OpenNi2Synthetic : public ::testing::Test {
 protected:
  void SetUp() override {
    Dl_info info{};
    ASSERT_NE(dladdr(reinterpret_cast<void*>(&oniInitialize), &info), 0);
    const std::string loaded = info.dli_fname != nullptr ? info.dli_fname : "";
    ASSERT_EQ(loaded.rfind(SIGHTLINE_OPENNI2_TEST_RUNTIME_DIR, 0), 0u)
        << "libOpenNI2 was loaded from " << loaded << ", not from the private runtime "
        << SIGHTLINE_OPENNI2_TEST_RUNTIME_DIR << " (run through ctest, or set LD_LIBRARY_PATH)";
  }

  static OpenNi2Options FastOptions() {
    OpenNi2Options options;
    options.live.grab_timeout_ms = 1000;
    options.live.stall_timeout_ms = 600;
    options.live.reconnect_interval_ms = 200;
    return options;
  }

  static RgbdFrame Grab(OpenNi2Source* source) {
    const Status grabbed = source->Grab();
    EXPECT_TRUE(grabbed.ok()) << grabbed.ToString() << " / " << source->stats().message;
    if (!grabbed.ok()) return RgbdFrame();
    return std::get<RgbdFrame>(*source->Retrieve());
  }

  // Checks every pixel against the driver's pattern for frame `index`.
  static void ExpectPattern(const RgbdFrame& frame, int index, bool mirrored = false) {
    ASSERT_EQ(frame.depth_m.size(), cv::Size(pattern::kWidth, pattern::kHeight));
    ASSERT_EQ(frame.color.size(), cv::Size(pattern::kWidth, pattern::kHeight));
    int wrong = 0;
    for (int y = 0; y < pattern::kHeight; ++y) {
      for (int x = 0; x < pattern::kWidth; ++x) {
        const int sx = mirrored ? pattern::kWidth - 1 - x : x;
        const uint16_t mm = pattern::DepthMm(sx, y, index);
        const float d = frame.depth_m.at<float>(y, x);
        if (mm == 0 ? !std::isnan(d) : std::abs(d - mm / 1000.0f) > 1e-6f) ++wrong;
        uint8_t rgb[3];
        pattern::Rgb(sx, y, index, rgb);
        if (frame.color.at<cv::Vec3b>(y, x) != cv::Vec3b(rgb[2], rgb[1], rgb[0])) ++wrong;
      }
    }
    EXPECT_EQ(wrong, 0) << "frame index " << index;
  }
};

TEST_F(OpenNi2Synthetic, EnumeratesTheSyntheticDevice) {
  bool found = false;
  for (const DeviceInfo& d : OpenNi2Source::Enumerate()) {
    if (d.uri != std::string("openni2://") + pattern::kUri) continue;
    found = true;
    EXPECT_EQ(d.driver, "openni2");
    EXPECT_EQ(d.name, "Sightline Synthetic RGB-D");
  }
  EXPECT_TRUE(found);
  EXPECT_TRUE(FindDriver(BuiltinDrivers(), "openni2")->available().ok());
  EXPECT_EQ(FindDriver(BuiltinDrivers(), "openni2")->enumerate(OptionSet()).size(), 1u);
}

TEST_F(OpenNi2Synthetic, LiveFramesCarryTheKnownPattern) {
  OpenNi2Source source(pattern::kUri, FastOptions());
  const Status opened = source.Open();
  ASSERT_TRUE(opened.ok()) << opened.ToString();
  const SourceInfo& info = source.info();
  EXPECT_EQ(info.format, "OpenNI2 device");
  EXPECT_TRUE(info.live);
  EXPECT_FALSE(info.seekable);
  EXPECT_EQ(info.frame_count, -1);
  EXPECT_EQ(info.width, pattern::kWidth);
  EXPECT_EQ(info.rate_hz, pattern::kFps);
  ASSERT_TRUE(info.camera.has_value());
  EXPECT_NEAR(info.camera->fx, pattern::kWidth / (2 * std::tan(pattern::kHorizontalFovRad / 2)),
              1e-3);
  bool registered = false;
  for (const std::string& note : info.notes) {
    registered = registered || note == "depth registered to colour by the device";
  }
  EXPECT_TRUE(registered);

  int64_t last_sequence = -1, last_index = -1;
  for (int i = 0; i < 10; ++i) {
    const RgbdFrame frame = Grab(&source);
    const int64_t index = source.last_grabbed().device_frame_id;
    EXPECT_GT(frame.stamp.sequence_id, last_sequence);
    EXPECT_GT(index, last_index);
    EXPECT_NEAR(frame.stamp.sensor_time_s, 1.0 + index * 0.033333, 1e-6) << "device timestamp";
    ExpectPattern(frame, static_cast<int>(index));
    last_sequence = frame.stamp.sequence_id;
    last_index = index;
  }
  const SensorStats stats = source.stats();
  EXPECT_EQ(stats.state, SensorState::kStreaming);
  EXPECT_EQ(stats.unpaired_frames, 0u);
  EXPECT_EQ(source.Seek(0).code(), StatusCode::kFailedPrecondition);
}

TEST_F(OpenNi2Synthetic, MirroringOption) {
  OpenNi2Options options = FastOptions();
  options.mirror = true;
  OpenNi2Source source(pattern::kUri, options);
  ASSERT_TRUE(source.Open().ok());
  const RgbdFrame frame = Grab(&source);
  ExpectPattern(frame, static_cast<int>(source.last_grabbed().device_frame_id), true);
}

TEST_F(OpenNi2Synthetic, UnsupportedModeListsTheModes) {
  OpenNi2Options options = FastOptions();
  options.width = 640;
  options.height = 480;
  OpenNi2Source source(pattern::kUri, options);
  const Status opened = source.Open();
  ASSERT_EQ(opened.code(), StatusCode::kInvalidArgument) << opened.ToString();
  EXPECT_NE(opened.message().find("no depth mode 640x480@30"), std::string::npos)
      << opened.message();
  EXPECT_NE(opened.message().find("160x120@30 DEPTH_1_MM"), std::string::npos);
}

TEST_F(OpenNi2Synthetic, RecordsToOniAndPlaysBackEveryFrame) {
  const std::string dir = ::sightline::testing::TempDir("oni_record");
  ASSERT_FALSE(dir.empty());
  const std::string oni = dir + "/synthetic.oni";
  {
    OpenNi2Source live(pattern::kUri, FastOptions());
    ASSERT_TRUE(live.Open().ok());
    Grab(&live);
    const Status started = live.StartRecording(oni);
    ASSERT_TRUE(started.ok()) << started.ToString();
    EXPECT_TRUE(live.recording());
    EXPECT_EQ(live.StartRecording(oni).code(), StatusCode::kFailedPrecondition);
    for (int i = 0; i < 20; ++i) Grab(&live);
    live.StopRecording();
    EXPECT_FALSE(live.recording());
  }
  OpenNi2Source playback(oni, OpenNi2Options());
  const Status opened = playback.Open();
  ASSERT_TRUE(opened.ok()) << opened.ToString();
  const int64_t count = playback.info().frame_count;
  EXPECT_GE(count, 15) << "about 20 frames at 30 Hz were recorded";
  int frames = 0;
  int last_index = -1;
  while (true) {
    const Status grabbed = playback.Grab();
    if (grabbed.code() == StatusCode::kOutOfRange) break;
    ASSERT_TRUE(grabbed.ok()) << grabbed.ToString();
    const RgbdFrame frame = std::get<RgbdFrame>(*playback.Retrieve());
    // The player renumbers frames from 1; the device's index survives in the blue channel.
    const int index = frame.color.at<cv::Vec3b>(0, 0)[0];
    EXPECT_EQ(frame.stamp.sequence_id, frames);
    EXPECT_EQ(playback.last_grabbed().device_frame_id, frames + 1);
    if (last_index >= 0) EXPECT_EQ(index, last_index + 1) << "no recorded frame is skipped";
    last_index = index;
    ExpectPattern(frame, index);
    ++frames;
    ASSERT_LE(frames, count);
  }
  EXPECT_EQ(frames, count) << "every recorded frame plays back";
  ASSERT_TRUE(playback.Seek(count / 2).ok());
  EXPECT_EQ(Grab(&playback).stamp.sequence_id, count / 2);
}

TEST_F(OpenNi2Synthetic, StalledDeviceIsReportedAndReopened) {
  ScopedEnv stop_after(pattern::kStopAfterEnv, "15");
  ScopedEnv mode(pattern::kStopModeEnv, "stall");
  OpenNi2Options options = FastOptions();
  options.live.grab_timeout_ms = 300;         // Shorter than the pause before reopening, so
  options.live.reconnect_interval_ms = 1000;  // that a Grab() sees the disconnected state.
  OpenNi2Source source(pattern::kUri, options);
  ASSERT_TRUE(source.Open().ok());
  Grab(&source);
  const Clock::time_point deadline = Clock::now() + std::chrono::seconds(20);
  Status status;
  while (Clock::now() < deadline) {
    status = source.Grab();
    if (!status.ok() && status.message().find("disconnected") != std::string::npos) break;
  }
  ASSERT_EQ(status.code(), StatusCode::kUnavailable) << status.ToString();
  EXPECT_NE(status.message().find("OpenNI2 device '" + std::string(pattern::kUri) +
                                  "' disconnected: no frame for 600 ms"),
            std::string::npos)
      << status.message();
  // Reopening gives a fresh device that streams again (15 more frames).
  while (Clock::now() < deadline && !(status = source.Grab()).ok()) {
  }
  ASSERT_TRUE(status.ok()) << status.ToString();
  EXPECT_GE(source.stats().reconnects, 1u);
  EXPECT_GE(source.stats().disconnects, 1u);
}

TEST_F(OpenNi2Synthetic, UnpluggedDeviceIsReportedAndReconnectsWhenBack) {
  ScopedEnv stop_after(pattern::kStopAfterEnv, "10");
  ScopedEnv mode(pattern::kStopModeEnv, "unplug");
  ScopedEnv absent(pattern::kAbsentMsEnv, "1500");
  OpenNi2Options options = FastOptions();
  options.live.stall_timeout_ms = 0;  // Only the driver's unplug event may report the loss.
  options.live.grab_timeout_ms = 300;
  OpenNi2Source source(pattern::kUri, options);
  ASSERT_TRUE(source.Open().ok());
  const Clock::time_point deadline = Clock::now() + std::chrono::seconds(20);
  Status status;
  bool saw_failed_reconnect = false;
  while (Clock::now() < deadline) {
    status = source.Grab();
    if (!status.ok() && status.message().find("unplugged") != std::string::npos) break;
  }
  ASSERT_EQ(status.code(), StatusCode::kUnavailable) << status.ToString();
  EXPECT_NE(status.message().find("the driver reported it unplugged"), std::string::npos)
      << status.message();
  EXPECT_EQ(source.stats().state, SensorState::kDisconnected);
  while (Clock::now() < deadline && !(status = source.Grab()).ok()) {
    saw_failed_reconnect =
        saw_failed_reconnect || status.message().find("could not be opened") != std::string::npos;
  }
  ASSERT_TRUE(status.ok()) << status.ToString();
  EXPECT_TRUE(saw_failed_reconnect) << "while absent, reconnect attempts fail and say why";
  EXPECT_EQ(source.stats().state, SensorState::kStreaming);
  EXPECT_GE(source.stats().reconnects, 1u);
}

TEST_F(OpenNi2Synthetic, FirstDeviceAndRegistryUri) {
  auto first = std::make_unique<OpenNi2Source>("", FastOptions());
  ASSERT_TRUE(first->Open().ok());
  EXPECT_EQ(first->info().path, std::string("openni2://") + pattern::kUri);
  // OpenNI2 shares one device between handles and crashes on a second frame-sync request:
  // a second source for the same device is refused instead.
  StatusOr<std::unique_ptr<Source>> second = OpenSource(std::string("openni2://") + pattern::kUri);
  ASSERT_FALSE(second.ok());
  EXPECT_EQ(second.status().code(), StatusCode::kUnavailable);
  EXPECT_NE(second.status().message().find("already open in this process"), std::string::npos)
      << second.status().message();
  first.reset();
  StatusOr<std::unique_ptr<Source>> by_uri = OpenSource(std::string("openni2://") + pattern::kUri);
  ASSERT_TRUE(by_uri.ok()) << by_uri.status().ToString();
  EXPECT_TRUE((*by_uri)->Grab().ok());
  EXPECT_EQ(OpenNi2Runtime::UseCount(), 1);
  OpenNi2Source missing("sightline-synthetic://7", FastOptions());
  const Status opened = missing.Open();
  EXPECT_EQ(opened.code(), StatusCode::kUnavailable);
  EXPECT_NE(opened.message().find("sightline-synthetic://7"), std::string::npos);
}

}  // namespace
}  // namespace sightline
