// Coverage feedback for calibration: where in the image, at which sizes and tilts the accepted
// board views lie. A calibration is only as good as the spread of its views, so the CLI prints
// these numbers and the GUI draws the grid.
#pragma once

#include <opencv2/core.hpp>
#include <string>
#include <vector>

#include "core/calib/chessboard.h"
#include "core/options/option_table.h"

namespace sightline {

// The coverage grid. Keys "calib.coverage.*".
struct CoverageOptions {
  int grid_columns = 8;  // Cells across the image.
  int grid_rows = 6;     // Cells down the image.

  bool IsValid(std::string* error) const;
  static OptionTable<CoverageOptions> Describe();
};

// How well a set of views covers the image, sizes and tilts.
struct Coverage {
  int grid_columns = 0, grid_rows = 0;
  std::vector<int> cell_views;  // Row-major: views with at least one corner in each cell.
  double cells_covered = 0;     // Fraction of cells holding a corner of some view, [0, 1].
  // Extent of all corners as fractions of the image width and height, [0, 1].
  double x_min = 0, x_max = 0, y_min = 0, y_max = 0;
  // Board size as sqrt(board area / image area), smallest and largest view, [0, 1].
  double scale_min = 0, scale_max = 0;
  // Angle between the board normal and the optical axis, degrees; negative until poses are known.
  double tilt_min_deg = -1, tilt_max_deg = -1;
  int views = 0;

  // Views in cell (column, row).
  int CellViews(int column, int row) const { return cell_views[row * grid_columns + column]; }
  // One line: "cells 40/48 (83 %), x 0.03-0.97, y 0.05-0.93, size 0.21-0.55, tilt 8-47 deg".
  std::string Summary() const;
  // What to add to improve the spread, e.g. "no corners near the left edge".
  std::vector<std::string> Hints() const;
};

// Coverage of `views` (all of size `image_size`).
Coverage ComputeCoverage(const std::vector<BoardView>& views, cv::Size image_size,
                         const CoverageOptions& options = {});

// Fills the tilt range from board rotations (cv::Rodrigues vectors, camera_from_board).
void SetCoverageTilts(const std::vector<cv::Vec3d>& camera_from_board_rvecs, Coverage* coverage);

}  // namespace sightline
