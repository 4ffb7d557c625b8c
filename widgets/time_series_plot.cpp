#include "widgets/time_series_plot.h"

#include <QPainter>
#include <QPainterPath>
#include <algorithm>
#include <cmath>
#include <limits>

namespace sightline {

namespace {

// A compact label for an axis value.
QString Compact(double v) {
  if (std::abs(v) >= 100 || v == std::floor(v)) return QString::number(v, 'f', 0);
  if (std::abs(v) >= 1) return QString::number(v, 'f', 1);
  return QString::number(v, 'g', 2);
}

}  // namespace

TimeSeriesPlot::TimeSeriesPlot(const QString& title, QWidget* parent)
    : QWidget(parent), title_(title) {
  setAttribute(Qt::WA_OpaquePaintEvent);
}

void TimeSeriesPlot::SetCapacity(int samples) {
  capacity_ = std::max(2, samples);
  for (Series& s : series_) {
    while (static_cast<int>(s.samples.size()) > capacity_) s.samples.pop_front();
  }
  update();
}

TimeSeriesPlot::Series* TimeSeriesPlot::Find(const QString& name) {
  for (Series& s : series_) {
    if (s.name == name) return &s;
  }
  return nullptr;
}

const TimeSeriesPlot::Series* TimeSeriesPlot::Find(const QString& name) const {
  for (const Series& s : series_) {
    if (s.name == name) return &s;
  }
  return nullptr;
}

void TimeSeriesPlot::Append(const QString& series, double x, double y, const QColor& color) {
  Series* s = Find(series);
  if (s == nullptr) {
    series_.push_back({series, color, {}});
    s = &series_.back();
  }
  if (!std::isfinite(x) || !std::isfinite(y)) return;
  s->samples.emplace_back(x, y);
  while (static_cast<int>(s->samples.size()) > capacity_) s->samples.pop_front();
  const QRectF range = DataRange();
  if (!range.isNull()) DropMarkersBefore(range.left());
  update();
}

void TimeSeriesPlot::AddMarker(double x) {
  if (!std::isfinite(x)) return;
  markers_.push_back(x);
  update();
}

void TimeSeriesPlot::DropMarkersBefore(double x) {
  while (!markers_.empty() && markers_.front() < x) markers_.pop_front();
}

void TimeSeriesPlot::Clear() {
  for (Series& s : series_) s.samples.clear();
  markers_.clear();
  update();
}

QStringList TimeSeriesPlot::SeriesNames() const {
  QStringList names;
  for (const Series& s : series_) names << s.name;
  return names;
}

std::vector<QPointF> TimeSeriesPlot::Samples(const QString& series) const {
  const Series* s = Find(series);
  if (s == nullptr) return {};
  return {s->samples.begin(), s->samples.end()};
}

std::vector<double> TimeSeriesPlot::Markers() const { return {markers_.begin(), markers_.end()}; }

QRectF TimeSeriesPlot::DataRange() const {
  double x0 = std::numeric_limits<double>::infinity(), x1 = -x0, y0 = 0, y1 = -x0;
  for (const Series& s : series_) {
    for (const QPointF& p : s.samples) {
      x0 = std::min(x0, p.x());
      x1 = std::max(x1, p.x());
      y0 = std::min(y0, p.y());
      y1 = std::max(y1, p.y());
    }
  }
  if (!std::isfinite(x0)) return {};
  return QRectF(QPointF(x0, y0), QPointF(x1, y1));
}

QSize TimeSeriesPlot::sizeHint() const { return {320, 120}; }
QSize TimeSeriesPlot::minimumSizeHint() const { return {160, 80}; }

void TimeSeriesPlot::paintEvent(QPaintEvent*) {
  QPainter painter(this);
  painter.fillRect(rect(), QColor(25, 25, 30));
  painter.setRenderHint(QPainter::Antialiasing, true);
  const QFontMetrics fm(font());
  const int line = fm.height();
  // Plot area: title on top, y labels on the left, legend at the bottom.
  const int legend_rows = static_cast<int>(series_.size() + 2) / 3;
  const QRectF area(fm.horizontalAdvance("00000") + 4, line + 2,
                    width() - fm.horizontalAdvance("00000") - 8,
                    height() - line - 4 - legend_rows * line - 4);
  painter.setPen(QColor(200, 200, 200));
  painter.drawText(QPointF(4, line - 3), title_);
  painter.setPen(QColor(70, 70, 80));
  painter.drawRect(area);
  const QRectF range = DataRange();
  if (area.width() < 10 || area.height() < 10 || range.isNull()) return;
  const double y_top = range.bottom() > range.top() ? range.bottom() * 1.05 : range.top() + 1;
  const double y_bottom = range.top();
  const double x_span = range.width() > 0 ? range.width() : 1.0;
  auto to_widget = [&](double x, double y) {
    return QPointF(area.left() + (x - range.left()) / x_span * area.width(),
                   area.bottom() - (y - y_bottom) / (y_top - y_bottom) * area.height());
  };
  painter.setPen(QColor(160, 160, 160));
  painter.drawText(QPointF(2, area.top() + line - 4), Compact(y_top));
  painter.drawText(QPointF(2, area.bottom()), Compact(y_bottom));
  painter.setPen(QPen(QColor(230, 60, 60, 160), 1.0));
  for (double m : markers_) {
    if (m < range.left() || m > range.right()) continue;
    const double x = to_widget(m, 0).x();
    painter.drawLine(QPointF(x, area.top()), QPointF(x, area.bottom()));
  }
  painter.setClipRect(area.adjusted(-1, -1, 1, 1));
  for (const Series& s : series_) {
    if (s.samples.empty()) continue;
    QPainterPath path(to_widget(s.samples.front().x(), s.samples.front().y()));
    for (size_t i = 1; i < s.samples.size(); ++i) {
      path.lineTo(to_widget(s.samples[i].x(), s.samples[i].y()));
    }
    painter.setPen(QPen(s.color, 1.5));
    painter.drawPath(path);
    if (s.samples.size() == 1) painter.drawEllipse(path.currentPosition(), 1.5, 1.5);
  }
  painter.setClipping(false);
  const double column = width() / 3.0;
  for (size_t i = 0; i < series_.size(); ++i) {
    const Series& s = series_[i];
    const size_t row = i / 3;  // Three legend entries per line.
    const QPointF at(4 + column * static_cast<double>(i % 3),
                     area.bottom() + line * (1 + static_cast<double>(row)) + 2);
    painter.setPen(s.color);
    const QString value = s.samples.empty() ? QString("-") : Compact(s.samples.back().y());
    painter.drawText(at, s.name + " " + value);
  }
}

}  // namespace sightline
