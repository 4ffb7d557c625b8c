#include "core/calib/coverage.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <opencv2/calib3d.hpp>
#include <opencv2/imgproc.hpp>

namespace sightline {

bool CoverageOptions::IsValid(std::string* error) const {
  if (grid_columns < 1 || grid_rows < 1 || grid_columns > 64 || grid_rows > 64) {
    if (error) *error = "calib.coverage.grid_columns and grid_rows must lie in [1, 64]";
    return false;
  }
  return true;
}

OptionTable<CoverageOptions> CoverageOptions::Describe() {
  using O = CoverageOptions;
  return OptionTable<O>("calib.coverage")
      .Int("grid_columns", &O::grid_columns, "", 1, 64, 1, "Coverage cells across the image.")
      .Int("grid_rows", &O::grid_rows, "", 1, 64, 1, "Coverage cells down the image.");
}

Coverage ComputeCoverage(const std::vector<BoardView>& views, cv::Size image_size,
                         const CoverageOptions& options) {
  Coverage c;
  c.grid_columns = options.grid_columns;
  c.grid_rows = options.grid_rows;
  c.cell_views.assign(static_cast<size_t>(c.grid_columns) * c.grid_rows, 0);
  c.views = static_cast<int>(views.size());
  if (views.empty() || image_size.width <= 0 || image_size.height <= 0) return c;
  const double w = image_size.width, h = image_size.height;
  c.x_min = c.y_min = c.scale_min = 1;
  for (const BoardView& view : views) {
    std::vector<char> seen(c.cell_views.size(), 0);
    for (const cv::Point2f& p : view.corners) {
      const double x = std::clamp(p.x / w, 0.0, 1.0), y = std::clamp(p.y / h, 0.0, 1.0);
      c.x_min = std::min(c.x_min, x);
      c.x_max = std::max(c.x_max, x);
      c.y_min = std::min(c.y_min, y);
      c.y_max = std::max(c.y_max, y);
      const int col = std::min(static_cast<int>(x * c.grid_columns), c.grid_columns - 1);
      const int row = std::min(static_cast<int>(y * c.grid_rows), c.grid_rows - 1);
      seen[static_cast<size_t>(row) * c.grid_columns + col] = 1;
    }
    for (size_t i = 0; i < seen.size(); ++i) c.cell_views[i] += seen[i];
    std::vector<cv::Point2f> hull;
    cv::convexHull(view.corners, hull);
    const double scale = std::sqrt(std::max(0.0, cv::contourArea(hull)) / (w * h));
    c.scale_min = std::min(c.scale_min, scale);
    c.scale_max = std::max(c.scale_max, scale);
  }
  const auto covered =
      std::count_if(c.cell_views.begin(), c.cell_views.end(), [](int n) { return n > 0; });
  c.cells_covered = static_cast<double>(covered) / c.cell_views.size();
  return c;
}

void SetCoverageTilts(const std::vector<cv::Vec3d>& rvecs, Coverage* coverage) {
  if (rvecs.empty()) return;
  coverage->tilt_min_deg = 180;
  coverage->tilt_max_deg = 0;
  for (const cv::Vec3d& rvec : rvecs) {
    cv::Matx33d r;
    cv::Rodrigues(rvec, r);
    const double tilt = std::acos(std::min(1.0, std::abs(r(2, 2)))) * 180.0 / M_PI;
    coverage->tilt_min_deg = std::min(coverage->tilt_min_deg, tilt);
    coverage->tilt_max_deg = std::max(coverage->tilt_max_deg, tilt);
  }
}

std::string Coverage::Summary() const {
  const int covered = static_cast<int>(std::lround(cells_covered * cell_views.size()));
  char text[256];
  std::snprintf(text, sizeof(text),
                "%d views; cells %d/%zu (%.0f %%), x %.2f-%.2f, y %.2f-%.2f, size %.2f-%.2f", views,
                covered, cell_views.size(), 100 * cells_covered, x_min, x_max, y_min, y_max,
                scale_min, scale_max);
  std::string summary = text;
  if (tilt_max_deg >= 0) {
    std::snprintf(text, sizeof(text), ", tilt %.0f-%.0f deg", tilt_min_deg, tilt_max_deg);
    summary += text;
  }
  return summary;
}

std::vector<std::string> Coverage::Hints() const {
  std::vector<std::string> hints;
  if (views == 0) return {"no views yet: show the board to the camera"};
  const double kEdge = 0.15;
  if (x_min > kEdge) hints.push_back("no corners near the left edge");
  if (x_max < 1 - kEdge) hints.push_back("no corners near the right edge");
  if (y_min > kEdge) hints.push_back("no corners near the top edge");
  if (y_max < 1 - kEdge) hints.push_back("no corners near the bottom edge");
  if (cells_covered < 0.6) hints.push_back("less than 60 % of the image cells covered");
  if (scale_max < 1.5 * scale_min) hints.push_back("vary the distance: board sizes too similar");
  if (tilt_max_deg >= 0 && tilt_max_deg < 20) {
    hints.push_back("tilt the board more (largest tilt below 20 deg)");
  }
  return hints;
}

}  // namespace sightline
