#include "widgets/image_view.h"

#include <QFontMetrics>
#include <QMouseEvent>
#include <QPainter>
#include <QWheelEvent>
#include <algorithm>
#include <cmath>
#include <cstring>
#include <opencv2/imgproc.hpp>
#include <tuple>
#include <vector>

#include "widgets/color_map.h"

namespace sightline {
namespace {

constexpr int kMargin = 4;
constexpr int kLegendBarWidth = 14;

bool ValidDepth(float d) { return std::isfinite(d) && d > 0.f; }

// The [2%, 98%] range of the valid depths over a subsample; {0, 0} when none is valid.
std::pair<double, double> RobustDepthRange(const cv::Mat& depth_m) {
  std::vector<float> values;
  const int step = std::max(1, static_cast<int>(std::sqrt(depth_m.total() / 40000.0)));
  for (int r = 0; r < depth_m.rows; r += step) {
    const float* row = depth_m.ptr<float>(r);
    for (int c = 0; c < depth_m.cols; c += step) {
      if (ValidDepth(row[c])) values.push_back(row[c]);
    }
  }
  if (values.empty()) return {0, 0};
  const auto at = [&values](double q) {
    auto nth = values.begin() + static_cast<ptrdiff_t>(q * (values.size() - 1));
    std::nth_element(values.begin(), nth, values.end());
    return static_cast<double>(*nth);
  };
  const double low = at(0.02);
  const double high = at(0.98);
  return {low, high > low ? high : low + 0.01};
}

QString TypeName(int type) { return QString::fromStdString(cv::typeToString(type)); }

}  // namespace

ImageView::ImageView(QWidget* parent) : QWidget(parent), message_(tr("No image")) {
  setAttribute(Qt::WA_OpaquePaintEvent);
  setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Expanding);
}

ImageView::~ImageView() = default;

void ImageView::SetImage(const cv::Mat& image, Kind kind) {
  if (kind == Kind::kAuto) {
    switch (image.type()) {
      case CV_8UC1:
        kind = Kind::kGray;
        break;
      case CV_8UC3:
        kind = Kind::kBgr;
        break;
      case CV_32FC1:
        kind = Kind::kDepthMeters;
        break;
      default:
        break;
    }
  }
  const int expected = kind == Kind::kGray          ? CV_8UC1
                       : kind == Kind::kBgr         ? CV_8UC3
                       : kind == Kind::kDepthMeters ? CV_32FC1
                                                    : -1;
  is_depth_ = false;
  depth_low_m_ = depth_high_m_ = 0;
  if (image.empty()) {
    image_ = QImage();
    message_ = tr("No image");
  } else if (image.type() != expected || image.dims != 2) {
    image_ = QImage();
    message_ = tr("Unsupported image type %1").arg(TypeName(image.type()));
  } else if (kind == Kind::kGray) {
    image_ = QImage(image.cols, image.rows, QImage::Format_Grayscale8);
    for (int r = 0; r < image.rows; ++r) {
      std::memcpy(image_.scanLine(r), image.ptr(r), static_cast<size_t>(image.cols));
    }
  } else if (kind == Kind::kBgr) {
    image_ = QImage(image.cols, image.rows, QImage::Format_RGB888);
    // Converts straight into the QImage's own buffer: one pass, and a real copy.
    cv::Mat rgb(image.rows, image.cols, CV_8UC3, image_.bits(),
                static_cast<size_t>(image_.bytesPerLine()));
    cv::cvtColor(image, rgb, cv::COLOR_BGR2RGB);
  } else {
    SetDepthImage(image);
  }
  update();
}

void ImageView::SetDepthImage(const cv::Mat& depth_m) {
  is_depth_ = true;
  if (fixed_low_m_ < fixed_high_m_) {
    depth_low_m_ = fixed_low_m_;
    depth_high_m_ = fixed_high_m_;
  } else {
    std::tie(depth_low_m_, depth_high_m_) = RobustDepthRange(depth_m);
  }
  const auto& lut = TurboColorMap();
  const double span = depth_high_m_ - depth_low_m_;
  const float scale = span > 0 ? static_cast<float>(255.0 / span) : 0.f;
  const float low = static_cast<float>(depth_low_m_);
  image_ = QImage(depth_m.cols, depth_m.rows, QImage::Format_RGB888);
  for (int r = 0; r < depth_m.rows; ++r) {
    const float* in = depth_m.ptr<float>(r);
    uchar* out = image_.scanLine(r);
    for (int c = 0; c < depth_m.cols; ++c, out += 3) {
      if (!ValidDepth(in[c])) {
        out[0] = out[1] = out[2] = 0;
        continue;
      }
      const Rgb8 color = lut[static_cast<int>(std::clamp((in[c] - low) * scale, 0.f, 255.f))];
      out[0] = color.r;
      out[1] = color.g;
      out[2] = color.b;
    }
  }
}

void ImageView::Clear() {
  image_ = QImage();
  zoom_ = 1.0;
  pan_ = QPointF();
  is_depth_ = false;
  message_ = tr("No image");
  update();
}

void ImageView::SetTitle(const QString& title) {
  title_ = title;
  update();
}

void ImageView::SetMessage(const QString& message) {
  message_ = message;
  update();
}

void ImageView::SetDepthRange(double low_m, double high_m) {
  fixed_low_m_ = low_m;
  fixed_high_m_ = high_m;
}

void ImageView::SetOverlay(ImageOverlay overlay) {
  overlay_ = std::move(overlay);
  update();
}

void ImageView::SetOverlayPainter(OverlayPainter painter) {
  overlay_painter_ = std::move(painter);
  update();
}

int ImageView::TitleHeight() const {
  return title_.isEmpty() ? 0 : fontMetrics().height() + kMargin;
}

int ImageView::LegendWidth() const {
  if (!legend_visible()) return 0;
  return kLegendBarWidth + 3 * kMargin + fontMetrics().horizontalAdvance(QStringLiteral("00.00 m"));
}

QRect ImageView::ImageArea() const {
  return QRect(0, TitleHeight(), std::max(1, width() - LegendWidth()),
               std::max(1, height() - TitleHeight()));
}

QTransform ImageView::ImageToWidget() const {
  if (image_.isNull()) return QTransform();
  const QRect area = ImageArea();
  const double scale = std::min(static_cast<double>(area.width()) / image_.width(),
                                static_cast<double>(area.height()) / image_.height());
  const double x0 = area.x() + 0.5 * (area.width() - scale * image_.width());
  const double y0 = area.y() + 0.5 * (area.height() - scale * image_.height());
  // Image coordinate u has its pixel spanning [u - 0.5, u + 0.5).
  const QTransform fitted = QTransform::fromTranslate(0.5, 0.5) *
                            QTransform::fromScale(scale, scale) * QTransform::fromTranslate(x0, y0);
  // Zoom about the area's centre, then pan.
  const QPointF c = QRectF(area).center();
  return fitted * QTransform::fromTranslate(-c.x(), -c.y()) * QTransform::fromScale(zoom_, zoom_) *
         QTransform::fromTranslate(c.x() + pan_.x(), c.y() + pan_.y());
}

void ImageView::FitImage() {
  zoom_ = 1.0;
  pan_ = QPointF();
  update();
}

void ImageView::wheelEvent(QWheelEvent* event) {
  if (image_.isNull() || event->angleDelta().y() == 0) return QWidget::wheelEvent(event);
  const double next =
      std::clamp(zoom_ * std::pow(1.25, event->angleDelta().y() / 120.0), 1.0, 32.0);
  if (next == 1.0) return FitImage();
  // The image point under the mouse stays under it.
  const QPointF m = event->position();
  const QPointF c = QRectF(ImageArea()).center();
  pan_ = m - c - (m - c - pan_) * (next / zoom_);
  zoom_ = next;
  update();
  event->accept();
}

void ImageView::mousePressEvent(QMouseEvent* event) {
  if (event->button() != Qt::LeftButton || zoom_ == 1.0) return QWidget::mousePressEvent(event);
  dragging_ = true;
  drag_from_ = event->position();
  setCursor(Qt::ClosedHandCursor);
}

void ImageView::mouseMoveEvent(QMouseEvent* event) {
  if (!dragging_) return QWidget::mouseMoveEvent(event);
  pan_ += event->position() - drag_from_;
  drag_from_ = event->position();
  update();
}

void ImageView::mouseReleaseEvent(QMouseEvent* event) {
  if (!dragging_) return QWidget::mouseReleaseEvent(event);
  dragging_ = false;
  unsetCursor();
}

void ImageView::mouseDoubleClickEvent(QMouseEvent* event) {
  if (event->button() != Qt::LeftButton) return QWidget::mouseDoubleClickEvent(event);
  FitImage();
}

QRect ImageView::LegendBarRect() const {
  if (!legend_visible()) return QRect();
  const int top = TitleHeight() + fontMetrics().height();
  const int bottom = height() - fontMetrics().height();
  return QRect(width() - LegendWidth() + kMargin, top, kLegendBarWidth, std::max(1, bottom - top));
}

QSize ImageView::sizeHint() const { return QSize(400, 320); }

QSize ImageView::minimumSizeHint() const { return QSize(80, 60); }

void ImageView::paintEvent(QPaintEvent*) {
  QPainter painter(this);
  painter.fillRect(rect(), palette().color(QPalette::Window).darker(160));
  if (!title_.isEmpty()) {
    painter.setPen(palette().color(QPalette::BrightText));
    painter.drawText(QRect(kMargin, 0, width() - 2 * kMargin, TitleHeight()),
                     Qt::AlignLeft | Qt::AlignVCenter, title_);
  }
  if (image_.isNull()) {
    painter.setPen(palette().color(QPalette::PlaceholderText));
    painter.drawText(ImageArea(), Qt::AlignCenter, message_);
    return;
  }
  const QTransform image_to_widget = ImageToWidget();
  painter.save();
  painter.setClipRect(ImageArea());  // A zoomed image stays off the title and the legend.
  // The image rectangle in widget coordinates (pixel edges at -0.5 and size - 0.5).
  const QRectF target =
      image_to_widget.mapRect(QRectF(-0.5, -0.5, image_.width(), image_.height()));
  // Nearest-neighbour when enlarging keeps pixels honest; smooth when shrinking avoids aliasing.
  painter.setRenderHint(QPainter::SmoothPixmapTransform, target.width() < image_.width());
  painter.drawImage(target, image_);
  if (!overlay_.empty()) DrawImageOverlay(painter, image_to_widget, overlay_);
  if (overlay_painter_) {
    painter.save();
    overlay_painter_(painter, image_to_widget);
    painter.restore();
  }
  painter.restore();
  if (legend_visible()) DrawLegend(painter);
  DrawKeys(painter);
}

void ImageView::SetKeys(std::vector<Key> keys) {
  keys_ = std::move(keys);
  update();
}

QRect ImageView::KeySwatchRect(size_t i) const {
  if (image_.isNull() || i >= keys_.size()) return QRect();
  const int line = fontMetrics().height();
  const QRect area = ImageArea();
  return QRect(area.left() + 2 * kMargin, area.top() + 2 * kMargin + static_cast<int>(i) * line + 2,
               line - 4, line - 4);
}

void ImageView::DrawKeys(QPainter& painter) const {
  if (image_.isNull() || keys_.empty()) return;
  const QFontMetrics metrics = fontMetrics();
  int text_width = 0;
  for (const Key& key : keys_)
    text_width = std::max(text_width, metrics.horizontalAdvance(key.label));
  const int line = metrics.height();
  const QRect area = ImageArea();
  // A dark box under the key keeps it readable on any image.
  painter.fillRect(
      QRect(area.left() + kMargin, area.top() + kMargin, line + text_width + 3 * kMargin,
            static_cast<int>(keys_.size()) * line + 2 * kMargin),
      QColor(0, 0, 0, 170));
  for (size_t i = 0; i < keys_.size(); ++i) {
    const QRect swatch = KeySwatchRect(i);
    painter.fillRect(swatch, keys_[i].color);
    painter.setPen(QColor(160, 160, 160));  // An outline: a black swatch shows on the dark box.
    painter.drawRect(swatch.adjusted(0, 0, -1, -1));
    painter.setPen(Qt::white);
    painter.drawText(
        QRect(swatch.right() + kMargin + 2, swatch.top() - 2, text_width + kMargin, line),
        Qt::AlignLeft | Qt::AlignVCenter, keys_[i].label);
  }
}

void ImageView::DrawLegend(QPainter& painter) const {
  const QRect bar = LegendBarRect();
  // High values at the top, like a thermometer.
  QImage ramp(1, 256, QImage::Format_RGB888);
  const auto& lut = TurboColorMap();
  for (int i = 0; i < 256; ++i) {
    uchar* px = ramp.scanLine(255 - i);
    px[0] = lut[i].r;
    px[1] = lut[i].g;
    px[2] = lut[i].b;
  }
  painter.setRenderHint(QPainter::SmoothPixmapTransform, true);
  painter.drawImage(bar, ramp);
  painter.setPen(palette().color(QPalette::BrightText));
  painter.drawRect(bar.adjusted(0, 0, -1, -1));
  const int ticks = 5;
  const QFontMetrics metrics = fontMetrics();
  for (int i = 0; i < ticks; ++i) {
    const double t = static_cast<double>(i) / (ticks - 1);
    const double value = depth_low_m_ + t * (depth_high_m_ - depth_low_m_);
    const int y = bar.bottom() - static_cast<int>(t * (bar.height() - 1));
    painter.drawLine(bar.right() + 1, y, bar.right() + 3, y);
    painter.drawText(bar.right() + kMargin + 2, y + metrics.ascent() / 2,
                     QStringLiteral("%1 m").arg(value, 0, 'f', 2));
  }
}

}  // namespace sightline
