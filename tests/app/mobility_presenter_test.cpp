// The mobility map in the main window under an X server: play real RGB-D frames, look at the
// projection's pixels, the timing table and the 3D layers, and re-run a frame on an option change.
#include "app/sightline/mobility_presenter.h"

#include <gtest/gtest.h>

#include <QSignalSpy>
#include <QTableWidget>
#include <QTest>
#include <cmath>

#include "app/sightline/main_window.h"
#include "app/sightline/mobility_views.h"
#include "app/sightline/playback_controller.h"
#include "core/io/floor_file.h"
#include "core/pipeline/mobility_pipeline.h"
#include "tests/support/test_data.h"
#include "widgets/image_view.h"
#include "widgets/parameter_panel.h"
#include "widgets/scene_view.h"

namespace sightline {
namespace {

// Pixels of the image that are clearly green (the score colour of 1).
int GreenPixels(const QImage& image) {
  int count = 0;
  for (int y = 0; y < image.height(); y += 2) {
    for (int x = 0; x < image.width(); x += 2) {
      const QColor c = image.pixelColor(x, y);
      count += c.green() > 120 && c.green() > c.red() + 60 && c.green() > c.blue() + 60;
    }
  }
  return count;
}

TEST(MobilityPresenter, ShowsScoredCloudProjectionAndTimingWhilePlayingTum) {
  SIGHTLINE_REQUIRE_DATA(path, "tum_fr1_desk");
  MainWindow window;
  auto* mobility = new MobilityPresenter();
  window.AddPipeline(mobility);
  ASSERT_TRUE(window.ActivatePipeline(mobility->Title()));
  window.show();
  QSignalSpy opened(&window, &MainWindow::DatasetOpened);
  window.OpenPath(QString::fromStdString(path));
  ASSERT_TRUE(QTest::qWaitFor([&] { return opened.count() == 1; }, 20000));
  QSignalSpy shown(&window, &MainWindow::FrameShown);
  for (int i = 0; i < 3; ++i) {
    window.playback()->Step();
    ASSERT_TRUE(QTest::qWaitFor([&] { return shown.count() == i + 1; }, 20000)) << "step " << i;
  }
  const QImage projection = mobility->images()->projection_view()->image();
  ASSERT_FALSE(projection.isNull());
  EXPECT_GT(GreenPixels(projection), 2000) << "the floor in the lower right is traversable";
  EXPECT_FALSE(mobility->images()->top_view()->image().isNull());
  // Ten stages and the total, with times.
  const QTableWidget* table = mobility->timing()->table();
  ASSERT_EQ(table->rowCount(), 11);
  EXPECT_EQ(table->item(3, 0)->text(), "normals");
  EXPECT_GT(table->item(10, 1)->text().toDouble(), 0.0);
  for (const std::string& layer : MobilityPresenter::SceneLayers()) {
    EXPECT_TRUE(window.scene_view()->HasLayer(layer)) << layer;
  }

  // An option change while paused re-runs the current frame with it.
  const int before = shown.count();
  auto* panel = window.findChild<ParameterPanel*>();
  ASSERT_NE(panel, nullptr);
  OptionSet changed = panel->options();
  ASSERT_TRUE(changed.ApplyOverride("mobility.grid_stride=8").ok());
  panel->SetOptions(changed);
  emit panel->OptionsChanged(changed);
  ASSERT_TRUE(QTest::qWaitFor([&] { return shown.count() > before; }, 20000));
  EXPECT_EQ(shown.last().at(0).value<int64_t>(), 2);  // The same frame again.
  EXPECT_EQ(table->item(0, 2)->text(), "307200");
  EXPECT_LT(table->item(1, 2)->text().toInt(), 640 * 480 / 64 + 1);  // 8 px stride.
}

// The GUI runs the registry's pipeline object, the one `sightline-cli run mobility` runs, so it
// honours every option the CLI does: mobility.run.floor_file gives the expected up direction.
TEST(MobilityPresenter, RunsTheRegistryPipelineWhichHonoursTheFloorFile) {
  MobilityPresenter presenter;
  EXPECT_EQ(presenter.info().name, "mobility");
  OptionSet options;
  ASSERT_TRUE(presenter.DeclareOptions(&options).ok());
  const std::string dir = testing::TempDir("gui_mobility_floor");
  FloorCalibration floor;
  floor.plane.normal = Eigen::Vector3d(0, -std::cos(0.4), std::sin(0.4));
  floor.plane.d = 1.2;
  ASSERT_TRUE(WriteFloorCalibration(floor, dir + "/floor.yaml").ok());
  ASSERT_TRUE(options.ApplyOverride("mobility.run.floor_file=" + dir + "/floor.yaml").ok());

  PipelineSource source;
  source.info.kind = SourceKind::kCloud;
  source.info.path = dir;
  std::unique_ptr<Pipeline> pipeline = presenter.CreateProcessor(source);
  ASSERT_NE(pipeline, nullptr);
  EXPECT_NE(dynamic_cast<MobilityPipeline*>(pipeline.get()), nullptr);
  ASSERT_TRUE(pipeline->Configure(options).ok());
  ASSERT_TRUE(pipeline->Open(source).ok());
  // An organized 61 x 61 patch of the floor 1.2 m below the camera, 1-4 m ahead.
  CloudFrame frame;
  auto cloud = std::make_shared<PointCloud>();
  const Eigen::Vector3d n = floor.plane.normal;
  const Eigen::Vector3d ahead = (Eigen::Vector3d::UnitZ() - n.z() * n).normalized();
  const Eigen::Vector3d side = n.cross(ahead);
  for (int i = 0; i <= 60; ++i) {
    for (int j = -30; j <= 30; ++j) {
      const Eigen::Vector3d p = -1.2 * n + (1.0 + 0.05 * i) * ahead + 0.05 * j * side;
      cloud->points.push_back(p.cast<float>());
    }
  }
  cloud->width = 61;
  cloud->height = 61;
  frame.cloud = cloud;
  StatusOr<std::shared_ptr<const PipelineResult>> result = pipeline->Process(Frame(frame));
  ASSERT_TRUE(result.ok()) << result.status().ToString();
  const auto* mobility = dynamic_cast<const MobilityFrameResult*>(result->get());
  ASSERT_NE(mobility, nullptr);
  ASSERT_NE(mobility->mobility, nullptr);
  EXPECT_LT((mobility->mobility->expected_up - n).norm(), 1e-6);
}

}  // namespace
}  // namespace sightline
