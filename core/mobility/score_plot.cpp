#include "core/mobility/score_plot.h"

#include <cstdio>
#include <opencv2/imgproc.hpp>
#include <vector>

#include "core/mobility/mobility_map.h"

namespace sightline {

cv::Mat RenderScoreSurface(const GprScore& gpr, int width, int height) {
  constexpr int kLeft = 44, kBottom = 30, kTop = 8, kRight = 8;
  constexpr double kMaxSlope = 60, kMinRough = 1.0, kMaxRough = 2.4;
  cv::Mat image(height + kTop + kBottom, width + kLeft + kRight, CV_8UC3, cv::Scalar(30, 30, 30));
  auto to_x = [&](double slope) { return kLeft + static_cast<int>(slope / kMaxSlope * width); };
  auto to_y = [&](double rough) {
    return kTop + height - static_cast<int>((rough - kMinRough) / (kMaxRough - kMinRough) * height);
  };
  for (int y = 0; y < height; ++y) {
    const double rough = kMaxRough - (y + 0.5) / height * (kMaxRough - kMinRough);
    for (int x = 0; x < width; ++x) {
      const double slope = (x + 0.5) / width * kMaxSlope;
      image.at<cv::Vec3b>(kTop + y, kLeft + x) =
          ScoreColorBgr(static_cast<float>(gpr.Predict(slope, rough)));
    }
  }
  const cv::Scalar grid(60, 60, 60), text(220, 220, 220);
  char label[16];
  for (int s = 0; s <= 60; s += 10) {
    cv::line(image, {to_x(s), kTop}, {to_x(s), kTop + height}, grid, 1);
    std::snprintf(label, sizeof(label), "%d", s);
    cv::putText(image, label, {to_x(s) - 6, kTop + height + 14}, cv::FONT_HERSHEY_PLAIN, 0.9, text);
  }
  for (int k = 0; k <= 7; ++k) {
    const double r = 1.0 + 0.2 * k;
    cv::line(image, {kLeft, to_y(r)}, {kLeft + width, to_y(r)}, grid, 1);
    std::snprintf(label, sizeof(label), "%.1f", r);
    cv::putText(image, label, {4, to_y(r) + 4}, cv::FONT_HERSHEY_PLAIN, 0.9, text);
  }
  cv::putText(image, "slope [deg]", {kLeft + width / 2 - 40, kTop + height + 27},
              cv::FONT_HERSHEY_PLAIN, 0.9, text);
  std::vector<Eigen::Vector2d> centres;
  std::vector<double> scores;
  TableCellCentres(&centres, &scores);
  for (size_t i = 0; i < centres.size(); ++i) {
    if (centres[i].y() > kMaxRough) continue;
    const cv::Point p(to_x(centres[i].x()), to_y(centres[i].y()));
    const cv::Vec3b c = ScoreColorBgr(static_cast<float>(scores[i]));
    cv::circle(image, p, 6, cv::Scalar(c[0], c[1], c[2]), -1, cv::LINE_AA);
    cv::circle(image, p, 6, cv::Scalar(255, 255, 255), 1, cv::LINE_AA);
  }
  return image;
}

}  // namespace sightline
