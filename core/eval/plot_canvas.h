// A small 2D chart drawn with OpenCV imgproc: data-to-pixel mapping, axes with round-number
// ticks and labels, polylines, markers and a legend. No highgui: the image is for PNG files and
// for the GUI's image view.
#pragma once

#include <Eigen/Core>
#include <opencv2/core.hpp>
#include <string>
#include <utility>
#include <vector>

namespace sightline {

// Round tick values (1, 2 or 5 times a power of ten) covering [min, max], about `target_count`.
std::vector<double> NiceTicks(double min, double max, int target_count);

// One chart on a white BGR image.
//
//   PlotCanvas canvas(800, 600, {0, 10}, {0, 2}, /*equal_aspect=*/false);
//   canvas.DrawAxes("time [s]", "error [m]");
//   canvas.DrawPolyline(points, PlotCanvas::kRed);
//   canvas.DrawLegend({{"ATE", PlotCanvas::kRed}});
//   cv::imwrite("plot.png", canvas.image());
class PlotCanvas {
 public:
  // An inclusive data interval along one axis.
  struct Range {
    double min = 0;
    double max = 1;
  };

  static const cv::Scalar kBlue;
  static const cv::Scalar kRed;
  static const cv::Scalar kBlack;

  // Pads the ranges by a margin, widens empty ones, and with `equal_aspect` widens one range so
  // that a metre is as many pixels across as up (top views must not look stretched).
  PlotCanvas(int width, int height, Range x, Range y, bool equal_aspect);

  // Frame, ticks with labels, grid lines and the axis labels.
  void DrawAxes(const std::string& x_label, const std::string& y_label);
  // A centred title above the plot area.
  void DrawTitle(const std::string& title);
  // A line through data points, clipped to the plot area.
  void DrawPolyline(const std::vector<Eigen::Vector2d>& points, const cv::Scalar& color,
                    int thickness = 2);
  // A horizontal dashed line at data height y.
  void DrawDashedHorizontal(double y, const cv::Scalar& color);
  // A circle (filled) or a square (outline) marker at a data point.
  void DrawMarker(const Eigen::Vector2d& point, const cv::Scalar& color, bool filled_circle);
  // Small grey text in the bottom-left corner of the image, for a remark such as marker meanings.
  void DrawNote(const std::string& note);
  // A boxed legend in the top-right corner of the plot area.
  void DrawLegend(const std::vector<std::pair<std::string, cv::Scalar>>& entries);

  // The chart so far (BGR, 8 bits per channel).
  const cv::Mat& image() const { return image_; }

 private:
  cv::Point2d ToPixel(const Eigen::Vector2d& point) const;

  cv::Mat image_;
  cv::Rect area_;  // Plot area inside the margins.
  Range x_;
  Range y_;
};

}  // namespace sightline
