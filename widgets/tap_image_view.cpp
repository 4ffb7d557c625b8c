#include "widgets/tap_image_view.h"

#include <QEvent>
#include <QMouseEvent>
#include <QPainter>
#include <QTouchEvent>
#include <opencv2/imgproc.hpp>

namespace sightline {

TapImageView::TapImageView(QWidget* parent) : QWidget(parent) {
  setAttribute(Qt::WA_AcceptTouchEvents);
  setAttribute(Qt::WA_OpaquePaintEvent);
  setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Expanding);
  setMinimumSize(160, 120);
}

void TapImageView::SetImage(const cv::Mat& image) {
  if (image.empty() || image.depth() != CV_8U) {
    image_ = QImage();
  } else {
    cv::Mat rgb;
    if (image.channels() == 1)
      cv::cvtColor(image, rgb, cv::COLOR_GRAY2RGB);
    else if (image.channels() == 4)
      cv::cvtColor(image, rgb, cv::COLOR_BGRA2RGB);
    else
      cv::cvtColor(image, rgb, cv::COLOR_BGR2RGB);
    image_ = QImage(rgb.data, rgb.cols, rgb.rows, int(rgb.step), QImage::Format_RGB888).copy();
  }
  update();
}

void TapImageView::SetOutline(const QPolygonF& outline_in_image) {
  outline_ = outline_in_image;
  update();
}

void TapImageView::SetRing(std::optional<QPointF> centre_in_image, double radius_px) {
  ring_centre_ = centre_in_image;
  ring_radius_ = radius_px;
  update();
}

QRectF TapImageView::ImageRect() const {
  if (image_.isNull()) return {};
  const double s = std::min(width() / double(image_.width()), height() / double(image_.height()));
  const double w = image_.width() * s, h = image_.height() * s;
  return {(width() - w) / 2, (height() - h) / 2, w, h};
}

std::optional<QPointF> TapImageView::ToImage(QPointF p) const {
  const QRectF r = ImageRect();
  if (r.isEmpty() || !r.contains(p)) return std::nullopt;
  const double s = r.width() / image_.width();
  return QPointF((p.x() - r.left()) / s - 0.5, (p.y() - r.top()) / s - 0.5);
}

QPointF TapImageView::ToWidget(QPointF p) const {
  const QRectF r = ImageRect();
  const double s = image_.isNull() ? 1.0 : r.width() / image_.width();
  return {r.left() + (p.x() + 0.5) * s, r.top() + (p.y() + 0.5) * s};
}

void TapImageView::paintEvent(QPaintEvent*) {
  QPainter painter(this);
  painter.fillRect(rect(), Qt::black);
  if (image_.isNull()) return;
  painter.setRenderHint(QPainter::SmoothPixmapTransform);
  painter.drawImage(ImageRect(), image_);
  PaintRing(&painter);
  if (outline_.size() < 2) return;
  QPolygonF shown;
  for (const QPointF& p : outline_) shown << ToWidget(p);
  painter.setRenderHint(QPainter::Antialiasing);
  // Black under yellow: visible on light and dark panels alike.
  painter.setPen(QPen(Qt::black, 9, Qt::SolidLine, Qt::RoundCap, Qt::RoundJoin));
  painter.drawPolygon(shown);
  painter.setPen(QPen(QColor(255, 221, 0), 5, Qt::SolidLine, Qt::RoundCap, Qt::RoundJoin));
  painter.drawPolygon(shown);
}

void TapImageView::PaintRing(QPainter* painter) const {
  if (!ring_centre_) return;
  const QPointF c = ToWidget(*ring_centre_);
  const double scale = ImageRect().width() / image_.width();
  const double r = std::max(8.0, ring_radius_ * scale + 4);  // Around the button, not on it.
  painter->save();
  painter->setRenderHint(QPainter::Antialiasing);
  painter->setBrush(Qt::NoBrush);
  painter->setPen(QPen(Qt::black, 9));
  painter->drawEllipse(c, r, r);
  painter->setPen(QPen(QColor(255, 221, 0), 5));
  painter->drawEllipse(c, r, r);
  painter->restore();
}

void TapImageView::Tap(QPointF widget_point) {
  if (!taps_enabled_) return;
  if (auto p = ToImage(widget_point)) emit Tapped(*p);
}

void TapImageView::mousePressEvent(QMouseEvent* event) {
  if (event->button() == Qt::LeftButton) Tap(event->position());
  event->accept();
}

bool TapImageView::event(QEvent* event) {
  if (event->type() == QEvent::TouchBegin) {
    auto* touch = static_cast<QTouchEvent*>(event);
    if (!touch->points().isEmpty()) Tap(touch->points().first().position());
    event->accept();
    return true;
  }
  if (event->type() == QEvent::TouchUpdate || event->type() == QEvent::TouchEnd) {
    event->accept();
    return true;
  }
  return QWidget::event(event);
}

}  // namespace sightline
