// A small plot of named series over time (or frame index): one polyline per series on shared
// axes that fit the data, a legend with each series' latest value, and optional markers (vertical
// lines, e.g. frames where an estimate was rejected). Painted with QPainter; cheap enough to
// update every frame.
#pragma once

#include <QColor>
#include <QString>
#include <QWidget>
#include <deque>
#include <vector>

namespace sightline {

// Usage:
//   auto* plot = new TimeSeriesPlot(tr("ms per stage"), parent);
//   plot->SetCapacity(300);                       // keep the last 300 samples
//   plot->Append("tracking", frame, tracking_ms, Qt::green);
//   plot->AddMarker(frame);                       // e.g. a gated frame
class TimeSeriesPlot : public QWidget {
  Q_OBJECT

 public:
  explicit TimeSeriesPlot(const QString& title = {}, QWidget* parent = nullptr);

  // Samples kept per series (older ones are dropped, with markers before the oldest sample).
  void SetCapacity(int samples);
  int capacity() const { return capacity_; }
  // Appends a sample; creates the series (drawn in `color`) on first use. Non-finite y values
  // are skipped. x must not decrease within a series.
  void Append(const QString& series, double x, double y, const QColor& color = Qt::white);
  // A vertical line at x.
  void AddMarker(double x);
  // Forgets all samples and markers (series keep their colours).
  void Clear();

  // What is plotted, for tests and tooltips.
  QStringList SeriesNames() const;
  std::vector<QPointF> Samples(const QString& series) const;
  std::vector<double> Markers() const;
  // The plotted data range: x from the oldest to the newest sample, y from min(0, lowest) to
  // the highest value; empty when there is no sample.
  QRectF DataRange() const;

  QSize sizeHint() const override;
  QSize minimumSizeHint() const override;

 protected:
  void paintEvent(QPaintEvent* event) override;

 private:
  struct Series {
    QString name;
    QColor color;
    std::deque<QPointF> samples;
  };
  Series* Find(const QString& name);
  const Series* Find(const QString& name) const;
  void DropMarkersBefore(double x);

  QString title_;
  int capacity_ = 500;
  std::vector<Series> series_;
  std::deque<double> markers_;
};

}  // namespace sightline
