#include "widgets/image_overlay.h"

#include <QPainter>
#include <QPainterPath>
#include <QTransform>

namespace sightline {

void DrawImageOverlay(QPainter& painter, const QTransform& image_to_widget,
                      const ImageOverlay& overlay) {
  painter.save();
  painter.setRenderHint(QPainter::Antialiasing, true);
  painter.setBrush(Qt::NoBrush);
  for (const ImageOverlay::Line& l : overlay.lines) {
    painter.setPen(QPen(l.color, l.width_px));
    painter.drawLine(image_to_widget.map(l.line));
  }
  for (const ImageOverlay::Rect& r : overlay.rects) {
    painter.setPen(QPen(r.color, r.width_px));
    // Pixel centres are at integers: a box covering pixels x..x+w-1 spans x-0.5 .. x+w-0.5.
    painter.drawRect(image_to_widget.mapRect(r.rect.translated(-0.5, -0.5)));
  }
  for (const ImageOverlay::Point& p : overlay.points) {
    painter.setPen(QPen(p.color, 1.5));
    painter.drawEllipse(image_to_widget.map(p.position), p.radius_px, p.radius_px);
  }
  for (const ImageOverlay::Text& t : overlay.texts) {
    // A dark outline keeps labels readable on bright and dark images alike.
    QPainterPath path;
    path.addText(image_to_widget.map(t.position), painter.font(), t.text);
    painter.setPen(QPen(QColor(0, 0, 0, 200), 3.0));
    painter.drawPath(path);
    painter.fillPath(path, t.color);
  }
  painter.restore();
}

}  // namespace sightline
