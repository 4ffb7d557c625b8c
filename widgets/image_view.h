// Shows one camera image (grey, BGR colour, or depth in metres with a colour legend), scaled to
// fit with its aspect ratio, with a title and optional overlays in image coordinates.
#pragma once

#include <QColor>
#include <QImage>
#include <QPointF>
#include <QString>
#include <QTransform>
#include <QWidget>
#include <functional>
#include <opencv2/core.hpp>
#include <vector>

#include "widgets/image_overlay.h"

namespace sightline {

// An image panel. SetImage copies the pixels, so the cv::Mat may be released right after.
//
//   ImageView* view = new ImageView(this);
//   view->SetTitle(tr("Depth"));
//   view->SetImage(frame.depth_m, ImageView::Kind::kDepthMeters);
//   view->SetOverlay(detections_overlay);
class ImageView : public QWidget {
  Q_OBJECT

 public:
  // How to interpret the cv::Mat given to SetImage.
  enum class Kind {
    kAuto,         // From the type: CV_8UC1 grey, CV_8UC3 BGR, CV_32FC1 depth in metres.
    kGray,         // CV_8UC1.
    kBgr,          // CV_8UC3 in OpenCV's BGR order.
    kDepthMeters,  // CV_32FC1 metres; NaN, inf and <= 0 are invalid and drawn black.
  };

  // Draws over the image; `image_to_widget` maps image coordinates (pixel centres at integers)
  // to the painter's coordinates.
  using OverlayPainter = std::function<void(QPainter& painter, const QTransform& image_to_widget)>;

  // Creates an empty view that says "No image".
  explicit ImageView(QWidget* parent = nullptr);
  ~ImageView() override;

  // Shows a copy of `image`. An unsupported type shows a message naming it instead.
  void SetImage(const cv::Mat& image, Kind kind = Kind::kAuto);
  // Removes the image (and keeps title and overlays).
  void Clear();
  // Text above the image.
  void SetTitle(const QString& title);
  const QString& title() const { return title_; }
  // The text shown instead of an image ("No image"); the next SetImage replaces it. Switching
  // the GUI's language turns both texts into the new language through these.
  const QString& message() const { return message_; }
  void SetMessage(const QString& message);
  // Fixes the depth colour range in metres; low >= high restores automatic range (2nd to 98th
  // percentile of the valid depths).
  void SetDepthRange(double low_m, double high_m);
  // Replaces the primitive overlay (empty overlay = none).
  void SetOverlay(ImageOverlay overlay);
  // Replaces the custom overlay painter, drawn after the primitives (nullptr = none).
  void SetOverlayPainter(OverlayPainter painter);

  // The displayed image as converted (RGB888 or Grayscale8); null when none.
  const QImage& image() const { return image_; }
  // The depth range used for the current depth image, in metres (0, 0 when not a depth image).
  std::pair<double, double> depth_range() const { return {depth_low_m_, depth_high_m_}; }
  // Where the image is drawn; image coordinates follow OpenCV (pixel centres at integers).
  QTransform ImageToWidget() const;
  // Whether the colour legend is shown (depth images only).
  bool legend_visible() const { return is_depth_ && !image_.isNull(); }
  // The rectangle of the legend's colour bar in widget coordinates (empty when not shown).
  QRect LegendBarRect() const;

  // A key to the overlay's colours (e.g. wall classes, track roles), drawn as swatches with
  // their words in the image's top-left corner; empty: none. It stays when images change.
  struct Key {
    QColor color;
    QString label;
  };
  void SetKeys(std::vector<Key> keys);
  const std::vector<Key>& keys() const { return keys_; }
  // The swatch of key `i` in widget coordinates (empty when not drawn).
  QRect KeySwatchRect(size_t i) const;

  // Zoom and pan: the wheel zooms about the mouse (1x = the whole image fitted, up to 32x), a
  // drag moves the zoomed image, a double click (or FitImage) fits it again. New images keep
  // the zoom, so a region can be watched while playing; Clear fits.
  double zoom() const { return zoom_; }
  void FitImage();

  // Room for a 4:3 image with title and legend.
  QSize sizeHint() const override;
  // Small enough for a grid of camera views.
  QSize minimumSizeHint() const override;

 protected:
  void paintEvent(QPaintEvent* event) override;
  void wheelEvent(QWheelEvent* event) override;
  void mousePressEvent(QMouseEvent* event) override;
  void mouseMoveEvent(QMouseEvent* event) override;
  void mouseReleaseEvent(QMouseEvent* event) override;
  void mouseDoubleClickEvent(QMouseEvent* event) override;

 private:
  // Converts a depth image through the colour map into image_, choosing the range if automatic.
  void SetDepthImage(const cv::Mat& depth_m);
  // The part of the widget left for the image (below the title, left of the legend).
  QRect ImageArea() const;
  int TitleHeight() const;
  int LegendWidth() const;
  void DrawLegend(QPainter& painter) const;
  void DrawKeys(QPainter& painter) const;

  QImage image_;
  QString title_;
  QString message_;  // Shown instead of an image ("No image", unsupported type).
  bool is_depth_ = false;
  double fixed_low_m_ = 0;
  double fixed_high_m_ = 0;
  double depth_low_m_ = 0;
  double depth_high_m_ = 0;
  ImageOverlay overlay_;
  OverlayPainter overlay_painter_;
  std::vector<Key> keys_;
  double zoom_ = 1.0;  // 1: fitted.
  QPointF pan_;        // Widget pixels the zoomed image is moved by.
  QPointF drag_from_;  // Mouse position at the last drag event.
  bool dragging_ = false;
};

}  // namespace sightline
