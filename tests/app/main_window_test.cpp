// The main window on real data under an X server: open, step, and look at the pixels.
#include "app/sightline/main_window.h"

#include <gtest/gtest.h>

#include <QDir>
#include <QFile>
#include <QImage>
#include <QMenu>
#include <QMenuBar>
#include <QSettings>
#include <QSignalSpy>
#include <QTest>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iomanip>
#include <iterator>
#include <sstream>

#include "app/sightline/demo_generator.h"
#include "app/sightline/evaluation_panel.h"
#include "app/sightline/mapping_presenter.h"
#include "app/sightline/mono_slam_presenter.h"
#include "app/sightline/playback_controller.h"
#include "app/sightline/stereo_vo_presenter.h"
#include "core/io/dataset.h"
#include "core/io/floor_file.h"
#include "core/sim/simulate.h"
#include "tests/app/process.h"
#include "tests/support/test_data.h"
#include "widgets/image_view.h"
#include "widgets/parameter_panel.h"
#include "widgets/scene_view.h"
#include "widgets/time_series_plot.h"

namespace sightline {
namespace {

// Pixels (every second row and column) inside `region` that differ clearly from the colour at
// the image corner (the background). The whole image when `region` is empty.
int ForegroundPixels(const QImage& image, QRect region = QRect()) {
  if (region.isEmpty()) region = image.rect();
  const QColor background = image.pixelColor(1, 1);
  int count = 0;
  for (int y = region.top(); y <= region.bottom(); y += 2) {
    for (int x = region.left(); x <= region.right(); x += 2) {
      const QColor c = image.pixelColor(x, y);
      if (std::abs(c.red() - background.red()) + std::abs(c.green() - background.green()) +
              std::abs(c.blue() - background.blue()) >
          60) {
        ++count;
      }
    }
  }
  return count;
}

bool WaitFor(const std::function<bool()>& condition, int timeout_ms) {
  return QTest::qWaitFor(condition, timeout_ms);
}

TEST(MainWindow, OpensTumStepsThreeFramesAndDrawsTheCloud) {
  SIGHTLINE_REQUIRE_DATA(dir, "tum_fr1_desk");
  MainWindow window;
  window.resize(1200, 800);
  window.show();
  ASSERT_TRUE(QTest::qWaitForWindowExposed(&window));
  window.scene_view()->SetGroundGrid(false);  // Only the cloud may differ from the background.

  // Background before any data.
  QTest::qWait(200);
  const int empty = ForegroundPixels(window.scene_view()->grabFramebuffer());

  QSignalSpy opened(&window, &MainWindow::DatasetOpened);
  window.OpenPath(QString::fromStdString(dir));
  ASSERT_TRUE(WaitFor([&] { return opened.count() == 1; }, 20000)) << "dataset did not open";
  ASSERT_NE(window.playback()->info(), nullptr);
  EXPECT_EQ(window.playback()->info()->frame_count, 9);

  QSignalSpy shown(&window, &MainWindow::FrameShown);
  for (int i = 0; i < 3; ++i) {
    window.playback()->Step();
    ASSERT_TRUE(WaitFor([&] { return shown.count() == i + 1; }, 10000)) << "step " << i;
  }
  EXPECT_EQ(shown.at(2).at(0).value<int64_t>(), 2);  // Frames 0, 1, 2 in order.
  QTest::qWait(300);

  const QImage frame = window.scene_view()->grabFramebuffer();
  ASSERT_FALSE(frame.isNull());
  const int drawn = ForegroundPixels(frame);
  frame.save(QString::fromStdString(testing::TempDir("gui") + "/scene.png"));
  // The view is fit to the cloud, so the central region is mostly cloud; an empty or black view
  // has almost no foreground anywhere.
  EXPECT_LT(empty, 50) << "background not uniform before data";
  const QRect centre(frame.width() * 3 / 8, frame.height() * 3 / 8, frame.width() / 4,
                     frame.height() / 4);
  const int centre_samples = (centre.width() / 2) * (centre.height() / 2);
  EXPECT_GT(ForegroundPixels(frame, centre), centre_samples / 2)
      << "the centre of the 3D view is not covered by the cloud";
  EXPECT_GT(drawn, 1000) << "the 3D view shows too few cloud pixels: " << drawn;
}

TEST(GuiTests, UseTheirOwnSettingsFolderNotTheUsers) {
  const char* home = std::getenv("SIGHTLINE_GUI_TEST_HOME");
  ASSERT_NE(home, nullptr) << "gui_test_main.cpp sets up a folder per test process";
  QSettings settings;
  settings.setValue("probe", 1);
  settings.sync();
  EXPECT_TRUE(settings.fileName().startsWith(QString::fromUtf8(home)))
      << settings.fileName().toStdString();
  EXPECT_TRUE(QFile::exists(settings.fileName()));
}

TEST(MainWindow, MissingDatasetIsReportedNotFatal) {
  MainWindow window;
  window.show();
  QSignalSpy failed(&window, &MainWindow::DatasetFailed);
  window.OpenPath("/nonexistent/recording");
  ASSERT_TRUE(WaitFor([&] { return failed.count() == 1; }, 10000));
  EXPECT_TRUE(failed.at(0).at(0).toString().contains("/nonexistent/recording"));
  EXPECT_EQ(window.playback()->info(), nullptr);
}

TEST(SightlineExecutable, ScreenshotShowsColourDepthAndCloud) {
  SIGHTLINE_REQUIRE_DATA(dir, "tum_fr1_desk");
  const std::string png = testing::TempDir("gui") + "/shot.png";
  const auto r = testing::RunProcess(std::string(SIGHTLINE_BIN_DIR) + "/sightline --open " + dir +
                                     " --screenshot " + png + " --frames 5");
  ASSERT_EQ(r.exit_code, 0) << r.out;
  QImage shot(QString::fromStdString(png));
  ASSERT_FALSE(shot.isNull()) << "no screenshot at " << png;
  EXPECT_GT(shot.width(), 800);
  EXPECT_GT(ForegroundPixels(shot), shot.width() * shot.height() / 4 / 5);
}

}  // namespace
}  // namespace sightline

namespace sightline {
namespace {

TEST(EvaluationPanel, EvaluatesKittiGroundTruthAgainstItselfAndAScaledCopy) {
  SIGHTLINE_REQUIRE_DATA(dir, "kitti_clip1");
  MainWindow window;
  window.show();
  EvaluationPanel* panel = window.evaluation_panel();
  QSignalSpy finished(panel, &EvaluationPanel::Finished);
  panel->Evaluate(QString::fromStdString(dir + "/poses.txt"),
                  QString::fromStdString(dir + "/poses.txt"), "se3");
  ASSERT_TRUE(QTest::qWaitFor([&] { return finished.count() == 1; }, 20000));
  EXPECT_NEAR(panel->Figure("ate_rmse_m"), 0.0, 1e-9);
  EXPECT_NEAR(panel->Figure("pairs"), 51, 0);
  EXPECT_FALSE(panel->top_view()->image().isNull());
  EXPECT_FALSE(panel->error_view()->image().isNull());

  // A copy whose translations are 1% longer: length error 1% without alignment.
  std::ifstream in(dir + "/poses.txt");
  const std::string scaled = testing::TempDir("eval_gui") + "/scaled.txt";
  std::ofstream out(scaled);
  for (std::string line; std::getline(in, line);) {
    std::istringstream fields(line);
    std::vector<double> v((std::istream_iterator<double>(fields)), std::istream_iterator<double>());
    if (v.size() != 12) continue;
    for (int i : {3, 7, 11}) v[i] *= 1.01;
    for (size_t i = 0; i < v.size(); ++i) out << (i ? " " : "") << std::setprecision(12) << v[i];
    out << "\n";
  }
  out.close();
  panel->Evaluate(QString::fromStdString(scaled), QString::fromStdString(dir + "/poses.txt"),
                  "none");
  ASSERT_TRUE(QTest::qWaitFor([&] { return finished.count() == 2; }, 20000));
  EXPECT_NEAR(panel->Figure("length_error_pct"), 1.0, 1e-3);
}

TEST(EvaluationPanel, MissingFileIsReported) {
  EvaluationPanel panel;
  QSignalSpy failed(&panel, &EvaluationPanel::Failed);
  panel.Evaluate("/nonexistent/est.txt", "/nonexistent/gt.txt", "se3");
  ASSERT_TRUE(QTest::qWaitFor([&] { return failed.count() == 1; }, 10000));
  EXPECT_TRUE(failed.at(0).at(0).toString().contains("/nonexistent/est.txt"));
}

}  // namespace
}  // namespace sightline

namespace sightline {
namespace {

TEST(DemoGenerator, MakesReadableRecordingsOnceThenReusesThem) {
  const QString folder = QString::fromStdString(testing::TempDir("demo") + "/demo");
  {
    DemoGenerator demo(folder, nullptr, 6, 4);
    QSignalSpy ready(&demo, &DemoGenerator::Ready);
    QSignalSpy progress(&demo, &DemoGenerator::Progress);
    demo.Start();
    ASSERT_TRUE(QTest::qWaitFor([&] { return ready.count() == 1; }, 120000));
    EXPECT_GE(progress.count(), 10);
    EXPECT_EQ(ready.at(0).at(0).toString(), demo.corridor_path());
  }
  // The corridor opens as RGB-D with ground truth, in the main window.
  MainWindow window;
  window.show();
  QSignalSpy opened(&window, &MainWindow::DatasetOpened);
  window.OpenPath(folder + "/corridor");
  ASSERT_TRUE(QTest::qWaitFor([&] { return opened.count() == 1; }, 20000));
  ASSERT_NE(window.playback()->info(), nullptr);
  EXPECT_EQ(window.playback()->info()->kind, SourceKind::kRgbd);
  EXPECT_EQ(window.playback()->info()->frame_count, 6);
  EXPECT_TRUE(window.playback()->info()->has_ground_truth);
  // A second start finds the complete demo and renders nothing.
  DemoGenerator again(folder, nullptr, 6, 4);
  QSignalSpy ready(&again, &DemoGenerator::Ready);
  QSignalSpy progress(&again, &DemoGenerator::Progress);
  again.Start();
  ASSERT_TRUE(QTest::qWaitFor([&] { return ready.count() == 1; }, 5000));
  EXPECT_EQ(progress.count(), 0);
}

}  // namespace
}  // namespace sightline

namespace sightline {
namespace {

TEST(MainWindow, PlaysAnOniRecording) {
  SIGHTLINE_REQUIRE_DATA(oni, "oni_livingroom/test.oni");
  MainWindow window;
  window.show();
  QSignalSpy opened(&window, &MainWindow::DatasetOpened);
  window.OpenPath(QString::fromStdString(oni));
  ASSERT_TRUE(QTest::qWaitFor([&] { return opened.count() == 1; }, 20000));
  EXPECT_EQ(window.playback()->info()->frame_count, 12);
  QSignalSpy shown(&window, &MainWindow::FrameShown);
  for (int i = 0; i < 3; ++i) {
    window.playback()->Step();
    ASSERT_TRUE(QTest::qWaitFor([&] { return shown.count() == i + 1; }, 10000)) << "step " << i;
  }
  EXPECT_EQ(shown.at(2).at(0).value<int64_t>(), 2);
}

}  // namespace
}  // namespace sightline

namespace sightline {
namespace {

TEST(MainWindow, SensorsMenuListsEveryDriverWithItsAvailability) {
  MainWindow window;
  QMenu* sensors = nullptr;
  for (QAction* action : window.menuBar()->actions()) {
    if (action->menu() && action->text().contains("Sensors")) sensors = action->menu();
  }
  ASSERT_NE(sensors, nullptr);
  // One action per driver (openni2, aravis, v4l2, replay); Record and Stop follow a separator.
  QList<QAction*> drivers;
  for (QAction* action : sensors->actions()) {
    if (action->isSeparator()) break;
    drivers.push_back(action);
  }
  ASSERT_EQ(drivers.size(), 4);
  // No /dev/video* on the build machine: the webcam driver is greyed out and says why.
  bool webcam_checked = false;
  for (QAction* action : drivers) {
    if (!action->isEnabled()) {
      EXPECT_FALSE(action->toolTip().isEmpty());
      EXPECT_TRUE(action->text().contains("unavailable"));
    }
    if (action->toolTip().contains("/dev/video")) webcam_checked = !action->isEnabled();
  }
  if (!QDir("/dev").entryList({"video*"}, QDir::System).isEmpty())
    GTEST_SKIP() << "a webcam exists";
  EXPECT_TRUE(webcam_checked);
}

}  // namespace
}  // namespace sightline

namespace sightline {
namespace {

TEST(MappingPresenter, DrawsOccupancyAndMapWhilePlayingAndRedrawsOnAThresholdChange) {
  const std::string dir = testing::TempDir("gui_mapping") + "/corridor";
  sim::SimulationOptions options = sim::SimulationOptions::ForScene("corridor");
  options.frames = 14;
  options.sensors = "rgbd";
  ASSERT_TRUE(sim::Simulate(options, dir).ok());

  MainWindow window;
  auto* mapping = new MappingPresenter();
  window.AddPipeline(mapping);
  ASSERT_TRUE(window.ActivatePipeline(mapping->Title()));
  window.show();
  QSignalSpy opened(&window, &MainWindow::DatasetOpened);
  window.OpenPath(QString::fromStdString(dir));
  ASSERT_TRUE(QTest::qWaitFor([&] { return opened.count() == 1; }, 20000));
  QSignalSpy shown(&window, &MainWindow::FrameShown);
  // Five frames calibrate the floor; then every frame maps; the map renders every 10th frame.
  for (int i = 0; i < 12; ++i) {
    window.playback()->Step();
    ASSERT_TRUE(QTest::qWaitFor([&] { return shown.count() == i + 1; }, 20000)) << "step " << i;
  }
  EXPECT_FALSE(mapping->occupancy_view()->image().isNull());
  // Both views say what their colours mean: cells, scan rays, wall classes, the floor.
  EXPECT_EQ(mapping->occupancy_view()->keys().size(), 8u);
  ASSERT_EQ(window.scene_view()->keys().size(), 7u);
  EXPECT_EQ(window.scene_view()->keys()[3].label, "floor");
  EXPECT_EQ(window.scene_view()->keys()[5].label, "map: occupied");
  EXPECT_FALSE(mapping->map_view()->image().isNull());
  // The stitched map's own key: free, unknown, occupied, the path.
  EXPECT_EQ(mapping->map_view()->keys().size(), 4u);
  // The 3D view shows the floor grid, the walls found beside the cloud, and the stitched map on
  // the floor with the path over it.
  for (const std::string& layer : MappingPresenter::SceneLayers()) {
    EXPECT_TRUE(window.scene_view()->HasLayer(layer)) << layer;
  }
  // The map plane renders: seen alone (the depth cloud's floor points lie over it), its free
  // cells' green and occupied cells' red show, and hiding the layer takes them away.
  const std::string map_layer = MappingPresenter::SceneLayers()[4];
  ASSERT_EQ(map_layer, "mapping/stitched_map");
  SceneView* scene = window.scene_view();
  for (const std::string& layer : scene->LayerNames()) scene->SetLayerVisible(layer, false);
  scene->SetLayerVisible(map_layer, true);
  const auto count = [](const QImage& image, QColor want) {
    int n = 0;
    for (int y = 0; y < image.height(); ++y) {
      for (int x = 0; x < image.width(); ++x) {
        const QColor c = image.pixelColor(x, y);
        n += std::abs(c.red() - want.red()) + std::abs(c.green() - want.green()) +
                 std::abs(c.blue() - want.blue()) <
             30;
      }
    }
    return n;
  };
  const QColor free_green(60, 160, 60), occupied_red(220, 40, 40);
  scene->ResetView();
  const QImage with_map = scene->grabFramebuffer();
  const QByteArray shots = qgetenv("SIGHTLINE_TEST_SCREENSHOT_DIR");
  if (!shots.isEmpty()) with_map.save(QString::fromUtf8(shots) + "/mapping_scene_map.png");
  EXPECT_GT(count(with_map, free_green), 300);
  EXPECT_GT(count(with_map, occupied_red), 20);
  scene->SetLayerVisible(map_layer, false);
  const QImage without_map = scene->grabFramebuffer();
  EXPECT_EQ(count(without_map, free_green) + count(without_map, occupied_red), 0);
  for (const std::string& layer : scene->LayerNames()) scene->SetLayerVisible(layer, true);

  // A threshold change while paused re-runs the current frame at once.
  const int before = shown.count();
  auto* panel = window.findChild<ParameterPanel*>();
  ASSERT_NE(panel, nullptr);
  OptionSet changed = panel->options();
  ASSERT_TRUE(changed.ApplyOverride("mapping.ransac.max_iterations=100").ok());
  panel->SetOptions(changed);
  emit panel->OptionsChanged(changed);
  ASSERT_TRUE(QTest::qWaitFor([&] { return shown.count() > before; }, 20000));
  EXPECT_EQ(shown.last().at(0).value<int64_t>(), 11);  // The same frame again.

  // Calibrate floor: the saved calibration holds the simulated camera height; a new fit starts
  // from the next frame.
  const std::string floor_file = testing::TempDir("gui_mapping") + "/floor.yaml";
  ASSERT_TRUE(mapping->SaveFloor(QString::fromStdString(floor_file)).ok());
  StatusOr<FloorCalibration> floor = ReadFloorCalibration(floor_file);
  ASSERT_TRUE(floor.ok()) << floor.status().ToString();
  EXPECT_NEAR(floor->plane.CameraHeightM(), options.motion.camera_height_m, 0.03);
  QSignalSpy messages(mapping, &PipelinePresenter::Message);
  mapping->RecalibrateFloor();
  const int stepped = shown.count();
  window.playback()->Step();
  ASSERT_TRUE(QTest::qWaitFor([&] { return shown.count() > stepped; }, 20000));
  bool calibrating = false;
  for (const auto& m : messages)
    calibrating |= m.at(1).toString().contains("calibrating the floor (1 of");
  EXPECT_TRUE(calibrating);
}

}  // namespace
}  // namespace sightline

namespace sightline {
namespace {

TEST(StereoVoPresenter, DrawsTracksAndATrajectoryThatFollowsKittiGroundTruth) {
  SIGHTLINE_REQUIRE_DATA(dir, "kitti_clip1");
  MainWindow window;
  auto* vo = new StereoVoPresenter();
  window.AddPipeline(vo);
  ASSERT_TRUE(window.ActivatePipeline(vo->Title()));
  window.show();
  QSignalSpy opened(&window, &MainWindow::DatasetOpened);
  window.OpenPath(QString::fromStdString(dir));
  ASSERT_TRUE(QTest::qWaitFor([&] { return opened.count() == 1; }, 20000));
  QSignalSpy shown(&window, &MainWindow::FrameShown);
  constexpr int kFrames = 6;
  for (int i = 0; i < kFrames; ++i) {
    window.playback()->Step();
    ASSERT_TRUE(QTest::qWaitFor([&] { return shown.count() == i + 1; }, 20000)) << "step " << i;
  }
  EXPECT_FALSE(vo->tracks_view()->image().isNull());
  ASSERT_EQ(vo->estimate().size(), static_cast<size_t>(kFrames));
  EXPECT_TRUE(window.scene_view()->HasLayer("vo/estimate"));
  EXPECT_TRUE(window.scene_view()->HasLayer("vo/ground_truth"));
  // The car drives about 1.2 m per frame; the estimate's length over 5 steps is within 5 % of it.
  auto gt = OpenDataset(dir, SourceKind::kStereo);
  ASSERT_TRUE(gt.ok());
  Trajectory truth;
  for (int i = 0; i < kFrames; ++i)
    truth.mutable_poses().push_back((*gt)->ground_truth()->poses()[i]);
  EXPECT_NEAR(vo->estimate().LengthM(), truth.LengthM(), 0.05 * truth.LengthM());
  // The 3D view follows the growing trajectory: re-fitted as it left the fitted box (the car
  // covers about 6 m, more than the first fit's margin), and the last fit holds every pose.
  EXPECT_GE(vo->view_fits(), 2);
  for (const TimedPose& p : vo->estimate().poses()) {
    EXPECT_TRUE(vo->fitted_box().contains(p.world_from_sensor.translation()));
  }
  // Per-frame statistics plotted over time, one sample per frame shown.
  const TimeSeriesPlot* counts = vo->counts_plot();
  ASSERT_NE(counts, nullptr);
  for (const QString& name : {"tracks", "stereo", "inliers", "RANSAC it."}) {
    EXPECT_EQ(counts->Samples(name).size(), static_cast<size_t>(kFrames)) << name.toStdString();
  }
  // Frame 0 has no tracks; later frames track hundreds of features with most of them inliers.
  const std::vector<QPointF> tracks = counts->Samples("tracks");
  const std::vector<QPointF> inliers = counts->Samples("inliers");
  EXPECT_EQ(tracks.front().y(), 0);
  for (int i = 1; i < kFrames; ++i) {
    EXPECT_GT(tracks[i].y(), 100) << "frame " << i;
    EXPECT_GT(inliers[i].y(), 0.5 * tracks[i].y()) << "frame " << i;
  }
  for (const QString& stage : {"tracking", "matching", "RANSAC", "refine", "total"}) {
    EXPECT_EQ(vo->timing_plot()->Samples(stage).size(), static_cast<size_t>(kFrames));
  }
  EXPECT_GT(vo->timing_plot()->Samples("total").back().y(), 0);
  EXPECT_EQ(vo->residual_plot()->Samples("residual").size(), static_cast<size_t>(kFrames));
  EXPECT_TRUE(vo->residual_plot()->Markers().empty());  // No frame of the clip is gated.
}

TEST(MonoSlamPresenter, DrawsTheMapKeyframesAndTrajectoryOnKittiLeftImages) {
  SIGHTLINE_REQUIRE_DATA(dir, "kitti_clip1");
  MainWindow window;
  auto* mono = new MonoSlamPresenter();
  window.AddPipeline(mono);
  ASSERT_TRUE(window.ActivatePipeline(mono->Title()));
  window.show();
  QSignalSpy opened(&window, &MainWindow::DatasetOpened);
  window.OpenPath(QString::fromStdString(dir));
  ASSERT_TRUE(QTest::qWaitFor([&] { return opened.count() == 1; }, 20000));
  QSignalSpy shown(&window, &MainWindow::FrameShown);
  constexpr int kFrames = 8;
  for (int i = 0; i < kFrames; ++i) {
    window.playback()->Step();
    ASSERT_TRUE(QTest::qWaitFor([&] { return shown.count() == i + 1; }, 30000)) << "step " << i;
  }
  EXPECT_FALSE(mono->image_view()->image().isNull());
  // Initialised within the first frames: the two first keyframes and their points are drawn.
  EXPECT_GE(mono->keyframes_drawn(), 2u);
  EXPECT_GT(mono->points_drawn(), 50u);
  EXPECT_TRUE(window.scene_view()->HasLayer("mono/map"));
  EXPECT_TRUE(window.scene_view()->HasLayer("mono/keyframes"));
  EXPECT_TRUE(window.scene_view()->HasLayer("mono/trajectory"));
  // The 3D view was fitted to the path as it started (View > Follow is on by default).
  EXPECT_GE(window.scene_view()->follow_fits(), 1);
}

}  // namespace
}  // namespace sightline
