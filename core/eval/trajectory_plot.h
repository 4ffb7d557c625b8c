// Pictures of an evaluation: the top view of estimate and ground truth, and the ATE over time.
// `sightline-cli eval --plot DIR` writes them as PNG; the GUI shows the same images.
#pragma once

#include <Eigen/Core>
#include <opencv2/core.hpp>
#include <string>
#include <vector>

#include "core/common/status.h"
#include "core/eval/evaluation.h"

namespace sightline {

// The plane a top view shows.
enum class PlotPlane {
  kAuto,  // x-z or x-y, whichever drops the axis (y or z) along which the ground truth varies less.
  kXZ,    // Camera optical frames (KITTI): x right, z forward, y down.
  kXY,    // z-up worlds (TUM RGB-D motion capture, EuRoC, ROS).
};

// "auto", "xz", "xy".
const char* PlotPlaneName(PlotPlane plane);
// Parses "auto", "xz" or "xy"; the error lists the choices.
StatusOr<PlotPlane> ParsePlotPlane(const std::string& text);
// Resolves kAuto for these positions; other planes are returned unchanged.
PlotPlane ResolvePlotPlane(PlotPlane plane, const std::vector<Eigen::Vector3d>& positions);

// Image size of the plots [px].
struct PlotSize {
  int width = 960;
  int height = 720;
};

// Ground truth (blue) and aligned estimate (red) seen from above, equal scale on both axes, start
// marked with a dot and end with a square. A BGR image.
cv::Mat DrawTopView(const TrajectoryErrors& errors, PlotPlane plane, PlotSize size = {});

// ATE of each associated pose against time since the first one, with the RMSE dashed. BGR.
cv::Mat DrawAteOverTime(const TrajectoryErrors& errors, PlotSize size = {});

// Writes DIR/top_view.png and DIR/ate_over_time.png, creating DIR if needed. Errors name the file.
Status WriteEvaluationPlots(const TrajectoryErrors& errors, const std::string& dir, PlotPlane plane,
                            PlotSize size = {});

}  // namespace sightline
