// The GUI's live-sensor status and recording: a simulated recording replayed as a live camera
// (replay://) through the real capture thread, recorded from the window and read back with the
// project's readers; the GigE Vision fake camera streaming into the sightline executable.
#include <gtest/gtest.h>
#include <unistd.h>

#include <QFileInfo>
#include <QImage>
#include <QSignalSpy>
#include <QTest>
#include <fstream>

#include "app/sightline/live_status_widget.h"
#include "app/sightline/main_window.h"
#include "app/sightline/playback_controller.h"
#include "app/sightline/recording_controller.h"
#include "core/sim/simulate.h"
#include "tests/app/process.h"
#include "tests/core/record/record_test_util.h"
#include "tests/support/test_data.h"

namespace sightline {
namespace {

// A 60-frame simulated RGB-D corridor at 320x240, made once.
const std::string& SmallCorridor() {
  static const std::string dir = [] {
    const std::string path = testing::TempDir("gui_record") + "/corridor";
    sim::SimulationOptions options = sim::SimulationOptions::ForScene("corridor");
    options.frames = 60;
    options.sensors = "rgbd";
    options.rgbd.resolution = "320x240";
    const auto done = sim::Simulate(options, path);
    EXPECT_TRUE(done.ok()) << done.status().ToString();
    return path + "/rgbd";
  }();
  return dir;
}

// Opens `uri` in the window and plays it; false when it did not open.
bool OpenAndPlay(MainWindow* window, const std::string& uri) {
  QSignalSpy opened(window, &MainWindow::DatasetOpened);
  window->OpenPath(QString::fromStdString(uri));
  if (!QTest::qWaitFor([&] { return opened.count() == 1; }, 20000)) return false;
  window->playback()->Play();
  return true;
}

TEST(LiveStatus, ShowsStateFpsDroppedAndLatencyWhileALiveSourceRuns) {
  MainWindow window;
  window.show();
  LiveStatusWidget* status = window.live_status();
  ASSERT_NE(status, nullptr);
  status->Refresh();
  EXPECT_FALSE(status->shown().has_value()) << "nothing live is open";
  EXPECT_FALSE(status->isVisible());

  ASSERT_TRUE(OpenAndPlay(&window, "replay://" + SmallCorridor() + "?fps=20&loop=1"));
  EXPECT_TRUE(window.playback()->info()->live);
  ASSERT_TRUE(QTest::qWaitFor([&] { return window.frames_shown() >= 8; }, 20000));
  status->Refresh();
  ASSERT_TRUE(status->shown().has_value());
  EXPECT_EQ(status->shown()->state, SensorState::kStreaming);
  EXPECT_GE(status->shown()->frames_received, 8u);
  EXPECT_GT(status->shown()->receive_rate_hz, 5.0);
  EXPECT_GE(status->shown()->mean_latency_ms, 0.0);
  EXPECT_TRUE(status->isVisible());
  for (const char* word : {"streaming", "fps", "dropped", "latency"}) {
    EXPECT_TRUE(status->text().contains(word)) << word << ": " << status->text().toStdString();
  }
  EXPECT_TRUE(status->toolTip().contains("sensors/")) << status->toolTip().toStdString();

  // A recorded dataset is not live: the indicator goes away.
  window.playback()->Close();
  status->Refresh();
  EXPECT_FALSE(status->isVisible());
}

TEST(Recording, RecordsTheLiveSourceFromTheWindowAndReadsBackExactly) {
  MainWindow window;
  window.show();
  RecordingController* recording = window.recording();
  ASSERT_NE(recording, nullptr);
  EXPECT_TRUE(recording->record_action()->isEnabled());
  EXPECT_FALSE(recording->stop_action()->isEnabled());

  ASSERT_TRUE(OpenAndPlay(&window, "replay://" + SmallCorridor() + "?fps=20"));
  QSignalSpy progress(recording, &RecordingController::Progress);
  QSignalSpy finished(recording, &RecordingController::Finished);
  const std::string out = testing::TempDir("gui_record_live") + "/rec";
  ASSERT_TRUE(recording->Start(QString::fromStdString(out)));
  EXPECT_FALSE(recording->record_action()->isEnabled());
  EXPECT_TRUE(recording->stop_action()->isEnabled());
  ASSERT_TRUE(QTest::qWaitFor([&] { return recording->stats().frames_written >= 15; }, 30000));
  ASSERT_GE(progress.count(), 1);
  EXPECT_TRUE(progress.last().at(0).toString().contains("written"))
      << progress.last().at(0).toString().toStdString();
  recording->Stop();
  ASSERT_EQ(finished.count(), 1);
  EXPECT_TRUE(finished.at(0).at(0).toString().contains("Recorded"));
  EXPECT_TRUE(recording->record_action()->isEnabled());

  const RecorderStats stats = recording->stats();
  EXPECT_EQ(stats.frames_written + stats.frames_dropped, stats.frames_offered);
  const std::vector<Frame> recorded = testing::ReadAllFrames(out);
  EXPECT_EQ(recorded.size(), stats.frames_written);
  EXPECT_EQ(testing::ExpectRecordedFramesMatch(testing::ReadAllFrames(SmallCorridor()), recorded),
            static_cast<int>(recorded.size()));
}

TEST(Recording, ARecordedDatasetIsCopiedWithoutDrops) {
  SIGHTLINE_REQUIRE_DATA(tum, "tum_fr1_desk");
  MainWindow window;
  window.show();
  QSignalSpy opened(&window, &MainWindow::DatasetOpened);
  window.OpenPath(QString::fromStdString(tum));
  ASSERT_TRUE(QTest::qWaitFor([&] { return opened.count() == 1; }, 20000));
  const std::string out = testing::TempDir("gui_record_tum") + "/rec";
  ASSERT_TRUE(window.recording()->Start(QString::fromStdString(out)));
  QSignalSpy ended(window.playback(), &PlaybackController::EndOfStream);
  window.playback()->SetSpeed(0);
  window.playback()->Play();
  ASSERT_TRUE(QTest::qWaitFor([&] { return ended.count() >= 1; }, 30000));
  window.recording()->Stop();
  EXPECT_EQ(window.recording()->stats().frames_written, 9u);
  EXPECT_EQ(window.recording()->stats().frames_dropped, 0u);
  EXPECT_EQ(
      testing::ExpectRecordedFramesMatch(testing::ReadAllFrames(tum), testing::ReadAllFrames(out)),
      9);
}

// Record... into a folder that holds files (the home folder, an earlier recording) records into
// a new sub-folder of it; the files there stay untouched and the recording reads back whole.
TEST(Recording, RecordIntoAUsedFolderMakesANewSubFolderAndKeepsTheFiles) {
  SIGHTLINE_REQUIRE_DATA(tum, "tum_fr1_desk");
  const QString empty = QString::fromStdString(testing::TempDir("gui_record_empty"));
  EXPECT_EQ(RecordingController::FolderFor(empty), empty);
  EXPECT_EQ(RecordingController::FolderFor(empty + "/new"), empty + "/new");

  const QString used = QString::fromStdString(testing::TempDir("gui_record_used"));
  { std::ofstream(used.toStdString() + "/notes.txt") << "keep me\n"; }
  const QString folder = RecordingController::FolderFor(used);
  ASSERT_NE(folder, used);
  EXPECT_EQ(QFileInfo(folder).absolutePath(), QFileInfo(used).absoluteFilePath());
  EXPECT_TRUE(QFileInfo(folder).fileName().startsWith("sightline-"));

  MainWindow window;
  window.show();
  QSignalSpy opened(&window, &MainWindow::DatasetOpened);
  window.OpenPath(QString::fromStdString(tum));
  ASSERT_TRUE(QTest::qWaitFor([&] { return opened.count() == 1; }, 20000));
  ASSERT_TRUE(window.recording()->Start(folder));
  // A second pick of the same folder gets another sub-folder, not the running recording's.
  EXPECT_NE(RecordingController::FolderFor(used), folder);
  QSignalSpy ended(window.playback(), &PlaybackController::EndOfStream);
  window.playback()->SetSpeed(0);
  window.playback()->Play();
  ASSERT_TRUE(QTest::qWaitFor([&] { return ended.count() >= 1; }, 30000));
  window.recording()->Stop();
  EXPECT_EQ(window.recording()->stats().frames_written, 9u);
  EXPECT_EQ(testing::ReadAll(used.toStdString() + "/notes.txt"), "keep me\n");
  EXPECT_EQ(testing::ReadAllFrames(folder.toStdString()).size(), 9u);
}

TEST(Recording, NothingOpenIsReportedNotFatal) {
  MainWindow window;
  QSignalSpy failed(window.recording(), &RecordingController::Failed);
  EXPECT_FALSE(window.recording()->Start(QString::fromStdString(testing::TempDir("gui_none"))));
  ASSERT_EQ(failed.count(), 1);
  EXPECT_TRUE(failed.at(0).at(0).toString().contains("open a sensor"));
}

// The sightline executable streams a GigE Vision camera (arv-fake-gv-camera-0.8 in a private
// network namespace, whose loopback the GUI shares) and saves a window screenshot.
TEST(SightlineExecutable, StreamsTheAravisGigEFakeCamera) {
#ifndef SIGHTLINE_HAVE_ARAVIS
  GTEST_SKIP() << "built without Aravis";
#else
  const std::string flag = getuid() == 0 ? "-n" : "-rn";
  if (testing::RunProcess("unshare " + flag + " true").exit_code != 0) {
    GTEST_SKIP() << "needs a private network namespace (unshare " << flag << " failed)";
  }
  if (testing::RunProcess("command -v ip").exit_code != 0) {
    GTEST_SKIP() << "needs the ip command (iproute2) to bring up lo in the namespace";
  }
  const std::string bin = SIGHTLINE_BIN_DIR;
  const std::string shot = testing::TempDir("gui_aravis") + "/shot.png";
  // Waits (bounded, 60 attempts) until discovery finds the camera, then screenshots 5 frames.
  // The camera's output goes to /dev/null: it must not hold the test's pipe open.
  const std::string script =
      "ip link set lo up && { arv-fake-gv-camera-0.8 -i 127.0.0.1 -s GUI1 >/dev/null 2>&1 & } "
      "&& camera=\\$! && i=0; "
      "until " +
      bin +
      "/sightline-cli info aravis://Aravis-Fake-GUI1 >/dev/null 2>&1; do "
      "i=\\$((i+1)); [ \\$i -gt 60 ] && break; done; " +
      bin + "/sightline --open aravis://Aravis-Fake-GUI1 --screenshot " + shot +
      " --frames 5 --timeout 60; rc=\\$?; kill \\$camera; exit \\$rc";
  const auto r = testing::RunProcess("unshare " + flag + " sh -c \"" + script + "\"");
  ASSERT_EQ(r.exit_code, 0) << r.out;
  QImage image(QString::fromStdString(shot));
  ASSERT_FALSE(image.isNull()) << r.out;
  EXPECT_GT(image.width(), 400);
#endif
}

}  // namespace
}  // namespace sightline
