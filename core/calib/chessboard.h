// Chessboard detection for camera calibration: the board's geometry (inner corners and square
// size), corner detection with sub-pixel refinement, and the board's corners in its own frame.
#pragma once

#include <opencv2/core.hpp>
#include <string>
#include <vector>

#include "core/common/status.h"
#include "core/options/option_table.h"

namespace sightline {

// The calibration board and how to find it. Keys "calib.board.*".
struct ChessboardOptions {
  int columns = 9;               // Inner corners along a row (squares per row minus one).
  int rows = 6;                  // Inner corners along a column.
  double square_size_m = 0.025;  // Edge of one square, metres.
  // Use cv::findChessboardCornersSB (sector-based, more robust to blur) instead of the classic
  // detector followed by cornerSubPix.
  bool sector_based = false;
  int subpix_half_window = 11;  // cornerSubPix half window, pixels (classic detector only).

  bool IsValid(std::string* error) const;
  static OptionTable<ChessboardOptions> Describe();

  // "9x6".
  std::string SizeText() const;
  // The inner corners in the board frame (z = 0), row by row, metres.
  std::vector<cv::Point3f> ObjectPoints() const;
};

// Parses "COLSxROWS" (e.g. "9x6") into options->columns / rows. InvalidArgument naming the text.
Status ParseBoardSize(const std::string& text, ChessboardOptions* options);

// One image in which the board was found.
struct BoardView {
  std::string name;                  // File name or frame label, for reports.
  cv::Size image_size;               // Pixels.
  std::vector<cv::Point2f> corners;  // Inner corners in the order of ObjectPoints(), pixels.
  double time_s = -1;                // Timestamp of a source frame, seconds; -1 for files.
  std::string path;                  // The image file; empty for source frames.
};

// Finds the board in a grey or BGR image. Returns false when it is not found completely.
bool FindChessboard(const cv::Mat& image, const ChessboardOptions& options,
                    std::vector<cv::Point2f>* corners);

}  // namespace sightline
