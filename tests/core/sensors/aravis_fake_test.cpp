// The Aravis sources against Aravis' in-process simulated camera ("Fake" interface, device
// Fake_1): real Aravis streams and buffers, no network.
#include <arv.h>
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <thread>

#include "core/sensors/aravis_source.h"
#include "core/sensors/driver_registry.h"

namespace sightline {
namespace {

// Keeps this test off the host's network and USB: only the in-process Fake interface is
// searched, so opening an absent camera sends no GigE discovery broadcast.
class FakeOnlyEnvironment : public ::testing::Environment {
 public:
  void SetUp() override {
    arv_disable_interface("GigEVision");
    arv_disable_interface("USB3Vision");
  }
};
::testing::Environment* const kEnvironment =
    ::testing::AddGlobalTestEnvironment(new FakeOnlyEnvironment);

AravisOptions FakeOptions() {
  AravisOptions options;
  options.fake_interface = true;
  options.live.grab_timeout_ms = 3000;
  return options;
}

MonoFrame GrabMono(AravisSource* source) {
  const Status grabbed = source->Grab();
  EXPECT_TRUE(grabbed.ok()) << grabbed.ToString();
  if (!grabbed.ok()) return MonoFrame();
  StatusOr<Frame> frame = source->Retrieve();
  EXPECT_TRUE(frame.ok());
  return std::get<MonoFrame>(*frame);
}

TEST(AravisFakeCamera, StreamsFramesWithIncreasingIds) {
  AravisSource source("Fake_1", FakeOptions());
  ASSERT_TRUE(source.Open().ok());
  const SourceInfo& info = source.info();
  EXPECT_EQ(info.kind, SourceKind::kMono);
  EXPECT_TRUE(info.live);
  EXPECT_FALSE(info.seekable);
  EXPECT_EQ(info.width, 512);
  EXPECT_EQ(info.height, 512);
  EXPECT_EQ(source.settings().pixel_format, "Mono8");
  int64_t last_sequence = -1, last_device_id = -1;
  double last_time = 0;
  for (int i = 0; i < 5; ++i) {
    MonoFrame frame = GrabMono(&source);
    ASSERT_EQ(frame.image.cols, 512);
    ASSERT_EQ(frame.image.rows, 512);
    EXPECT_EQ(frame.image.type(), CV_8UC1);
    EXPECT_GT(frame.stamp.sequence_id, last_sequence);
    EXPECT_GT(source.last_grabbed().device_frame_id, last_device_id);
    EXPECT_GT(frame.stamp.sensor_time_s, last_time);
    EXPECT_GT(frame.stamp.host_time_s, 0);
    last_sequence = frame.stamp.sequence_id;
    last_device_id = source.last_grabbed().device_frame_id;
    last_time = frame.stamp.sensor_time_s;
  }
  EXPECT_EQ(source.Position(), 5);
  const SensorStats stats = source.stats();
  EXPECT_EQ(stats.state, SensorState::kStreaming);
  EXPECT_GE(stats.frames_received, 5u);
  EXPECT_EQ(stats.frames_grabbed, 5u);
  EXPECT_EQ(stats.incomplete_frames, 0u);
  EXPECT_GT(stats.receive_rate_hz, 10);
  EXPECT_EQ(source.Seek(0).code(), StatusCode::kFailedPrecondition);
  source.Close();
  EXPECT_EQ(source.stats().state, SensorState::kClosed);
}

TEST(AravisFakeCamera, PixelFormatsConvertToMonoOrColour) {
  struct Case {
    const char* format;
    bool debayer;
    int type;
  } cases[] = {{"Mono16", true, CV_8UC1},
               {"BayerRG8", true, CV_8UC3},
               {"BayerRG8", false, CV_8UC1},
               {"RGB8", true, CV_8UC3}};
  for (const Case& c : cases) {
    AravisOptions options = FakeOptions();
    options.pixel_format = c.format;
    options.debayer = c.debayer;
    AravisSource source("Fake_1", options);
    const Status opened = source.Open();
    ASSERT_TRUE(opened.ok()) << c.format << ": " << opened.ToString();
    EXPECT_EQ(source.settings().pixel_format, c.format);
    MonoFrame frame = GrabMono(&source);
    EXPECT_EQ(frame.image.type(), c.type) << c.format << " debayer=" << c.debayer;
    EXPECT_EQ(frame.image.cols, 512);
  }
}

TEST(AravisFakeCamera, ExposureGainRateAndRegionAreApplied) {
  AravisOptions options = FakeOptions();
  options.exposure_us = 5000;
  options.gain_db = 3;
  options.frame_rate_hz = 50;
  options.width = 320;
  options.height = 240;
  AravisSource source("Fake_1", options);
  const Status opened = source.Open();
  ASSERT_TRUE(opened.ok()) << opened.ToString();
  const AravisCameraSettings settings = source.settings();
  EXPECT_DOUBLE_EQ(settings.exposure_us, 5000);
  EXPECT_DOUBLE_EQ(settings.gain_db, 3);
  EXPECT_NEAR(settings.frame_rate_hz, 50, 0.01);
  EXPECT_EQ(source.info().width, 320);
  MonoFrame frame = GrabMono(&source);
  EXPECT_EQ(frame.image.cols, 320);
  EXPECT_EQ(frame.image.rows, 240);
}

TEST(AravisFakeCamera, OutOfRangeSettingsAreRefusedWithTheRange) {
  AravisOptions rate = FakeOptions();
  rate.frame_rate_hz = 5000;  // The camera would clamp this to 1000 Hz silently.
  AravisSource fast("Fake_1", rate);
  Status opened = fast.Open();
  ASSERT_FALSE(opened.ok());
  EXPECT_EQ(opened.code(), StatusCode::kInvalidArgument);
  EXPECT_NE(opened.message().find("frame rate 5000 Hz outside the camera's range"),
            std::string::npos)
      << opened.message();
  EXPECT_NE(opened.message().find("Fake_1"), std::string::npos);

  AravisOptions gain = FakeOptions();
  gain.gain_db = 40;
  AravisSource loud("Fake_1", gain);
  opened = loud.Open();
  ASSERT_FALSE(opened.ok());
  EXPECT_NE(opened.message().find("gain 40 dB outside"), std::string::npos) << opened.message();

  AravisOptions format = FakeOptions();
  format.pixel_format = "YUV422_8";
  AravisSource yuv("Fake_1", format);
  opened = yuv.Open();
  ASSERT_FALSE(opened.ok());
  EXPECT_NE(opened.message().find("does not offer pixel format 'YUV422_8'"), std::string::npos)
      << opened.message();
  EXPECT_NE(opened.message().find("Mono16"), std::string::npos) << "lists what it offers";
}

TEST(AravisFakeCamera, AbsentCameraIsUnavailableAndNamed) {
  AravisSource source("Sightline-NoSuchCamera", FakeOptions());
  const Status opened = source.Open();
  ASSERT_FALSE(opened.ok());
  EXPECT_EQ(opened.code(), StatusCode::kUnavailable);
  EXPECT_NE(opened.message().find("Sightline-NoSuchCamera"), std::string::npos) << opened.message();
}

TEST(AravisFakeCamera, DropOldestKeepsViewsCurrent) {
  AravisOptions options = FakeOptions();
  options.frame_rate_hz = 100;
  options.live.queue_capacity = 2;
  options.live.latest_only = true;
  AravisSource source("Fake_1", options);
  ASSERT_TRUE(source.Open().ok());
  GrabMono(&source);
  std::this_thread::sleep_for(std::chrono::milliseconds(500));  // A busy consumer.
  MonoFrame frame = GrabMono(&source);
  const SensorStats stats = source.stats();
  EXPECT_GE(stats.frames_dropped, 20u) << "about 50 frames arrived while the consumer slept";
  EXPECT_LT(source.last_grabbed().latency_ms, 200) << "the grabbed frame must be recent";
  EXPECT_GE(frame.stamp.sequence_id, 30);
}

TEST(AravisFakeCamera, InOrderDeliveryForRecording) {
  AravisOptions options = FakeOptions();
  options.frame_rate_hz = 100;
  options.live.queue_capacity = 4;
  options.live.latest_only = false;
  AravisSource source("Fake_1", options);
  ASSERT_TRUE(source.Open().ok());
  GrabMono(&source);
  std::this_thread::sleep_for(std::chrono::milliseconds(200));
  const int64_t first = GrabMono(&source).stamp.sequence_id;
  const int64_t second = GrabMono(&source).stamp.sequence_id;
  EXPECT_EQ(second, first + 1) << "queued frames come in order, none skipped";
  EXPECT_GT(source.stats().frames_dropped, 0u) << "the queue itself still drops the oldest";
}

TEST(AravisFakeCamera, SoftwareTriggerAtTheRequestedRate) {
  AravisOptions options = FakeOptions();
  options.trigger = "software";
  options.frame_rate_hz = 20;
  AravisSource source("Fake_1", options);
  const Status opened = source.Open();
  ASSERT_TRUE(opened.ok()) << opened.ToString();
  EXPECT_EQ(source.settings().trigger, "software");
  const auto start = std::chrono::steady_clock::now();
  for (int i = 0; i < 10; ++i) GrabMono(&source);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_GT(seconds, 0.3) << "10 triggered frames at 20 Hz take about 0.5 s";
  EXPECT_LT(seconds, 3.0);
}

TEST(AravisFakeCamera, HardwareTriggerSelectsTheLine) {
  AravisOptions options = FakeOptions();
  options.trigger = "hardware";
  options.trigger_line = "Line0";     // The simulator pulses its own Line0 at its frame rate.
  options.live.stall_timeout_ms = 0;  // Rare triggers are no reason to reconnect.
  AravisSource source("Fake_1", options);
  const Status opened = source.Open();
  ASSERT_TRUE(opened.ok()) << opened.ToString();
  EXPECT_EQ(source.settings().trigger, "hardware:Line0") << "read back from the camera";
  EXPECT_EQ(GrabMono(&source).image.cols, 512);

  options.trigger_line = "Line7";
  AravisSource no_line("Fake_1", options);
  const Status refused = no_line.Open();
  ASSERT_FALSE(refused.ok());
  EXPECT_NE(refused.message().find("Line7"), std::string::npos) << refused.message();
}

TEST(AravisFakeCamera, ManyInstancesReopenAndStatsFromAnotherThread) {
  AravisSource a("Fake_1", FakeOptions());
  AravisSource b("Fake_1", FakeOptions());
  ASSERT_TRUE(a.Open().ok());
  ASSERT_TRUE(b.Open().ok());
  std::atomic<bool> done{false};
  std::thread watcher([&] {
    while (!done) {
      (void)a.stats();
      (void)b.stats();
      std::this_thread::yield();
    }
  });
  for (int i = 0; i < 3; ++i) {
    GrabMono(&a);
    GrabMono(&b);
  }
  ASSERT_TRUE(a.Open().ok()) << "re-opening closes and connects again";
  GrabMono(&a);
  EXPECT_EQ(a.stats().frames_grabbed, 1u);
  done = true;
  watcher.join();
}

TEST(AravisFakeCamera, OpenSourceWithOptionSet) {
  OptionSet options;
  ASSERT_TRUE(DeclareSensorOptions(&options).ok());
  ASSERT_TRUE(options.ApplyOverride("sensors.aravis.fake_interface=true").ok());
  ASSERT_TRUE(options.ApplyOverride("sensors.aravis.pixel_format=Mono16").ok());
  StatusOr<std::unique_ptr<Source>> source = OpenSource("aravis://Fake_1", options);
  ASSERT_TRUE(source.ok()) << source.status().ToString();
  EXPECT_EQ((*source)->info().format, "Aravis camera");
  ASSERT_TRUE((*source)->Grab().ok());
  const std::vector<DeviceInfo> devices =
      FindDriver(BuiltinDrivers(), "aravis")->enumerate(options);
  bool listed = false;
  for (const DeviceInfo& d : devices) listed = listed || d.uri == "aravis://Fake_1";
  EXPECT_TRUE(listed) << "the Fake interface lists Fake_1 when enabled";
}

}  // namespace
}  // namespace sightline
