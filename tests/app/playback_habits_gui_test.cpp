// The playback habits a lab expects of the window: a replayed recording (replay://) feeds the
// views and the frame counter like a recording does; Loop holds for every source and pipeline;
// Play at the end starts again; a seek that would wipe a SLAM map asks first; opening another
// dataset leaves nothing of the previous run in the views.
#include <gtest/gtest.h>

#include <QAction>
#include <QApplication>
#include <QCheckBox>
#include <QComboBox>
#include <QDockWidget>
#include <QLabel>
#include <QMessageBox>
#include <QPushButton>
#include <QSignalSpy>
#include <QSlider>
#include <QTest>
#include <QTimer>
#include <QToolButton>
#include <cmath>

#include "app/sightline/builtin_presenters.h"
#include "app/sightline/evaluation_panel.h"
#include "app/sightline/main_window.h"
#include "app/sightline/pipeline_presenter.h"
#include "app/sightline/playback_controller.h"
#include "app/sightline/stereo_vo_presenter.h"
#include "core/sim/simulate.h"
#include "tests/app/process.h"
#include "tests/support/test_data.h"
#include "widgets/image_view.h"
#include "widgets/playback_bar.h"
#include "widgets/scene_view.h"
#include "widgets/time_series_plot.h"

namespace sightline {
namespace {

constexpr int kCorridorFrames = 20;

// A 20-frame simulated RGB-D corridor at 320x240, made once.
const std::string& SmallCorridor() {
  static const std::string dir = [] {
    const std::string path = testing::TempDir("gui_habits") + "/corridor";
    sim::SimulationOptions options = sim::SimulationOptions::ForScene("corridor");
    options.frames = kCorridorFrames;
    options.sensors = "rgbd";
    options.rgbd.resolution = "320x240";
    const auto done = sim::Simulate(options, path);
    EXPECT_TRUE(done.ok()) << done.status().ToString();
    return path + "/rgbd";
  }();
  return dir;
}

bool Open(MainWindow* window, const std::string& path) {
  QSignalSpy opened(window, &MainWindow::DatasetOpened);
  window->OpenPath(QString::fromStdString(path));
  return QTest::qWaitFor([&] { return opened.count() == 1; }, 30000);
}

PlaybackBar* Bar(const MainWindow& window) { return window.findChild<PlaybackBar*>(); }

ImageView* ColourView(const MainWindow& window) {
  auto* dock = window.findChild<QDockWidget*>("colour_dock");
  return dock ? qobject_cast<ImageView*>(dock->widget()) : nullptr;
}

// The number in the live frame counter ("frame N"); -1 when the label is not one.
int LiveCounter(const PlaybackBar& bar) {
  const QString text = bar.frame_label()->text();
  bool ok = false;
  const int n = text.section(' ', -1).toInt(&ok);
  return ok ? n : -1;
}

// Clicks `button_name` of the seek question when it shows; counts the questions asked.
class SeekQuestionAnswerer {
 public:
  SeekQuestionAnswerer() {
    QObject::connect(&timer_, &QTimer::timeout, [this] {
      auto* box = qobject_cast<QMessageBox*>(QApplication::activeModalWidget());
      if (box == nullptr || box->objectName() != "seek_reset_question") return;
      ++asked_;
      text_ = box->text();
      if (auto* button = box->findChild<QPushButton*>(answer_)) button->click();
    });
    timer_.start(20);
  }
  void Answer(const QString& button_name) { answer_ = button_name; }
  int asked() const { return asked_; }
  const QString& text() const { return text_; }

 private:
  QTimer timer_;
  QString answer_;
  QString text_;
  int asked_ = 0;
};

TEST(PlaybackHabits, AReplayedRecordingFeedsTheViewsAndTheFrameCounter) {
  MainWindow window;
  window.show();
  ASSERT_TRUE(Open(&window, "replay://" + SmallCorridor() + "?fps=20&loop=1"));
  ASSERT_TRUE(window.playback()->info()->live);
  PlaybackBar* bar = Bar(window);
  ASSERT_NE(bar, nullptr);
  // The user starts it from the bar, as a recording: the play button must not be greyed out.
  ASSERT_TRUE(bar->play_button()->isEnabled()) << "a live source cannot be played from the bar";
  EXPECT_FALSE(bar->slider()->isEnabled()) << "a live source cannot seek";
  QTest::mouseClick(bar->play_button(), Qt::LeftButton);
  ASSERT_TRUE(QTest::qWaitFor([&] { return window.frames_shown() >= 5; }, 30000));
  const int first = LiveCounter(*bar);
  // 20 frames at 20 fps with loop=1: more frames than the recording holds arrive.
  ASSERT_TRUE(QTest::qWaitFor([&] { return window.frames_shown() >= kCorridorFrames + 5; }, 60000))
      << "the replay stopped after " << window.frames_shown() << " frames";
  const int later = LiveCounter(*bar);
  EXPECT_GT(first, 0) << bar->frame_label()->text().toStdString();
  EXPECT_GT(later, first) << "the frame counter does not advance";
  ImageView* colour = ColourView(window);
  ASSERT_NE(colour, nullptr);
  EXPECT_EQ(colour->image().width(), 320) << "the colour view shows no image";
  EXPECT_EQ(colour->image().height(), 240);
  bar->play_button()->click();  // Pause.
  EXPECT_FALSE(window.playback()->playing());
}

TEST(PlaybackHabits, ClickingTheSliderShowsThatFrame) {
  MainWindow window;
  window.resize(1200, 800);
  window.show();
  ASSERT_TRUE(QTest::qWaitForWindowExposed(&window));
  ASSERT_TRUE(Open(&window, SmallCorridor()));
  QSlider* slider = Bar(window)->slider();
  ASSERT_EQ(slider->maximum(), kCorridorFrames - 1);
  QSignalSpy shown(&window, &MainWindow::FrameShown);
  QTest::mouseClick(slider, Qt::LeftButton, {},
                    QPoint(slider->width() * 3 / 4, slider->height() / 2));
  ASSERT_TRUE(QTest::qWaitFor([&] { return shown.count() >= 1; }, 20000));
  const int64_t id = shown.last().at(0).value<int64_t>();
  // 3/4 of 0..19 is about 14; Qt's page step would have gone to 10.
  EXPECT_NEAR(id, 14, 1);
  EXPECT_FALSE(window.playback()->playing()) << "a seek while paused stays paused";
}

// Loop set before opening holds for the source opened next, with or without a pipeline; without
// loop, Play at the end starts from the first frame again.
void ExpectLoopAndRestart(const QString& pipeline) {
  MainWindow window;
  for (PipelinePresenter* presenter : MakeBuiltinPresenters()) window.AddPipeline(presenter);
  if (!pipeline.isEmpty()) ASSERT_TRUE(window.ActivatePipelineByWord(pipeline));
  window.show();
  PlaybackBar* bar = Bar(window);
  bar->loop_box()->click();
  bar->speed_box()->setCurrentIndex(bar->speed_box()->findData(0.0));  // As fast as possible.
  ASSERT_TRUE(Open(&window, SmallCorridor()));
  EXPECT_TRUE(bar->loop_box()->isChecked());
  QSignalSpy ended(window.playback(), &PlaybackController::EndOfStream);
  std::vector<int64_t> ids;
  QObject::connect(&window, &MainWindow::FrameShown, [&ids](int64_t id) { ids.push_back(id); });
  bar->play_button()->click();
  const auto wrapped = [&] {
    for (size_t i = 1; i < ids.size(); ++i)
      if (ids[i] < ids[i - 1]) return true;
    return false;
  };
  ASSERT_TRUE(QTest::qWaitFor(wrapped, 60000)) << "no loop after " << ids.size() << " frames";
  EXPECT_EQ(ended.count(), 0) << "a looping recording ended";
  if (!pipeline.isEmpty()) EXPECT_GT(window.pipeline_frames(), 0) << "the pipeline stopped";

  bar->loop_box()->click();  // Off: the recording ends, then Play starts it again.
  ASSERT_TRUE(QTest::qWaitFor([&] { return ended.count() == 1; }, 60000));
  EXPECT_FALSE(window.playback()->playing());
  bar->speed_box()->setCurrentIndex(bar->speed_box()->findData(1.0));
  ids.clear();
  bar->play_button()->click();
  ASSERT_TRUE(QTest::qWaitFor([&] { return ids.size() >= 3; }, 20000))
      << "Play at the end did nothing";
  // Without the restart Play at the end shows nothing and ends again. The window shows the
  // newest frame when several are ready (under load it skips some), hence no exact first id.
  EXPECT_LT(ids.front(), kCorridorFrames / 2) << "Play at the end does not start from the start";
  EXPECT_LT(ids.front(), ids.back());
  EXPECT_EQ(ended.count(), 1) << "Play at the end ended again";
}

TEST(PlaybackHabits, LoopHoldsForTheNextSourceAndPlayAtTheEndRestarts) { ExpectLoopAndRestart(""); }

TEST(PlaybackHabits, LoopAndRestartHoldWithAPipelineRunning) { ExpectLoopAndRestart("Inspect"); }

TEST(PlaybackHabits, SeekingAnOdometryRunAsksBeforeItResetsTheMap) {
  SIGHTLINE_REQUIRE_DATA(kitti, "kitti_clip1");
  MainWindow window;
  auto* vo = new StereoVoPresenter();
  window.AddPipeline(vo);
  window.show();
  SeekQuestionAnswerer answerer;
  ASSERT_TRUE(Open(&window, kitti));
  // No pipeline yet: a seek has nothing to lose and asks nothing.
  QSignalSpy shown(&window, &MainWindow::FrameShown);
  Bar(window)->slider()->setValue(3);
  ASSERT_TRUE(QTest::qWaitFor([&] { return shown.count() == 1; }, 20000));
  EXPECT_EQ(answerer.asked(), 0);

  ASSERT_TRUE(window.ActivatePipeline(vo->Title()));
  for (int i = 0; i < 3; ++i) {
    window.playback()->Step();
    ASSERT_TRUE(QTest::qWaitFor([&] { return shown.count() == i + 2; }, 20000)) << "step " << i;
  }
  ASSERT_EQ(window.pipeline_frames(), 3);
  const size_t poses = vo->estimate().size();
  ASSERT_EQ(poses, 3u);

  answerer.Answer("seek_reset_no");
  Bar(window)->slider()->setValue(30);
  EXPECT_EQ(answerer.asked(), 1) << "the seek did not ask";
  EXPECT_TRUE(answerer.text().contains("over 3 frames")) << answerer.text().toStdString();
  QTest::qWait(300);
  EXPECT_EQ(shown.count(), 4) << "declined, yet a frame was sought";
  EXPECT_EQ(Bar(window)->position(), 6) << "the slider stays on the frame shown";
  EXPECT_EQ(vo->estimate().size(), poses) << "the map was reset although the user declined";

  answerer.Answer("seek_reset_yes");
  Bar(window)->slider()->setValue(30);
  EXPECT_EQ(answerer.asked(), 2);
  ASSERT_TRUE(QTest::qWaitFor([&] { return shown.count() == 5; }, 20000));
  EXPECT_EQ(shown.last().at(0).value<int64_t>(), 30);
  EXPECT_EQ(window.pipeline_frames(), 1) << "the pipeline starts over at the frame sought";
  // ... and so does what the views drew: the trajectory holds the new run's poses alone, from
  // the origin, and the plots hold its frames alone.
  ASSERT_EQ(vo->estimate().size(), 1u) << "the forward seek kept the previous run's trajectory";
  EXPECT_LT(vo->estimate().poses()[0].world_from_sensor.translation().norm(), 1e-9);
  window.playback()->Step();
  ASSERT_TRUE(QTest::qWaitFor([&] { return shown.count() == 6; }, 20000));
  EXPECT_EQ(vo->estimate().size(), 2u);
  EXPECT_LT(vo->estimate().poses()[1].world_from_sensor.translation().norm(), 3.0)
      << "one KITTI frame moves the car about a metre";
}

TEST(PlaybackHabits, OpeningAnotherDatasetClearsThePreviousRunsViewsAndPlots) {
  SIGHTLINE_REQUIRE_DATA(kitti, "kitti_clip1");
  MainWindow window;
  auto* vo = new StereoVoPresenter();
  window.AddPipeline(vo);
  ASSERT_TRUE(window.ActivatePipeline(vo->Title()));
  window.show();
  ASSERT_TRUE(Open(&window, kitti));
  QSignalSpy shown(&window, &MainWindow::FrameShown);
  for (int i = 0; i < 2; ++i) {
    window.playback()->Step();
    ASSERT_TRUE(QTest::qWaitFor([&] { return shown.count() == i + 1; }, 20000)) << "step " << i;
  }
  EvaluationPanel* evaluation = window.evaluation_panel();
  QSignalSpy evaluated(evaluation, &EvaluationPanel::Finished);
  evaluation->Evaluate(QString::fromStdString(kitti + "/poses.txt"),
                       QString::fromStdString(kitti + "/poses.txt"), "se3");
  ASSERT_TRUE(QTest::qWaitFor([&] { return evaluated.count() == 1; }, 20000));
  ASSERT_FALSE(vo->tracks_view()->image().isNull());
  ASSERT_FALSE(evaluation->top_view()->image().isNull());
  ASSERT_FALSE(std::isnan(evaluation->Figure("ate_rmse_m")));
  ASSERT_FALSE(vo->counts_plot()->Samples("tracks").empty());

  ASSERT_TRUE(Open(&window, SmallCorridor()));  // RGB-D: stereo odometry draws nothing on it.
  // Only the new recording's first frame may show (320 wide; the KITTI images are 1226).
  QTest::qWait(500);
  int previous = 0;
  for (const ImageView* view : window.findChildren<ImageView*>()) {
    if (!view->image().isNull() && view->image().width() != 320) ++previous;
  }
  EXPECT_EQ(previous, 0) << "views still show the previous dataset";
  EXPECT_TRUE(vo->tracks_view()->image().isNull());
  EXPECT_TRUE(vo->counts_plot()->Samples("tracks").empty()) << "the plot shows the previous run";
  EXPECT_TRUE(evaluation->top_view()->image().isNull());
  EXPECT_TRUE(std::isnan(evaluation->Figure("ate_rmse_m"))) << "the previous run's figures";
}

// An opened recording shows its first frame at once, before Play; it is still the first frame
// played (nothing skipped) and nothing counts it as played.
TEST(PlaybackHabits, AnOpenedRecordingShowsItsFirstFrameAtOnce) {
  MainWindow window;
  window.show();
  ImageView* colour = ColourView(window);
  ASSERT_NE(colour, nullptr);
  ASSERT_TRUE(Open(&window, SmallCorridor()));
  ASSERT_TRUE(QTest::qWaitFor([&] { return !colour->image().isNull(); }, 10000))
      << "nothing shown until Play";
  EXPECT_EQ(colour->image().width(), 320);
  EXPECT_EQ(window.frames_shown(), 0);
  EXPECT_FALSE(window.playback()->playing());
  EXPECT_EQ(Bar(window)->frame_label()->text(), QString("1 / %1").arg(kCorridorFrames));
  QSignalSpy shown(&window, &MainWindow::FrameShown);
  window.playback()->Step();
  ASSERT_TRUE(QTest::qWaitFor([&] { return shown.count() == 1; }, 20000));
  EXPECT_EQ(shown.at(0).at(0).value<int64_t>(), 0) << "the first frame was skipped";
}

// View > Follow the trajectory: on (the default), the 3D view is fitted again as the car's
// path leaves it; off, the user's view stays however far the path grows.
TEST(PlaybackHabits, TheThreeDViewFollowsAGrowingTrajectoryUnlessFollowIsOff) {
  SIGHTLINE_REQUIRE_DATA(kitti, "kitti_clip1");
  MainWindow window;
  auto* vo = new StereoVoPresenter();
  window.AddPipeline(vo);
  ASSERT_TRUE(window.ActivatePipeline(vo->Title()));
  window.show();
  auto* follow = window.findChild<QAction*>("follow_action");
  ASSERT_NE(follow, nullptr) << "no View > Follow the trajectory";
  ASSERT_TRUE(follow->isChecked()) << "follow is on by default";
  follow->trigger();
  EXPECT_FALSE(window.scene_view()->follow());
  ASSERT_TRUE(Open(&window, kitti));
  QSignalSpy shown(&window, &MainWindow::FrameShown);
  constexpr int kFrames = 6;  // About 6 m of driving: more than a fit's 2 m margin.
  for (int i = 0; i < kFrames; ++i) {
    window.playback()->Step();
    ASSERT_TRUE(QTest::qWaitFor([&] { return shown.count() == i + 1; }, 20000)) << "step " << i;
  }
  ASSERT_EQ(vo->estimate().size(), static_cast<size_t>(kFrames));
  // The tracks view says what its colours mean.
  ASSERT_EQ(vo->tracks_view()->keys().size(), 3u);
  EXPECT_EQ(vo->tracks_view()->keys()[0].label, "inlier track");
  // And the 3D view says which path is which.
  ASSERT_EQ(window.scene_view()->keys().size(), 2u);
  EXPECT_EQ(window.scene_view()->keys()[1].label, "ground truth");
  EXPECT_TRUE(window.scene_view()->keys_label()->isVisible());
  EXPECT_EQ(vo->view_fits(), 0) << "the view was fitted although follow is off";

  follow->trigger();
  window.playback()->Step();
  ASSERT_TRUE(QTest::qWaitFor([&] { return shown.count() == kFrames + 1; }, 20000));
  EXPECT_GE(vo->view_fits(), 1) << "follow on, yet the view stays";
  for (const TimedPose& p : vo->estimate().poses()) {
    EXPECT_TRUE(vo->fitted_box().contains(p.world_from_sensor.translation()));
  }
}

#ifdef SIGHTLINE_HAVE_ROS
// A pipeline run in the window gets what the source carries beside its frames, as the CLI's run
// does: a bag's odometry topic and its ground truth reach the pipeline the GUI makes.
TEST(PlaybackHabits, ThePipelineGetsTheOdometryAndTruthOfABag) {
  const std::string dir = testing::TempDir("gui_bag_odometry");
  const auto sim = testing::RunProcess(std::string(SIGHTLINE_BIN_DIR) +
                                       "/sightline-cli simulate corridor --out " + dir +
                                       " --frames 6 --sensors rgbd --quiet --format bag"
                                       " --set sim.rgbd.resolution=320x240");
  ASSERT_EQ(sim.exit_code, 0) << sim.out;
  PlaybackController playback;
  std::vector<std::pair<size_t, size_t>>
      given;  // Odometry and ground-truth poses per factory call.
  OptionSet options;
  playback.SetProcessorFactory(
      [&](const PipelineSource& source) -> std::unique_ptr<Pipeline> {
        given.emplace_back(source.odometry ? source.odometry->size() : 0,
                           source.ground_truth ? source.ground_truth->size() : 0);
        return nullptr;
      },
      options);
  QSignalSpy opened(&playback, &PlaybackController::Opened);
  playback.Open(QString::fromStdString(dir + "/corridor.bag"));
  ASSERT_TRUE(QTest::qWaitFor([&] { return opened.count() == 1; }, 30000));
  ASSERT_FALSE(given.empty());
  EXPECT_EQ(given.back().first, 6u);   // /odom: one pose a frame.
  EXPECT_EQ(given.back().second, 6u);  // /tf world -> camera.
}
#endif

}  // namespace
}  // namespace sightline
