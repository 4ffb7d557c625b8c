// Whether the window keeps up with its pipelines: each pipeline runs once headless (the
// registry's object over the recording, as `sightline-cli run` runs it) and once in a MainWindow
// with the built-in presenters, playing the same recording at full speed to its end. Counters:
//   headless_fps       frames the pipeline processed per second headless (first to last result)
//   gui_processed_fps  frames the pipeline processed per second of wall time in the window
//   gui_shown_fps      frames that reached the views per second (MainWindow::FrameShown)
//   ratio              gui_processed_fps / headless_fps (the window's cost on the pipeline)
// The button picker runs with a tap on true button 5: headless on the first frame
// (button.run.tap; without the overlay files a headless run writes), in the window through the
// operator panel (tap, Yes) on the first frame shown while playing, then at full speed; its GUI
// rate counts the frames after the Yes.
// Needs a display with OpenGL:
//   QT_QPA_PLATFORM=xcb xvfb-run -a -s "-screen 0 1280x800x24" \
//       build/bin/bench_gui_playback --benchmark_repetitions=3
#include <benchmark/benchmark.h>
#include <unistd.h>

#include <QApplication>
#include <QElapsedTimer>
#include <QObject>
#include <QPushButton>
#include <QTest>
#include <atomic>
#include <chrono>
#include <filesystem>
#include <iostream>
#include <map>
#include <string>

#include "app/sightline/builtin_presenters.h"
#include "app/sightline/button_picker_presenter.h"
#include "app/sightline/main_window.h"
#include "app/sightline/pipeline_presenter.h"
#include "app/sightline/playback_controller.h"
#include "core/pipeline/button_pipeline.h"
#include "core/pipeline/pipeline_registry.h"
#include "core/sim/simulate.h"
#include "tests/support/isolated_home.h"
#include "widgets/operator_panel.h"
#include "widgets/vtk_gl_widget.h"

namespace sightline {
namespace {

constexpr int kCorridorFrames = 150;  // The simulated drive: RGB-D 640x480 and stereo 752x480.
constexpr int kPanelFrames = 100;     // The simulated arm approach: mono 640x480.

std::string BenchDir() {
  static const std::string dir = [] {
    const auto path = std::filesystem::temp_directory_path() /
                      ("sightline-bench-gui-" + std::to_string(::getpid()));
    std::filesystem::create_directories(path);
    return path.string();
  }();
  return dir;
}

// The simulated recording of `scene`, made once per process.
const std::string& Recording(const std::string& scene) {
  static std::map<std::string, std::string> made;
  auto it = made.find(scene);
  if (it != made.end()) return it->second;
  sim::SimulationOptions options = sim::SimulationOptions::ForScene(scene);
  const std::string dir = BenchDir() + "/" + scene;
  if (scene == "corridor") {
    options.frames = kCorridorFrames;
    options.sensors = "rgbd,stereo";
  } else {
    options.frames = kPanelFrames;
    options.sensors = "mono";
  }
  const auto done = sim::Simulate(options, dir);
  if (!done.ok()) {
    std::cerr << "simulation failed: " << done.status().ToString() << "\n";
    std::exit(2);
  }
  return made.emplace(scene, dir).first->second;
}

constexpr int kTappedButton = 5;

// True button kTappedButton of the simulated panel (buttons.csv of the recording), or null.
const TrueButton* TappedButton() {
  static const std::vector<TrueButton> buttons = [] {
    StatusOr<std::vector<TrueButton>> read = ReadTrueButtons(Recording("panel") + "/buttons.csv");
    if (!read.ok()) {
      std::cerr << read.status().ToString() << "\n";
      return std::vector<TrueButton>{};
    }
    return *read;
  }();
  for (const TrueButton& b : buttons)
    if (b.id == kTappedButton) return &b;
  return nullptr;
}

double NowS() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

// Frames per second of the registry's pipeline `name` over `path`, headless.
double HeadlessFps(const std::string& name, const std::string& path, int64_t* frames) {
  const PipelineRegistry registry = BuiltinPipelines();
  RunRequest request;
  request.pipeline = name;
  request.dataset_path = path;
  request.out_dir = BenchDir() + "/headless-" + name;
  if (name == "button") {
    const TrueButton* button = TappedButton();
    if (button == nullptr || button->visible.empty() || !button->visible[0]) return 0;
    request.overrides.push_back("button.run.tap=" + std::to_string(button->pixel[0].x()) + "," +
                                std::to_string(button->pixel[0].y()) + "@0");
    // The window draws its overlay; a headless run would also write it (PNGs, overlay.avi).
    request.overrides.push_back("button.overlay.png=false");
  }
  // From the first result to the last: the run's set-up (options, opening the recording, the
  // button run's hand-eye check) is left out, as the window's rate starts after opening.
  int64_t count = 0;
  double first_s = 0, last_s = 0;
  request.on_result = [&](const std::shared_ptr<const PipelineResult>& result, int64_t) {
    if (result && result->status.ok()) ++count;
    last_s = NowS();
    if (first_s == 0) first_s = last_s;
  };
  const auto report = RunPipeline(registry, request);
  if (!report.ok() || count < 2) {
    std::cerr << name << " headless on " << path << ": "
              << (report.ok() ? "fewer than 2 frames" : report.status().ToString()) << "\n";
    return 0;
  }
  *frames = count;
  return (count - 1) / (last_s - first_s);
}

struct GuiRate {
  int64_t processed = 0;
  int64_t shown = 0;
  double wall_s = 0;
};

// Plays `path` in a window with pipeline `name` active, at full speed to the end.
GuiRate GuiRun(const std::string& name, const std::string& path) {
  GuiRate rate;
  MainWindow window;
  PipelinePresenter* wanted = nullptr;
  for (PipelinePresenter* p : MakeBuiltinPresenters()) {
    window.AddPipeline(p);
    if (p->info().name == name) wanted = p;
  }
  window.resize(1280, 760);
  window.show();
  if (!QTest::qWaitForWindowExposed(&window)) return rate;
  bool opened = false;
  QObject::connect(&window, &MainWindow::DatasetOpened, [&] { opened = true; });
  window.OpenPath(QString::fromStdString(path));
  if (!QTest::qWaitFor([&] { return opened; }, 60000) || wanted == nullptr ||
      !window.ActivatePipeline(wanted->Title())) {
    std::cerr << name << ": could not open " << path << " or activate the pipeline\n";
    return rate;
  }
  QTest::qWait(300);  // The first frame's preview and the docks' first paint.
  PlaybackController* playback = window.playback();
  bool ended = false;
  double end_s = 0;
  int64_t shown = 0, last_shown_index = -1, tap_frame = -1;
  QObject::connect(playback, &PlaybackController::EndOfStream, [&] {
    ended = true;
    end_s = NowS();
  });
  QObject::connect(&window, &MainWindow::FrameShown, [&](int64_t index) {
    ++shown;
    last_shown_index = index;
  });
  if (auto* picker = dynamic_cast<ButtonPickerPresenter*>(wanted)) {
    // The operator taps the button on the first frame shown while playing, then says Yes.
    const TrueButton* button = TappedButton();
    playback->SetSpeed(1);
    playback->Play();
    if (button == nullptr || !QTest::qWaitFor([&] { return last_shown_index >= 0; }, 30000)) {
      std::cerr << name << ": no frame shown or no true button " << kTappedButton << "\n";
      return rate;
    }
    tap_frame = last_shown_index;
    const auto frame = static_cast<size_t>(tap_frame);
    if (frame >= button->visible.size() || !button->visible[frame]) return rate;
    emit picker->panel()->Tapped(QPointF(button->pixel[frame].x(), button->pixel[frame].y()));
    if (!QTest::qWaitFor([&] { return picker->panel()->state() == OperatorState::kConfirm; },
                         30000)) {
      std::cerr << name << ": the tap on frame " << frame << " was not offered for a Yes\n";
      return rate;
    }
    picker->panel()->yes_button()->click();
  }
  playback->SetSpeed(0);
  shown = 0;
  const int64_t processed_before = playback->frames_processed();
  const double start_s = NowS();
  playback->Play();
  if (!QTest::qWaitFor([&] { return ended; }, 600000)) {
    std::cerr << name << ": playback did not end\n";
    return rate;
  }
  rate.processed = playback->frames_processed() - processed_before;
  if (auto* picker = dynamic_cast<ButtonPickerPresenter*>(wanted)) {
    std::cerr << "button: tapped at frame " << tap_frame << ", " << processed_before
              << " processed before the Yes, final state " << PickerStateKey(picker->last_state())
              << "\n";
  }
  rate.shown = shown;
  rate.wall_s = end_s - start_s;
  return rate;
}

void BM_GuiPlayback(benchmark::State& state, const std::string& name, const std::string& scene,
                    const std::string& sensor) {
  const std::string path = Recording(scene) + "/" + sensor;
  double headless = 0;
  GuiRate gui;
  int64_t headless_frames = 0;
  for (auto _ : state) {
    headless = HeadlessFps(name, path, &headless_frames);
    gui = GuiRun(name, path);
  }
  if (headless <= 0 || gui.wall_s <= 0) {
    state.SkipWithError("a run failed (see stderr)");
    return;
  }
  const double processed_fps = gui.processed / gui.wall_s;
  state.counters["headless_fps"] = headless;
  state.counters["gui_processed_fps"] = processed_fps;
  state.counters["gui_shown_fps"] = gui.shown / gui.wall_s;
  state.counters["ratio"] = processed_fps / headless;
  state.counters["headless_frames"] = static_cast<double>(headless_frames);
  state.counters["gui_processed"] = static_cast<double>(gui.processed);
  state.counters["gui_shown"] = static_cast<double>(gui.shown);
}

}  // namespace
}  // namespace sightline

int main(int argc, char** argv) {
  const sightline::testing::IsolatedHome home;  // Never the user's settings or layout.
  sightline::VtkGlWidget::SetDefaultSurfaceFormat();
  QApplication app(argc, argv);
  QApplication::setOrganizationName("SightlineBenchmarks");
  using sightline::BM_GuiPlayback;
  const struct {
    const char* name;
    const char* scene;
    const char* sensor;
  } kRuns[] = {{"mapping", "corridor", "rgbd"},     {"mobility", "corridor", "rgbd"},
               {"stereo-vo", "corridor", "stereo"}, {"mono-slam", "panel", "mono"},
               {"button", "panel", "mono"},         {"inspect", "corridor", "rgbd"}};
  for (const auto& run : kRuns) {
    benchmark::RegisterBenchmark((std::string("BM_GuiPlayback/") + run.name).c_str(),
                                 BM_GuiPlayback, run.name, run.scene, run.sensor)
        ->Iterations(1)
        ->Unit(benchmark::kSecond)
        ->UseRealTime();
  }
  benchmark::Initialize(&argc, argv);
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  std::error_code ignored;
  std::filesystem::remove_all(sightline::BenchDir(), ignored);
  return 0;
}
