#include "widgets/image_view.h"

#include <gtest/gtest.h>

#include <QApplication>
#include <QPainter>
#include <QTest>
#include <QWheelEvent>
#include <cmath>
#include <limits>
#include <opencv2/imgproc.hpp>

#include "widgets/color_map.h"

namespace sightline {
namespace {

// The widget's pixel that shows image pixel (u, v).
QColor WidgetPixel(const ImageView& view, const QImage& grab, double u, double v) {
  const QPointF p = view.ImageToWidget().map(QPointF(u, v));
  return grab.pixelColor(static_cast<int>(p.x()), static_cast<int>(p.y()));
}

bool Near(QColor a, QColor b, int tolerance = 3) {
  return std::abs(a.red() - b.red()) <= tolerance && std::abs(a.green() - b.green()) <= tolerance &&
         std::abs(a.blue() - b.blue()) <= tolerance;
}

void SaveScreenshot(const QImage& image, const char* name) {
  const QByteArray dir = qgetenv("SIGHTLINE_TEST_SCREENSHOT_DIR");
  if (!dir.isEmpty()) image.save(QString::fromUtf8(dir) + "/" + name);
}

class ImageViewTest : public ::testing::Test {
 protected:
  void SetUp() override { view_.resize(500, 400); }

  QImage Grab() { return view_.grab().toImage(); }

  ImageView view_;
};

TEST_F(ImageViewTest, GrayImageShowsItsGreyLevels) {
  cv::Mat gray(120, 160, CV_8UC1, cv::Scalar(77));
  gray(cv::Rect(0, 0, 80, 120)).setTo(200);
  view_.SetTitle("Left camera");
  view_.SetImage(gray);
  const QImage grab = Grab();
  EXPECT_TRUE(Near(WidgetPixel(view_, grab, 40, 60), QColor(200, 200, 200)));
  EXPECT_TRUE(Near(WidgetPixel(view_, grab, 120, 60), QColor(77, 77, 77)));
  EXPECT_FALSE(view_.legend_visible());
}

TEST_F(ImageViewTest, BgrImageShowsRgbColours) {
  cv::Mat bgr(100, 100, CV_8UC3, cv::Scalar(255, 0, 0));       // Blue in BGR order.
  bgr(cv::Rect(50, 0, 50, 100)).setTo(cv::Scalar(0, 0, 255));  // Red.
  view_.SetImage(bgr, ImageView::Kind::kBgr);
  const QImage grab = Grab();
  EXPECT_TRUE(Near(WidgetPixel(view_, grab, 20, 50), QColor(0, 0, 255)));
  EXPECT_TRUE(Near(WidgetPixel(view_, grab, 80, 50), QColor(255, 0, 0)));
}

TEST_F(ImageViewTest, KeepsAspectRatio) {
  view_.SetImage(cv::Mat(100, 400, CV_8UC1, cv::Scalar(0)));
  const QRectF shown = view_.ImageToWidget().mapRect(QRectF(-0.5, -0.5, 400, 100));
  EXPECT_NEAR(shown.width() / shown.height(), 4.0, 1e-6);
  EXPECT_LE(shown.width(), view_.width() + 1e-6);
}

TEST_F(ImageViewTest, DepthWithNanIsColouredWithBlackHolesAndALegend) {
  const float nan = std::numeric_limits<float>::quiet_NaN();
  cv::Mat depth(120, 160, CV_32FC1);
  for (int r = 0; r < depth.rows; ++r) {
    for (int c = 0; c < depth.cols; ++c) depth.at<float>(r, c) = 0.5f + 4.5f * c / (depth.cols - 1);
  }
  depth(cv::Rect(0, 0, 40, 120)).setTo(nan);
  view_.SetTitle("Depth");
  view_.SetDepthRange(0.5, 5.0);
  view_.SetImage(depth);
  ASSERT_TRUE(view_.legend_visible());
  EXPECT_EQ(view_.depth_range(), std::make_pair(0.5, 5.0));
  const QImage grab = Grab();
  SaveScreenshot(grab, "image_view_depth.png");

  EXPECT_TRUE(Near(WidgetPixel(view_, grab, 20, 60), Qt::black)) << "NaN must be black";
  const Rgb8 far = TurboColor(5.0, 0.5, 5.0);
  EXPECT_TRUE(Near(WidgetPixel(view_, grab, 159, 60), QColor(far.r, far.g, far.b), 6));
  const Rgb8 mid = TurboColor(0.5 + 4.5 * 100 / 159.0, 0.5, 5.0);
  EXPECT_TRUE(Near(WidgetPixel(view_, grab, 100, 60), QColor(mid.r, mid.g, mid.b), 8));

  // The legend: high values (red end) at the top, low values (dark blue) at the bottom.
  const QRect bar = view_.LegendBarRect();
  ASSERT_FALSE(bar.isEmpty());
  EXPECT_GT(bar.left(), view_.ImageToWidget().map(QPointF(159.5, 0)).x()) << "beside the image";
  const Rgb8 top = TurboColorMap()[255];
  const Rgb8 bottom = TurboColorMap()[0];
  EXPECT_TRUE(
      Near(grab.pixelColor(bar.center().x(), bar.top() + 3), QColor(top.r, top.g, top.b), 20));
  EXPECT_TRUE(Near(grab.pixelColor(bar.center().x(), bar.bottom() - 3),
                   QColor(bottom.r, bottom.g, bottom.b), 20));
}

TEST_F(ImageViewTest, AutomaticDepthRangeIgnoresInvalidValues) {
  cv::Mat depth(50, 50, CV_32FC1, cv::Scalar(2.0f));
  depth(cv::Rect(0, 0, 25, 50)).setTo(4.0f);
  depth.at<float>(0, 0) = std::numeric_limits<float>::infinity();
  depth.at<float>(1, 0) = 0.0f;
  view_.SetImage(depth, ImageView::Kind::kDepthMeters);
  EXPECT_NEAR(view_.depth_range().first, 2.0, 1e-6);
  EXPECT_NEAR(view_.depth_range().second, 4.0, 1e-6);
}

TEST_F(ImageViewTest, CopiesThePixels) {
  cv::Mat gray(10, 10, CV_8UC1, cv::Scalar(10));
  view_.SetImage(gray);
  gray.setTo(250);
  gray.release();
  EXPECT_EQ(view_.image().pixelColor(5, 5), QColor(10, 10, 10));
}

TEST_F(ImageViewTest, UnsupportedTypeShowsNoImage) {
  view_.SetImage(cv::Mat(10, 10, CV_16UC3, cv::Scalar(1, 2, 3)));
  EXPECT_TRUE(view_.image().isNull());
  EXPECT_FALSE(Grab().isNull());  // Paints a message instead of crashing.
}

TEST_F(ImageViewTest, OverlaysUseImageCoordinates) {
  view_.SetImage(cv::Mat(100, 100, CV_8UC1, cv::Scalar(0)));
  ImageOverlay overlay;
  overlay.rects.push_back({QRectF(20, 20, 60, 60), QColor(255, 0, 0), 3.0});
  overlay.texts.push_back({QPointF(5, 10), "label", Qt::white});
  overlay.points.push_back({QPointF(70, 30), Qt::yellow, 4.0});
  overlay.lines.push_back({QLineF(0, 99, 99, 0), Qt::cyan, 2.0});
  view_.SetOverlay(overlay);
  QPointF origin_seen;
  view_.SetOverlayPainter([&origin_seen](QPainter& painter, const QTransform& image_to_widget) {
    origin_seen = image_to_widget.map(QPointF(0, 0));
    painter.fillRect(QRectF(image_to_widget.map(QPointF(49.5, 49.5)), QSizeF(4, 4)), Qt::green);
  });
  const QImage grab = Grab();
  SaveScreenshot(grab, "image_view_overlay.png");
  const QTransform t = view_.ImageToWidget();
  EXPECT_EQ(origin_seen, t.map(QPointF(0, 0)));
  // The rectangle's left edge is at x = 19.5 in image coordinates.
  const QPointF edge = t.map(QPointF(19.5, 50));
  EXPECT_TRUE(Near(grab.pixelColor(static_cast<int>(edge.x()), static_cast<int>(edge.y())),
                   QColor(255, 0, 0), 60));
  const QPointF dot = t.map(QPointF(49.5, 49.5)) + QPointF(2, 2);
  EXPECT_EQ(grab.pixelColor(dot.toPoint()), QColor(Qt::green));
}

void Wheel(QWidget* widget, QPointF at, int delta) {
  QWheelEvent event(at, widget->mapToGlobal(at), QPoint(), QPoint(0, delta), Qt::NoButton,
                    Qt::NoModifier, Qt::NoScrollPhase, false);
  QApplication::sendEvent(widget, &event);
}

// The wheel zooms about the mouse (the image pixel under it stays under it), a drag pans the
// zoomed image, and a double click fits the whole image again.
TEST_F(ImageViewTest, WheelZoomsAboutTheMouseDragPansAndDoubleClickFits) {
  cv::Mat image(100, 200, CV_8UC1, cv::Scalar(0));
  image(cv::Rect(150, 20, 10, 10)).setTo(255);  // A white square to zoom in on.
  view_.SetImage(image);
  view_.show();
  ASSERT_TRUE(QTest::qWaitForWindowExposed(&view_));
  const QTransform fitted = view_.ImageToWidget();
  const QPointF square = fitted.map(QPointF(154.5, 24.5));
  const double fitted_scale = fitted.m11();

  Wheel(&view_, square, 3 * 120);  // Three notches in.
  EXPECT_NEAR(view_.zoom(), 1.25 * 1.25 * 1.25, 1e-9);
  const QTransform zoomed = view_.ImageToWidget();
  EXPECT_NEAR(zoomed.m11(), view_.zoom() * fitted_scale, 1e-9);
  const QPointF still = zoomed.map(QPointF(154.5, 24.5));
  EXPECT_NEAR(still.x(), square.x(), 1e-6) << "the pixel under the mouse moved";
  EXPECT_NEAR(still.y(), square.y(), 1e-6);
  // The square now covers about 1.95 times as many widget pixels per side.
  const QImage grab = Grab();
  EXPECT_TRUE(Near(grab.pixelColor(square.toPoint()), QColor(255, 255, 255), 10));
  const QPointF corner = zoomed.map(QPointF(150.2, 20.2));
  EXPECT_TRUE(Near(grab.pixelColor(corner.toPoint()), QColor(255, 255, 255), 10));

  QTest::mousePress(&view_, Qt::LeftButton, {}, QPoint(250, 200));
  QTest::mouseMove(&view_, QPoint(220, 190));
  QTest::mouseRelease(&view_, Qt::LeftButton, {}, QPoint(220, 190));
  const QPointF moved = view_.ImageToWidget().map(QPointF(154.5, 24.5));
  EXPECT_NEAR(moved.x() - still.x(), -30, 1e-6) << "the drag did not pan";
  EXPECT_NEAR(moved.y() - still.y(), -10, 1e-6);

  QTest::mouseDClick(&view_, Qt::LeftButton, {}, QPoint(100, 100));
  EXPECT_EQ(view_.zoom(), 1.0);
  EXPECT_EQ(view_.ImageToWidget(), fitted) << "a double click does not fit the image again";
  Wheel(&view_, square, -120);  // Out beyond the fit: stays fitted.
  EXPECT_EQ(view_.ImageToWidget(), fitted);
}

// A key to the overlay's colours: one swatch per entry in its colour, drawn over the image and
// kept when the next image comes.
TEST_F(ImageViewTest, KeysShowEachColourBesideItsWord) {
  view_.SetImage(cv::Mat(240, 320, CV_8UC3, cv::Scalar(128, 128, 128)));
  view_.SetKeys({{QColor(40, 220, 40), "inlier"}, {QColor(230, 40, 40), "outlier"}});
  view_.SetImage(cv::Mat(240, 320, CV_8UC3, cv::Scalar(128, 128, 128)));  // The next frame.
  ASSERT_EQ(view_.keys().size(), 2u);
  const QImage grab = Grab();
  SaveScreenshot(grab, "image_view_keys.png");
  const QRect first = view_.KeySwatchRect(0), second = view_.KeySwatchRect(1);
  ASSERT_FALSE(first.isEmpty());
  EXPECT_GT(second.top(), first.bottom()) << "swatches overlap";
  EXPECT_TRUE(Near(grab.pixelColor(first.center()), QColor(40, 220, 40)));
  EXPECT_TRUE(Near(grab.pixelColor(second.center()), QColor(230, 40, 40)));
  // The words are drawn right of the swatch: bright pixels on the dark box.
  int bright = 0;
  for (int x = first.right() + 4; x < first.right() + 60; ++x) {
    for (int y = first.top(); y <= first.bottom(); ++y)
      bright += grab.pixelColor(x, y).value() > 200;
  }
  EXPECT_GT(bright, 5) << "no label beside the swatch";
  view_.Clear();
  EXPECT_TRUE(view_.KeySwatchRect(0).isEmpty()) << "no key without an image";
}

}  // namespace
}  // namespace sightline
