#include "core/eval/trajectory_plot.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <opencv2/imgcodecs.hpp>

#include "core/eval/plot_canvas.h"

namespace sightline {

const char* PlotPlaneName(PlotPlane plane) {
  switch (plane) {
    case PlotPlane::kAuto:
      return "auto";
    case PlotPlane::kXZ:
      return "xz";
    case PlotPlane::kXY:
      return "xy";
  }
  return "?";
}

StatusOr<PlotPlane> ParsePlotPlane(const std::string& text) {
  for (PlotPlane p : {PlotPlane::kAuto, PlotPlane::kXZ, PlotPlane::kXY}) {
    if (text == PlotPlaneName(p)) return p;
  }
  return InvalidArgument("unknown plot plane '" + text + "' (expected xz, xy or auto)");
}

PlotPlane ResolvePlotPlane(PlotPlane plane, const std::vector<Eigen::Vector3d>& positions) {
  if (plane != PlotPlane::kAuto) return plane;
  if (positions.empty()) return PlotPlane::kXY;
  Eigen::Vector3d lo = positions.front();
  Eigen::Vector3d hi = positions.front();
  for (const Eigen::Vector3d& p : positions) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  const Eigen::Vector3d extent = hi - lo;
  return extent.y() < extent.z() ? PlotPlane::kXZ : PlotPlane::kXY;
}

namespace {

std::vector<Eigen::Vector2d> Project(const std::vector<Eigen::Vector3d>& points, PlotPlane plane) {
  std::vector<Eigen::Vector2d> projected;
  projected.reserve(points.size());
  const int vertical = plane == PlotPlane::kXZ ? 2 : 1;
  for (const Eigen::Vector3d& p : points) projected.emplace_back(p.x(), p(vertical));
  return projected;
}

// The bounding ranges of point sets.
void Extend(const std::vector<Eigen::Vector2d>& points, PlotCanvas::Range* x,
            PlotCanvas::Range* y) {
  for (const Eigen::Vector2d& p : points) {
    x->min = std::min(x->min, p.x());
    x->max = std::max(x->max, p.x());
    y->min = std::min(y->min, p.y());
    y->max = std::max(y->max, p.y());
  }
}

}  // namespace

cv::Mat DrawTopView(const TrajectoryErrors& errors, PlotPlane plane, PlotSize size) {
  plane = ResolvePlotPlane(plane, errors.ground_truth_positions);
  const std::vector<Eigen::Vector2d> gt = Project(errors.ground_truth_positions, plane);
  const std::vector<Eigen::Vector2d> est = Project(errors.estimate_positions, plane);
  PlotCanvas::Range x{1e300, -1e300};
  PlotCanvas::Range y{1e300, -1e300};
  Extend(gt, &x, &y);
  Extend(est, &x, &y);
  if (gt.empty() && est.empty()) x = y = {0, 1};
  PlotCanvas canvas(size.width, size.height, x, y, /*equal_aspect=*/true);
  const char* vertical = plane == PlotPlane::kXZ ? "z [m]" : "y [m]";
  canvas.DrawAxes("x [m]", vertical);
  char title[160];
  std::snprintf(title, sizeof(title), "Top view (%s plane), alignment %s, ATE RMSE %.3f m",
                plane == PlotPlane::kXZ ? "x-z" : "x-y", AlignmentModeName(errors.alignment),
                errors.ate.rmse);
  canvas.DrawTitle(title);
  canvas.DrawPolyline(gt, PlotCanvas::kBlue);
  canvas.DrawPolyline(est, PlotCanvas::kRed);
  for (const auto* line : {&gt, &est}) {
    if (line->empty()) continue;
    const cv::Scalar color = line == &gt ? PlotCanvas::kBlue : PlotCanvas::kRed;
    canvas.DrawMarker(line->front(), color, /*filled_circle=*/true);
    canvas.DrawMarker(line->back(), color, /*filled_circle=*/false);
  }
  canvas.DrawLegend({{"ground truth", PlotCanvas::kBlue}, {"estimate", PlotCanvas::kRed}});
  canvas.DrawNote("dot: start, square: end");
  return canvas.image().clone();
}

cv::Mat DrawAteOverTime(const TrajectoryErrors& errors, PlotSize size) {
  std::vector<Eigen::Vector2d> points;
  const double t0 = errors.times_s.empty() ? 0.0 : errors.times_s.front();
  double max_error = 0;
  for (size_t i = 0; i < errors.ate_m.size() && i < errors.times_s.size(); ++i) {
    points.emplace_back(errors.times_s[i] - t0, errors.ate_m[i]);
    max_error = std::max(max_error, errors.ate_m[i]);
  }
  const double duration = points.empty() ? 1.0 : points.back().x();
  PlotCanvas canvas(size.width, size.height, {0, duration > 0 ? duration : 1.0},
                    {0, max_error > 0 ? 1.25 * max_error : 1e-3},  // Headroom for the legend.
                    /*equal_aspect=*/false);
  canvas.DrawAxes("time since first pose [s]", "ATE [m]");
  char title[160];
  std::snprintf(title, sizeof(title), "Absolute trajectory error over time (alignment %s)",
                AlignmentModeName(errors.alignment));
  canvas.DrawTitle(title);
  canvas.DrawDashedHorizontal(errors.ate.rmse, PlotCanvas::kBlack);
  canvas.DrawPolyline(points, PlotCanvas::kRed);
  char rmse[64];
  std::snprintf(rmse, sizeof(rmse), "RMSE %.4f m", errors.ate.rmse);
  canvas.DrawLegend({{"ATE per pose", PlotCanvas::kRed}, {rmse, PlotCanvas::kBlack}});
  return canvas.image().clone();
}

Status WriteEvaluationPlots(const TrajectoryErrors& errors, const std::string& dir, PlotPlane plane,
                            PlotSize size) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec) return NotFound("cannot create plot folder " + dir + ": " + ec.message());
  const std::vector<std::pair<std::string, cv::Mat>> images = {
      {dir + "/top_view.png", DrawTopView(errors, plane, size)},
      {dir + "/ate_over_time.png", DrawAteOverTime(errors, size)},
  };
  for (const auto& [path, image] : images) {
    bool written = false;
    try {
      written = cv::imwrite(path, image);
    } catch (const cv::Exception& e) {
      return Unavailable("cannot write " + path + ": " + e.what());
    }
    if (!written) return Unavailable("cannot write " + path);
  }
  return Status::Ok();
}

}  // namespace sightline
