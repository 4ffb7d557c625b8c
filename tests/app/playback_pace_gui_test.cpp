// The window never holds its pipeline back: while the GUI thread is busy drawing, the worker
// goes on processing every frame, and the views then get the newest result, not a backlog.
#include <gtest/gtest.h>

#include <QSignalSpy>
#include <QTest>
#include <chrono>
#include <thread>
#include <vector>

#include "app/sightline/builtin_presenters.h"
#include "app/sightline/main_window.h"
#include "app/sightline/pipeline_presenter.h"
#include "app/sightline/playback_controller.h"
#include "core/sim/simulate.h"
#include "tests/support/test_data.h"

namespace sightline {
namespace {

constexpr int kFrames = 24;

// A 24-frame simulated RGB-D corridor at 320x240, made once.
const std::string& Corridor() {
  static const std::string dir = [] {
    const std::string path = testing::TempDir("gui_pace") + "/corridor";
    sim::SimulationOptions options = sim::SimulationOptions::ForScene("corridor");
    options.frames = kFrames;
    options.sensors = "rgbd";
    options.rgbd.resolution = "320x240";
    const auto done = sim::Simulate(options, path);
    EXPECT_TRUE(done.ok()) << done.status().ToString();
    return path + "/rgbd";
  }();
  return dir;
}

// Plays the corridor with pipeline `name` at full speed while the GUI thread, at the first frame
// it shows, stops drawing until the worker has processed every frame (or 120 s pass: a worker
// that waits for the GUI never gets there). Returns the ids of the frames shown.
std::vector<int64_t> PlayWithAStalledGui(const std::string& name, int64_t* processed_while_stalled,
                                         int64_t* processed_total) {
  MainWindow window;
  PipelinePresenter* wanted = nullptr;
  for (PipelinePresenter* p : MakeBuiltinPresenters()) {
    window.AddPipeline(p);
    if (p->info().name == name) wanted = p;
  }
  window.show();
  QSignalSpy opened(&window, &MainWindow::DatasetOpened);
  window.OpenPath(QString::fromStdString(Corridor()));
  EXPECT_TRUE(QTest::qWaitFor([&] { return opened.count() == 1; }, 30000));
  EXPECT_NE(wanted, nullptr);
  if (wanted == nullptr || !window.ActivatePipeline(wanted->Title())) return {};
  PlaybackController* playback = window.playback();
  const int64_t before = playback->frames_processed();
  std::vector<int64_t> shown;
  QObject::connect(&window, &MainWindow::FrameShown, [&](int64_t id) {
    shown.push_back(id);
    if (shown.size() != 1) return;
    // A GUI thread that cannot keep up at all: no event is handled while it waits here.
    const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(120);
    while (playback->frames_processed() - before < kFrames &&
           std::chrono::steady_clock::now() < give_up) {
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    *processed_while_stalled = playback->frames_processed() - before;
  });
  QSignalSpy ended(playback, &PlaybackController::EndOfStream);
  playback->SetSpeed(0);
  playback->Play();
  EXPECT_TRUE(QTest::qWaitFor([&] { return ended.count() == 1; }, 180000));
  QTest::qWait(200);  // Whatever is still on its way to the views arrives.
  *processed_total = playback->frames_processed() - before;
  return shown;
}

class PlaybackPace : public ::testing::TestWithParam<const char*> {};

TEST_P(PlaybackPace, AStalledGuiNeitherHoldsTheWorkerBackNorGetsABacklog) {
  int64_t while_stalled = -1;
  int64_t total = -1;
  const std::vector<int64_t> shown = PlayWithAStalledGui(GetParam(), &while_stalled, &total);
  ASSERT_FALSE(shown.empty()) << "no frame reached the views";
  EXPECT_EQ(while_stalled, kFrames)
      << "the worker stopped at " << while_stalled << " of " << kFrames
      << " frames while the GUI was busy drawing: it waits for the views";
  EXPECT_EQ(total, kFrames) << "every frame is processed, shown or not";
  // After the stall the views get the newest result at once: the last frame, not the ones
  // processed in between.
  EXPECT_EQ(shown.back(), kFrames - 1) << "the views do not end on the last frame";
  EXPECT_LE(shown.size(), 3u) << "the views drew a backlog of " << shown.size() << " frames";
  for (size_t i = 1; i < shown.size(); ++i) {
    EXPECT_GT(shown[i], shown[i - 1]) << "an older frame was shown after a newer one";
  }
}

// Every pipeline the simulated RGB-D corridor feeds, with its own presenter.
INSTANTIATE_TEST_SUITE_P(RgbdPipelines, PlaybackPace,
                         ::testing::Values("mapping", "mobility", "inspect"),
                         [](const ::testing::TestParamInfo<const char*>& info) {
                           return std::string(info.param);
                         });

}  // namespace
}  // namespace sightline
