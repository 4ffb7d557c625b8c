// Recording a real GigE Vision stream: arv-fake-gv-camera-0.8 serves a camera on the loopback
// of a private network namespace (entered before any test), Sightline's Aravis source grabs it
// through the live path and the recorder writes an image folder that reads back exactly.
#include <gtest/gtest.h>

#include <chrono>

#include "core/record/record_session.h"
#include "core/sensors/driver_registry.h"
#include "tests/core/record/record_test_util.h"
#include "tests/core/sensors/child_process.h"
#include "tests/core/sensors/network_namespace.h"
#include "tests/support/test_data.h"

namespace sightline {
namespace {

using Clock = std::chrono::steady_clock;

Status& NamespaceStatus() {
  static Status status = FailedPrecondition("the test environment did not run");
  return status;
}

class PrivateNetworkEnvironment : public ::testing::Environment {
 public:
  void SetUp() override { NamespaceStatus() = testing::EnterPrivateNetworkNamespace({}); }
};
::testing::Environment* const kEnvironment =
    ::testing::AddGlobalTestEnvironment(new PrivateNetworkEnvironment);

// Opens the fake camera through the registry, waiting (bounded) for discovery.
StatusOr<std::unique_ptr<Source>> OpenCamera(const OptionSet& options) {
  const Clock::time_point deadline = Clock::now() + std::chrono::seconds(15);
  StatusOr<std::unique_ptr<Source>> source = Unavailable("not tried");
  while (Clock::now() < deadline) {
    source = OpenSource("aravis://Aravis-Fake-REC1", options);
    if (source.ok()) break;
  }
  return source;
}

TEST(RecordAravis, RecordsTheGigEFakeCameraAndReadsItBackExactly) {
  if (!NamespaceStatus().ok()) {
    GTEST_SKIP() << "needs a private network namespace: " << NamespaceStatus().message();
  }
  auto camera =
      testing::ChildProcess::Start({SIGHTLINE_ARV_FAKE_GV_CAMERA, "-i", "127.0.0.1", "-s", "REC1"});
  ASSERT_TRUE(camera.ok()) << camera.status().ToString();
  OptionSet options;
  ASSERT_TRUE(DeclareSensorOptions(&options).ok());
  ASSERT_TRUE(options.ApplyOverride("sensors.aravis.latest_only=false").ok());
  ASSERT_TRUE(options.ApplyOverride("sensors.aravis.queue_capacity=32").ok());
  ASSERT_TRUE(options.ApplyOverride("sensors.aravis.frame_rate_hz=25").ok());
  StatusOr<std::unique_ptr<Source>> source = OpenCamera(options);
  ASSERT_TRUE(source.ok()) << source.status().ToString();
  EXPECT_TRUE((*source)->info().live);

  // Frames as grabbed, kept for comparison, through a recorder that waits for the disk.
  const std::string out = testing::TempDir("record_aravis") + "/rec";
  RecorderOptions recorder_options;
  recorder_options.block_when_full = true;
  auto recorder = Recorder::Start(out, (*source)->info(), recorder_options);
  ASSERT_TRUE(recorder.ok()) << recorder.status().ToString();
  std::vector<Frame> grabbed;
  while (grabbed.size() < 25) {
    const Status s = (*source)->Grab();
    ASSERT_TRUE(s.ok()) << s.ToString();
    grabbed.push_back(*(*source)->Retrieve());
    (*recorder)->Push(grabbed.back());
  }
  ASSERT_TRUE((*recorder)->Stop().ok());
  EXPECT_EQ((*recorder)->stats().frames_written, 25u);
  EXPECT_STREQ((*recorder)->format(), "image folder");
  const std::vector<Frame> recorded = testing::ReadAllFrames(out);
  ASSERT_EQ(recorded.size(), 25u);
  EXPECT_EQ(std::get<MonoFrame>(recorded[0]).image.size(), cv::Size(512, 512));
  EXPECT_EQ(testing::ExpectRecordedFramesMatch(grabbed, recorded), 25);

  // The session loop the CLI runs, with the source's own counters.
  const std::string out2 = testing::TempDir("record_aravis") + "/rec2";
  RecordLimits limits;
  limits.max_frames = 30;
  StatusOr<RecordSummary> summary = RecordSource(source->get(), out2, RecorderOptions(), limits);
  ASSERT_TRUE(summary.ok()) << summary.status().ToString();
  EXPECT_EQ(summary->end_reason, "frame limit");
  EXPECT_EQ(summary->recorder.frames_offered, 30u);
  EXPECT_EQ(summary->recorder.frames_written + summary->recorder.frames_dropped, 30u);
  ASSERT_TRUE(summary->sensor.has_value());
  EXPECT_EQ(summary->sensor->state, SensorState::kStreaming);
  EXPECT_EQ(testing::ReadAllFrames(out2).size(), summary->recorder.frames_written);
}

}  // namespace
}  // namespace sightline
