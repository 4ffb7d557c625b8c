// Simple drawing primitives in image pixel coordinates, so that a pipeline can describe what to
// draw over an image (keypoints, matches, detections) as a plain value, on any thread.
#pragma once

#include <QColor>
#include <QLineF>
#include <QPointF>
#include <QRectF>
#include <QString>
#include <vector>

class QPainter;
class QTransform;

namespace sightline {

// Overlay primitives in image coordinates (OpenCV convention: pixel centres at integers).
// Sizes (marker radius, pen width, font) are in screen pixels, so they stay readable at any zoom.
//
//   ImageOverlay overlay;
//   for (const cv::KeyPoint& k : keypoints) overlay.points.push_back({{k.pt.x, k.pt.y}});
//   overlay.rects.push_back({QRectF(x, y, w, h), Qt::red});
//   overlay.texts.push_back({{x, y - 4}, "person 0.93", Qt::red});
//   image_view->SetOverlay(std::move(overlay));
struct ImageOverlay {
  // A marker circle at a pixel.
  struct Point {
    QPointF position;
    QColor color = Qt::green;
    double radius_px = 3.0;
  };
  // A line between two pixels.
  struct Line {
    QLineF line;
    QColor color = Qt::yellow;
    double width_px = 1.5;
  };
  // An axis-aligned rectangle (top-left, size) in pixels.
  struct Rect {
    QRectF rect;
    QColor color = Qt::red;
    double width_px = 2.0;
  };
  // A label whose baseline starts at a pixel.
  struct Text {
    QPointF position;
    QString text;
    QColor color = Qt::white;
  };

  std::vector<Point> points;  // Drawn above lines and rectangles.
  std::vector<Line> lines;    // Drawn first.
  std::vector<Rect> rects;    // Drawn after lines.
  std::vector<Text> texts;    // Drawn last, outlined.

  // True when there is nothing to draw.
  bool empty() const { return points.empty() && lines.empty() && rects.empty() && texts.empty(); }
};

// Draws the overlay with `image_to_widget` mapping image coordinates to the painter's.
void DrawImageOverlay(QPainter& painter, const QTransform& image_to_widget,
                      const ImageOverlay& overlay);

}  // namespace sightline
