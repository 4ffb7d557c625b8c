// The live camera image for the operator's panel: fills its area (aspect kept), takes taps from
// a finger or a mouse and reports them in image pixels, outlines the found button and rings the
// tracked one.
#pragma once

#include <QImage>
#include <QPointF>
#include <QPolygonF>
#include <QWidget>
#include <opencv2/core.hpp>
#include <optional>

class QPainter;

namespace sightline {

// Usage: view->SetImage(frame); connect(view, &TapImageView::Tapped, ...);
// view->SetOutline(outline_in_image_pixels);
class TapImageView : public QWidget {
  Q_OBJECT

 public:
  explicit TapImageView(QWidget* parent = nullptr);

  // Shows a BGR, BGRA or grey 8-bit image (copied); an empty image shows nothing.
  void SetImage(const cv::Mat& image);
  // Outlines a region given in image pixels; an empty polygon clears it.
  void SetOutline(const QPolygonF& outline_in_image);
  const QPolygonF& outline() const { return outline_; }
  // Rings the tracked button: centre and radius in image pixels; nullopt clears it.
  void SetRing(std::optional<QPointF> centre_in_image, double radius_px = 0);
  std::optional<QPointF> ring_centre() const { return ring_centre_; }
  double ring_radius() const { return ring_radius_; }
  // Enables or ignores taps (e.g. while the operator answers a question).
  void SetTapsEnabled(bool enabled) { taps_enabled_ = enabled; }

  QSize image_size() const { return image_.size(); }
  // Widget point -> image pixel (invalid when outside the shown image).
  std::optional<QPointF> ToImage(QPointF widget_point) const;
  // Image pixel -> widget point.
  QPointF ToWidget(QPointF image_point) const;

 signals:
  // A finger or the mouse touched the image at this pixel.
  void Tapped(QPointF image_px);

 protected:
  void paintEvent(QPaintEvent* event) override;
  void mousePressEvent(QMouseEvent* event) override;
  bool event(QEvent* event) override;

 private:
  QRectF ImageRect() const;  // Where the image is drawn, widget coordinates.
  void PaintRing(QPainter* painter) const;
  void Tap(QPointF widget_point);

  QImage image_;
  QPolygonF outline_;
  std::optional<QPointF> ring_centre_;
  double ring_radius_ = 0;
  bool taps_enabled_ = true;
};

}  // namespace sightline
