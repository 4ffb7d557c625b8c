// Renders real OpenGL through VTK inside the Qt6 widget (run under Xvfb) and checks the pixels,
// so a black or empty view fails.
#include "widgets/scene_view.h"

#include <gtest/gtest.h>

#include <QApplication>
#include <QElapsedTimer>
#include <QImage>
#include <QLabel>
#include <QTest>
#include <QWheelEvent>
#include <cmath>
#include <functional>
#include <limits>
#include <memory>
#include <opencv2/core.hpp>

#include "core/common/frame.h"
#include "core/common/trajectory.h"

namespace sightline {
namespace {

const QColor kBackground(0, 0, 0);

// A w x h organized cloud on the plane z = depth, spanning [-1, 1] x [-0.75, 0.75] metres, all of
// one colour (or uncoloured), with every 7th point NaN.
std::shared_ptr<PointCloud> MakePlane(int w, int h, double depth, const QColor* color) {
  auto cloud = std::make_shared<PointCloud>();
  cloud->width = w;
  cloud->height = h;
  cloud->points.reserve(static_cast<size_t>(w) * h);
  const float nan = std::numeric_limits<float>::quiet_NaN();
  for (int r = 0; r < h; ++r) {
    for (int c = 0; c < w; ++c) {
      const size_t i = cloud->points.size();
      if (i % 7 == 3) {
        cloud->points.emplace_back(nan, nan, nan);
      } else {
        cloud->points.emplace_back(-1.f + 2.f * c / (w - 1), -0.75f + 1.5f * r / (h - 1),
                                   static_cast<float>(depth + 0.2 * c / (w - 1)));
      }
    }
  }
  if (color != nullptr) {
    cloud->colors.assign(cloud->points.size(),
                         Eigen::Matrix<uint8_t, 3, 1>(color->red(), color->green(), color->blue()));
  }
  return cloud;
}

int CountPixels(const QImage& image, const std::function<bool(QColor)>& match) {
  int count = 0;
  for (int y = 0; y < image.height(); ++y) {
    for (int x = 0; x < image.width(); ++x) count += match(image.pixelColor(x, y)) ? 1 : 0;
  }
  return count;
}

bool IsBackground(QColor c) {
  return std::abs(c.red() - kBackground.red()) + std::abs(c.green() - kBackground.green()) +
             std::abs(c.blue() - kBackground.blue()) <
         12;
}

void SaveScreenshot(const QImage& image, const char* name) {
  const QByteArray dir = qgetenv("SIGHTLINE_TEST_SCREENSHOT_DIR");
  if (!dir.isEmpty()) image.save(QString::fromUtf8(dir) + "/" + name);
}

class SceneViewTest : public ::testing::Test {
 protected:
  void SetUp() override {
    view_ = std::make_unique<SceneView>();
    view_->SetBackground(kBackground);
    view_->SetGroundGrid(false);
    view_->resize(640, 480);
    view_->show();
    ASSERT_TRUE(QTest::qWaitForWindowExposed(view_.get()));
  }

  std::unique_ptr<SceneView> view_;
};

TEST_F(SceneViewTest, ColouredCloudRendersInItsColourAndDisappearsWhenRemoved) {
  const QColor red(255, 0, 0);
  auto cloud = MakePlane(600, 500, 3.0, &red);  // 300k points, 1/7 NaN.
  QElapsedTimer timer;
  timer.start();
  view_->SetPointCloud("cloud", cloud, SceneView::ColorMode::kRgb, 3.0);
  const qint64 set_ms = timer.elapsed();
  RecordProperty("set_point_cloud_300k_ms", static_cast<int>(set_ms));
  EXPECT_LT(set_ms, 2000) << "converting 300k points must not stall the GUI";
  cloud.reset();  // The view must not depend on the caller keeping the cloud.
  view_->ResetView();

  const QImage with_cloud = view_->grabFramebuffer();
  SaveScreenshot(with_cloud, "scene_view_cloud.png");
  ASSERT_EQ(with_cloud.size(), QSize(640, 480) * view_->devicePixelRatio());
  const int total = with_cloud.width() * with_cloud.height();
  const int red_pixels = CountPixels(
      with_cloud, [](QColor c) { return c.red() > 220 && c.green() < 40 && c.blue() < 40; });
  EXPECT_GT(red_pixels, total / 5) << "the fitted plane should cover much of the view";
  const QColor center = with_cloud.pixelColor(with_cloud.width() / 2, with_cloud.height() / 2);
  EXPECT_GT(center.red(), 220);
  EXPECT_LT(center.green(), 40);
  EXPECT_LT(center.blue(), 40);

  view_->RemoveLayer("cloud");
  EXPECT_FALSE(view_->HasLayer("cloud"));
  const QImage empty = view_->grabFramebuffer();
  SaveScreenshot(empty, "scene_view_removed.png");
  EXPECT_EQ(CountPixels(empty, [](QColor c) { return !IsBackground(c); }), 0);
}

TEST_F(SceneViewTest, FirstGeometryIsFittedWithoutResetView) {
  const QColor red(255, 0, 0);
  view_->SetPointCloud("cloud", std::make_shared<PointCloud>(), SceneView::ColorMode::kRgb);
  // Far away from the default view: only an automatic fit brings it into sight.
  auto far = MakePlane(100, 75, 3.0, &red);
  for (Eigen::Vector3f& p : far->points) p += Eigen::Vector3f(40, 0, 60);
  view_->SetPointCloud("cloud", far, SceneView::ColorMode::kRgb, 4.0);
  const QImage image = view_->grabFramebuffer();
  const int red_pixels =
      CountPixels(image, [](QColor c) { return c.red() > 220 && c.green() < 40; });
  EXPECT_GT(red_pixels, image.width() * image.height() / 5);
}

TEST_F(SceneViewTest, LinesRenderInTheirColour) {
  std::vector<SceneView::Segment> segments;
  for (int i = -5; i <= 5; ++i) {
    segments.push_back({Eigen::Vector3d(i * 0.2, -1, 3), Eigen::Vector3d(i * 0.2, 1, 3)});
  }
  view_->SetLines("lines", segments, QColor(0, 255, 0), 3.0);
  const QImage image = view_->grabFramebuffer();
  SaveScreenshot(image, "scene_view_lines.png");
  const int green =
      CountPixels(image, [](QColor c) { return c.green() > 200 && c.red() < 60 && c.blue() < 60; });
  EXPECT_GT(green, 1000);
}

TEST_F(SceneViewTest, UncolouredCloudIsColouredByDepth) {
  auto cloud = MakePlane(200, 150, 2.0, nullptr);
  view_->SetPointCloud("depth", cloud, SceneView::ColorMode::kAuto, 3.0);
  const QImage image = view_->grabFramebuffer();
  SaveScreenshot(image, "scene_view_depth.png");
  // The depth ramp spans the turbo map: both bluish and reddish pixels appear.
  EXPECT_GT(CountPixels(image, [](QColor c) { return c.blue() > 150 && c.red() < 100; }), 500);
  EXPECT_GT(CountPixels(image, [](QColor c) { return c.red() > 150 && c.blue() < 100; }), 500);
}

TEST_F(SceneViewTest, TrajectoryPosesAndFrustaRender) {
  Trajectory trajectory;
  std::vector<Eigen::Isometry3d> poses;
  for (int i = 0; i < 10; ++i) {
    Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
    pose.translation() = Eigen::Vector3d(0.3 * i - 1.5, 0.1 * std::sin(i), 0.2 * i);
    trajectory.Add(i * 0.1, pose);
    poses.push_back(pose);
  }
  view_->SetTrajectory("path", trajectory, Qt::yellow);
  view_->SetPoses("axes", poses, QColor(), 0.2);
  view_->SetFrusta("cameras", poses, Qt::cyan, 0.25);
  view_->ResetView();
  const QImage image = view_->grabFramebuffer();
  SaveScreenshot(image, "scene_view_trajectory.png");
  EXPECT_GT(CountPixels(image, [](QColor c) { return !IsBackground(c); }), 500);
  EXPECT_EQ(view_->LayerNames(), (std::vector<std::string>{"axes", "cameras", "path"}));
}

// An image on a plane keeps its orientation (its top rows at the `up` end) and updates in place.
TEST_F(SceneViewTest, ImagePlaneShowsItsImageUprightAndUpdatesInPlace) {
  // Top half red, bottom half blue (BGR), on a 2 m x 2 m plane facing the default camera
  // (optical frame: y down, so the image's up is -y).
  cv::Mat image(40, 60, CV_8UC3, cv::Scalar(255, 0, 0));
  image.rowRange(0, 20).setTo(cv::Scalar(0, 0, 255));
  view_->SetImagePlane("map", image, {-1, 1, 3}, {2, 0, 0}, {0, -2, 0});
  view_->ResetView();
  QImage shot = view_->grabFramebuffer();
  SaveScreenshot(shot, "scene_view_image_plane.png");
  const auto red = [](QColor c) { return c.red() > 200 && c.green() < 50 && c.blue() < 50; };
  const auto blue = [](QColor c) { return c.blue() > 200 && c.red() < 50 && c.green() < 50; };
  const int w = shot.width(), h = shot.height();
  const QImage top = shot.copy(0, 0, w, h / 2), bottom = shot.copy(0, h / 2, w, h - h / 2);
  EXPECT_GT(CountPixels(top, red), w * h / 10) << "the image's top rows belong at the top";
  EXPECT_GT(CountPixels(bottom, blue), w * h / 10);
  EXPECT_LT(CountPixels(top, blue), w * h / 100);
  EXPECT_LT(CountPixels(bottom, red), w * h / 100);

  // A new image (grey, larger) replaces the texels of the same layer.
  view_->SetImagePlane("map", cv::Mat(80, 120, CV_8UC1, cv::Scalar(0)), {-1, 1, 3}, {2, 0, 0},
                       {0, -2, 0});
  shot = view_->grabFramebuffer();
  EXPECT_EQ(CountPixels(shot, red) + CountPixels(shot, blue), 0);
  EXPECT_EQ(view_->LayerNames(), std::vector<std::string>{"map"});
}

TEST_F(SceneViewTest, UpdatesCoalesceIntoOneRender) {
  (void)view_->grabFramebuffer();
  const int64_t before = view_->render_count();
  const QColor red(255, 0, 0);
  for (int i = 0; i < 5; ++i) {
    view_->SetPointCloud("cloud", MakePlane(50, 40, 2.0 + i, &red), SceneView::ColorMode::kRgb);
  }
  view_->SetBackground(QColor(20, 20, 20));
  (void)view_->grabFramebuffer();
  EXPECT_EQ(view_->render_count(), before + 1);
  // Nothing changed: a repaint only blits, it does not render again.
  (void)view_->grabFramebuffer();
  EXPECT_EQ(view_->render_count(), before + 1);
}

TEST_F(SceneViewTest, MouseDragRotatesTheCamera) {
  const QColor red(255, 0, 0);
  view_->SetPointCloud("cloud", MakePlane(200, 150, 3.0, &red), SceneView::ColorMode::kRgb);
  view_->ResetView();
  const QImage before = view_->grabFramebuffer();
  QTest::mousePress(view_.get(), Qt::LeftButton, {}, QPoint(320, 240));
  for (int x = 330; x <= 520; x += 10) QTest::mouseMove(view_.get(), QPoint(x, 250));
  QTest::mouseRelease(view_.get(), Qt::LeftButton, {}, QPoint(520, 250));
  const QImage after = view_->grabFramebuffer();
  EXPECT_NE(before, after);
}

TEST_F(SceneViewTest, WheelZoomsAndExitKeysAreIgnored) {
  const QColor red(255, 0, 0);
  view_->SetPointCloud("cloud", MakePlane(200, 150, 3.0, &red), SceneView::ColorMode::kRgb);
  view_->ResetView();
  const QImage before = view_->grabFramebuffer();
  const QPointF center(320, 240);
  QWheelEvent wheel(center, view_->mapToGlobal(center), QPoint(), QPoint(0, 120), Qt::NoButton,
                    Qt::NoModifier, Qt::NoScrollPhase, false);
  QApplication::sendEvent(view_.get(), &wheel);
  const QImage zoomed = view_->grabFramebuffer();
  const auto is_red = [](QColor c) { return c.red() > 220 && c.green() < 40; };
  EXPECT_GT(CountPixels(zoomed, is_red), CountPixels(before, is_red)) << "zoomed in";
  // The trackball style maps 'q' and 'e' to "exit"; inside an application they must do nothing.
  QTest::keyClick(view_.get(), Qt::Key_Q);
  QTest::keyClick(view_.get(), Qt::Key_E);
  EXPECT_FALSE(view_->grabFramebuffer().isNull());
}

// A key to the layers' colours sits in the top-left corner, its swatches in their colours; it
// stays out of the way of the mouse, and goes with ClearLayers.
// A cloud set while its layer is hidden is drawn when the layer is shown again (it is built
// then), and setting a layer again replaces what it showed (the actor is updated in place).
TEST_F(SceneViewTest, AHiddenLayersCloudShowsWhenShownAndUpdatesReplaceTheOldGeometry) {
  const QColor red(255, 0, 0), green(0, 255, 0);
  view_->SetPointCloud("cloud", MakePlane(200, 150, 3.0, &red), SceneView::ColorMode::kRgb, 3.0);
  view_->ResetView();
  view_->SetLayerVisible("cloud", false);
  EXPECT_FALSE(view_->IsLayerVisible("cloud"));
  view_->SetPointCloud("cloud", MakePlane(200, 150, 3.0, &green), SceneView::ColorMode::kRgb, 3.0);
  const auto is_red = [](QColor c) { return c.red() > 220 && c.green() < 40 && c.blue() < 40; };
  const auto is_green = [](QColor c) { return c.green() > 220 && c.red() < 40 && c.blue() < 40; };
  QImage shot = view_->grabFramebuffer();
  EXPECT_EQ(CountPixels(shot, is_red) + CountPixels(shot, is_green), 0) << "hidden, yet drawn";
  view_->SetLayerVisible("cloud", true);
  shot = view_->grabFramebuffer();
  EXPECT_GT(CountPixels(shot, is_green), shot.width() * shot.height() / 10)
      << "the cloud set while hidden did not show";
  EXPECT_EQ(CountPixels(shot, is_red), 0) << "the replaced cloud still shows";
  view_->SetPointCloud("cloud", MakePlane(200, 150, 3.0, &red), SceneView::ColorMode::kRgb, 3.0);
  shot = view_->grabFramebuffer();
  EXPECT_GT(CountPixels(shot, is_red), shot.width() * shot.height() / 10);
  EXPECT_EQ(CountPixels(shot, is_green), 0);
  EXPECT_EQ(view_->LayerNames(), std::vector<std::string>{"cloud"});
}

TEST_F(SceneViewTest, KeysNameTheLayersColoursUntilTheLayersAreCleared) {
  ASSERT_NE(view_->keys_label(), nullptr);
  EXPECT_FALSE(view_->keys_label()->isVisible());
  view_->SetKeys({{QColor(255, 80, 80), "estimate"}, {QColor(80, 160, 255), "ground truth"}});
  QLabel* label = view_->keys_label();
  EXPECT_TRUE(label->isVisible());
  EXPECT_TRUE(label->text().contains("ground truth"));
  EXPECT_TRUE(label->testAttribute(Qt::WA_TransparentForMouseEvents));
  EXPECT_LT(label->geometry().right(), view_->width() / 2) << "the key covers the view";
  const QImage image = label->grab().toImage();
  SaveScreenshot(image, "scene_view_keys.png");
  int red = 0, blue = 0;
  for (int y = 0; y < image.height(); ++y) {
    for (int x = 0; x < image.width(); ++x) {
      const QColor c = image.pixelColor(x, y);
      red += std::abs(c.red() - 255) + std::abs(c.green() - 80) + std::abs(c.blue() - 80) < 40;
      blue += std::abs(c.red() - 80) + std::abs(c.green() - 160) + std::abs(c.blue() - 255) < 40;
    }
  }
  EXPECT_GT(red, 10) << "no swatch in the estimate's colour";
  EXPECT_GT(blue, 10) << "no swatch in the ground truth's colour";
  view_->ClearLayers();
  EXPECT_FALSE(label->isVisible());
  EXPECT_TRUE(view_->keys().empty());
}

TEST(SceneViewComposed, OpticalFrameSceneWithGridLooksLikeARoboticsViewer) {
  SceneView view;
  view.resize(800, 600);
  view.show();
  ASSERT_TRUE(QTest::qWaitForWindowExposed(&view));
  // A floor 1.2 m below the camera (y down) and a wall 4 m ahead, coloured by height.
  auto room = std::make_shared<PointCloud>();
  for (int i = 0; i < 200; ++i) {
    for (int j = 0; j < 200; ++j) {
      const float a = -2.f + 4.f * i / 199, b = 4.f * j / 199;
      room->points.emplace_back(a, 1.2f, b);               // Floor.
      room->points.emplace_back(a, 1.2f - 0.6f * b, 4.f);  // Wall, up to 1.2 m above the camera.
    }
  }
  room->width = static_cast<int>(room->points.size());
  Trajectory path;
  std::vector<Eigen::Isometry3d> cameras;
  for (int i = 0; i < 8; ++i) {
    Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
    pose.translation() = Eigen::Vector3d(0.25 * i - 1.0, 0.0, 0.3 * i);
    pose.linear() = Eigen::AngleAxisd(0.08 * i, Eigen::Vector3d::UnitY()).toRotationMatrix();
    path.Add(0.1 * i, pose);
    cameras.push_back(pose);
  }
  view.SetGroundGrid(true, 0.5, 16, -1.2);
  view.SetPointCloud("room", room, SceneView::ColorMode::kHeight, 2.0);
  view.SetTrajectory("path", path, Qt::yellow, 3.0);
  view.SetFrusta("cameras", cameras, Qt::cyan, 0.3);
  view.SetPoses("axes", {Eigen::Isometry3d::Identity()}, QColor(), 0.5);
  view.ResetView();
  const QImage image = view.grabFramebuffer();
  SaveScreenshot(image, "scene_view_composed.png");
  // Floor (low, blue end of the map) at the bottom of the image, wall top (red end) higher up.
  int floor_rows = 0, wall_rows = 0;
  for (int y = 0; y < image.height(); ++y) {
    const QColor c = image.pixelColor(image.width() / 2, y);
    if (y > image.height() / 2 && c.blue() > 120 && c.red() < 80) ++floor_rows;
    if (y < image.height() / 2 && c.red() > 150 && c.blue() < 80) ++wall_rows;
  }
  EXPECT_GT(floor_rows, 10) << "the floor (y down = low) should appear below the centre";
  EXPECT_GT(wall_rows, 5) << "the top of the wall should appear above the centre";
}

TEST(SceneViewLifetime, ManyViewsCanBeCreatedAndDestroyed) {
  for (int i = 0; i < 3; ++i) {
    SceneView view;
    view.resize(200, 150);
    view.show();
    ASSERT_TRUE(QTest::qWaitForWindowExposed(&view));
    view.SetLines("l", {{Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitZ()}}, Qt::white);
    EXPECT_FALSE(view.grabFramebuffer().isNull());
  }
}

}  // namespace
}  // namespace sightline
