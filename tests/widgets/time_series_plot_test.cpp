#include "widgets/time_series_plot.h"

#include <gtest/gtest.h>

#include <QImage>
#include <cmath>

namespace sightline {
namespace {

// Pixels of `image` within a few grey levels of `color`.
int CountColor(const QImage& image, const QColor& color) {
  int n = 0;
  for (int y = 0; y < image.height(); ++y) {
    for (int x = 0; x < image.width(); ++x) {
      const QColor c = image.pixelColor(x, y);
      n += std::abs(c.red() - color.red()) < 12 && std::abs(c.green() - color.green()) < 12 &&
           std::abs(c.blue() - color.blue()) < 12;
    }
  }
  return n;
}

TEST(TimeSeriesPlot, KeepsTheLastSamplesAndFitsTheirRange) {
  TimeSeriesPlot plot("counts");
  plot.SetCapacity(10);
  for (int i = 0; i < 25; ++i) {
    plot.Append("tracks", i, 100 + i, Qt::green);
    plot.Append("inliers", i, 50 + 2 * i, Qt::yellow);
  }
  plot.Append("inliers", 25, std::nan(""));  // Skipped.
  EXPECT_EQ(plot.SeriesNames(), (QStringList{"tracks", "inliers"}));
  const std::vector<QPointF> tracks = plot.Samples("tracks");
  ASSERT_EQ(tracks.size(), 10u);
  EXPECT_EQ(tracks.front(), QPointF(15, 115));
  EXPECT_EQ(tracks.back(), QPointF(24, 124));
  EXPECT_EQ(plot.Samples("inliers").size(), 10u);
  EXPECT_TRUE(plot.Samples("unknown").empty());
  // x from the oldest kept sample to the newest, y from 0 to the highest value.
  const QRectF range = plot.DataRange();
  EXPECT_DOUBLE_EQ(range.left(), 15);
  EXPECT_DOUBLE_EQ(range.right(), 24);
  EXPECT_DOUBLE_EQ(range.top(), 0);
  EXPECT_DOUBLE_EQ(range.bottom(), 124);
}

TEST(TimeSeriesPlot, MarkersFollowTheWindowAndClearEmptiesEverything) {
  TimeSeriesPlot plot;
  plot.SetCapacity(5);
  plot.AddMarker(1);
  plot.AddMarker(8);
  for (int i = 0; i < 10; ++i) plot.Append("ms", i, 0.5 * i);
  EXPECT_EQ(plot.Markers(), std::vector<double>{8});  // 1 fell out of the window (5..9).
  plot.Clear();
  EXPECT_TRUE(plot.Samples("ms").empty());
  EXPECT_TRUE(plot.Markers().empty());
  EXPECT_TRUE(plot.DataRange().isNull());
  EXPECT_EQ(plot.SeriesNames(), QStringList{"ms"});
}

TEST(TimeSeriesPlot, PaintsEachSeriesInItsColour) {
  TimeSeriesPlot plot("per frame");
  plot.resize(300, 140);
  const QColor green(40, 220, 40), orange(255, 150, 0);
  const QImage empty = plot.grab().toImage();
  EXPECT_EQ(CountColor(empty, green), 0);
  for (int i = 0; i < 50; ++i) {
    plot.Append("rising", i, i, green);
    plot.Append("flat", i, 10, orange);
  }
  plot.AddMarker(25);
  const QImage image = plot.grab().toImage();
  // A polyline across the plot is at least as many pixels as the plot is wide, minus margins.
  EXPECT_GT(CountColor(image, green), 150);
  EXPECT_GT(CountColor(image, orange), 150);
  // The rising line climbs: its pixels on the right lie higher than on the left.
  auto mean_row = [&](int x0, int x1) {
    double sum = 0;
    int n = 0;
    for (int y = 0; y < image.height(); ++y) {
      for (int x = x0; x < x1; ++x) {
        const QColor c = image.pixelColor(x, y);
        if (std::abs(c.green() - 220) < 12 && c.red() < 60 && c.blue() < 60) sum += y, ++n;
      }
    }
    return n > 0 ? sum / n : -1.0;
  };
  const double left = mean_row(60, 110), right = mean_row(220, 290);
  ASSERT_GT(left, 0);
  ASSERT_GT(right, 0);
  EXPECT_LT(right, left - 20);
}

}  // namespace
}  // namespace sightline
