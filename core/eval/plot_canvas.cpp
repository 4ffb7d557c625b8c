#include "core/eval/plot_canvas.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <opencv2/imgproc.hpp>

namespace sightline {

namespace {

constexpr int kMarginLeft = 78;
constexpr int kMarginRight = 24;
constexpr int kMarginTop = 48;
constexpr int kMarginBottom = 56;
constexpr int kFont = cv::FONT_HERSHEY_SIMPLEX;
constexpr double kFontScale = 0.45;
constexpr int kSubpixelBits = 4;  // Anti-aliased lines at 1/16 pixel.

// Widens an empty or inverted range and adds a 5 % margin on each side.
PlotCanvas::Range Padded(PlotCanvas::Range r) {
  if (!std::isfinite(r.min) || !std::isfinite(r.max)) r = {0, 1};
  if (r.max < r.min) std::swap(r.min, r.max);
  if (r.max - r.min < 1e-9) {
    const double half = std::max(0.5, 0.05 * std::abs(r.min));
    return {r.min - half, r.max + half};
  }
  const double pad = 0.05 * (r.max - r.min);
  return {r.min - pad, r.max + pad};
}

// Widens r about its centre to `span`.
PlotCanvas::Range Widened(PlotCanvas::Range r, double span) {
  const double centre = 0.5 * (r.min + r.max);
  return {centre - 0.5 * span, centre + 0.5 * span};
}

std::string TickLabel(double value, double step) {
  const int decimals = std::max(0, static_cast<int>(std::ceil(-std::log10(step) - 1e-9)));
  char text[32];
  std::snprintf(text, sizeof(text), "%.*f", decimals, std::abs(value) < 1e-12 ? 0.0 : value);
  return text;
}

cv::Point Fixed(const cv::Point2d& p) {
  const double s = 1 << kSubpixelBits;
  return cv::Point(static_cast<int>(std::lround(p.x * s)), static_cast<int>(std::lround(p.y * s)));
}

void PutText(cv::Mat& image, const std::string& text, cv::Point origin, const cv::Scalar& color,
             double scale = kFontScale) {
  cv::putText(image, text, origin, kFont, scale, color, 1, cv::LINE_AA);
}

cv::Size TextSize(const std::string& text, double scale = kFontScale) {
  int baseline = 0;
  return cv::getTextSize(text, kFont, scale, 1, &baseline);
}

}  // namespace

const cv::Scalar PlotCanvas::kBlue(180, 100, 30);
const cv::Scalar PlotCanvas::kRed(40, 40, 220);
const cv::Scalar PlotCanvas::kBlack(30, 30, 30);

std::vector<double> NiceTicks(double min, double max, int target_count) {
  std::vector<double> ticks;
  if (!(max > min) || target_count < 1 || !std::isfinite(min) || !std::isfinite(max)) return ticks;
  const double raw = (max - min) / target_count;
  const double power = std::pow(10.0, std::floor(std::log10(raw)));
  double step = power;
  for (double m : {1.0, 2.0, 5.0, 10.0}) {
    step = m * power;
    if (step >= raw) break;
  }
  // Multiples of step, computed from an integer index so that no error accumulates.
  const double first = std::ceil(min / step - 1e-9);
  for (double k = first; k * step <= max + 1e-9 * step; k += 1) ticks.push_back(k * step + 0.0);
  return ticks;
}

PlotCanvas::PlotCanvas(int width, int height, Range x, Range y, bool equal_aspect)
    : image_(std::max(height, kMarginTop + kMarginBottom + 10),
             std::max(width, kMarginLeft + kMarginRight + 10), CV_8UC3, cv::Scalar(255, 255, 255)),
      area_(kMarginLeft, kMarginTop, image_.cols - kMarginLeft - kMarginRight,
            image_.rows - kMarginTop - kMarginBottom),
      x_(Padded(x)),
      y_(Padded(y)) {
  if (equal_aspect) {
    const double x_per_px = (x_.max - x_.min) / area_.width;
    const double y_per_px = (y_.max - y_.min) / area_.height;
    if (x_per_px > y_per_px) {
      y_ = Widened(y_, x_per_px * area_.height);
    } else {
      x_ = Widened(x_, y_per_px * area_.width);
    }
  }
}

cv::Point2d PlotCanvas::ToPixel(const Eigen::Vector2d& point) const {
  const double u = (point.x() - x_.min) / (x_.max - x_.min) * area_.width;
  const double v = (y_.max - point.y()) / (y_.max - y_.min) * area_.height;
  return {area_.x + u, area_.y + v};
}

void PlotCanvas::DrawAxes(const std::string& x_label, const std::string& y_label) {
  const int target_x = std::max(2, area_.width / 110);
  const int target_y = std::max(2, area_.height / 80);
  const std::vector<double> x_ticks = NiceTicks(x_.min, x_.max, target_x);
  const std::vector<double> y_ticks = NiceTicks(y_.min, y_.max, target_y);
  const double x_step = x_ticks.size() > 1 ? x_ticks[1] - x_ticks[0] : 1.0;
  const double y_step = y_ticks.size() > 1 ? y_ticks[1] - y_ticks[0] : 1.0;
  const int bottom = area_.y + area_.height;
  for (double t : x_ticks) {
    const int u = static_cast<int>(std::lround(ToPixel({t, y_.min}).x));
    cv::line(image_, {u, area_.y}, {u, bottom}, cv::Scalar(235, 235, 235), 1);
    cv::line(image_, {u, bottom}, {u, bottom + 5}, kBlack, 1);
    const std::string label = TickLabel(t, x_step);
    PutText(image_, label, {u - TextSize(label).width / 2, bottom + 20}, kBlack);
  }
  for (double t : y_ticks) {
    const int v = static_cast<int>(std::lround(ToPixel({x_.min, t}).y));
    cv::line(image_, {area_.x, v}, {area_.x + area_.width, v}, cv::Scalar(235, 235, 235), 1);
    cv::line(image_, {area_.x - 5, v}, {area_.x, v}, kBlack, 1);
    const std::string label = TickLabel(t, y_step);
    const cv::Size size = TextSize(label);
    PutText(image_, label, {area_.x - 8 - size.width, v + size.height / 2}, kBlack);
  }
  cv::rectangle(image_, area_, kBlack, 1);
  PutText(image_, x_label,
          {area_.x + area_.width / 2 - TextSize(x_label, 0.5).width / 2, bottom + 44}, kBlack, 0.5);
  // putText cannot rotate, so the y label sits above the axis.
  PutText(image_, y_label, {std::max(4, area_.x - 40), area_.y - 10}, kBlack, 0.5);
}

void PlotCanvas::DrawTitle(const std::string& title) {
  const cv::Size size = TextSize(title, 0.6);
  PutText(image_, title, {area_.x + area_.width / 2 - size.width / 2, 26}, kBlack, 0.6);
}

void PlotCanvas::DrawPolyline(const std::vector<Eigen::Vector2d>& points, const cv::Scalar& color,
                              int thickness) {
  if (points.size() < 2) return;
  cv::Mat plot = image_(area_);  // Drawing into the sub-image clips to the plot area.
  const cv::Point2d offset(area_.x, area_.y);
  std::vector<cv::Point> pixels;
  pixels.reserve(points.size());
  for (const Eigen::Vector2d& p : points) pixels.push_back(Fixed(ToPixel(p) - offset));
  cv::polylines(plot, pixels, false, color, thickness, cv::LINE_AA, kSubpixelBits);
}

void PlotCanvas::DrawDashedHorizontal(double y, const cv::Scalar& color) {
  cv::Mat plot = image_(area_);
  const int v = static_cast<int>(std::lround(ToPixel({x_.min, y}).y)) - area_.y;
  for (int u = 0; u < area_.width; u += 12) {
    cv::line(plot, {u, v}, {std::min(u + 6, area_.width - 1), v}, color, 1, cv::LINE_AA);
  }
}

void PlotCanvas::DrawMarker(const Eigen::Vector2d& point, const cv::Scalar& color,
                            bool filled_circle) {
  cv::Mat plot = image_(area_);
  const cv::Point2d p = ToPixel(point) - cv::Point2d(area_.x, area_.y);
  const cv::Point c(static_cast<int>(std::lround(p.x)), static_cast<int>(std::lround(p.y)));
  if (filled_circle) {
    cv::circle(plot, c, 5, color, cv::FILLED, cv::LINE_AA);
  } else {
    cv::rectangle(plot, c - cv::Point(5, 5), c + cv::Point(5, 5), color, 2, cv::LINE_AA);
  }
}

void PlotCanvas::DrawNote(const std::string& note) {
  PutText(image_, note, {8, image_.rows - 10}, cv::Scalar(110, 110, 110), 0.4);
}

void PlotCanvas::DrawLegend(const std::vector<std::pair<std::string, cv::Scalar>>& entries) {
  if (entries.empty()) return;
  int text_width = 0;
  for (const auto& [label, color] : entries)
    text_width = std::max(text_width, TextSize(label).width);
  const int row = 20;
  const int width = text_width + 50;
  const int height = row * static_cast<int>(entries.size()) + 8;
  const cv::Rect box(area_.x + area_.width - width - 10, area_.y + 10, width, height);
  cv::rectangle(image_, box, cv::Scalar(255, 255, 255), cv::FILLED);
  cv::rectangle(image_, box, kBlack, 1);
  for (size_t i = 0; i < entries.size(); ++i) {
    const int v = box.y + 14 + row * static_cast<int>(i);
    cv::line(image_, {box.x + 8, v}, {box.x + 34, v}, entries[i].second, 2, cv::LINE_AA);
    PutText(image_, entries[i].first, {box.x + 40, v + 5}, kBlack);
  }
}

}  // namespace sightline
