#include "core/calib/chessboard.h"

#include <cstdio>
#include <opencv2/calib3d.hpp>
#include <opencv2/imgproc.hpp>

namespace sightline {

bool ChessboardOptions::IsValid(std::string* error) const {
  auto fail = [&](const std::string& m) {
    if (error) *error = "calib.board." + m;
    return false;
  };
  if (columns < 3 || rows < 3) return fail("columns and rows must be at least 3 inner corners");
  if (columns > 100 || rows > 100) return fail("columns and rows must be at most 100");
  if (!(square_size_m > 0 && square_size_m <= 1)) return fail("square_size_m must lie in (0, 1]");
  if (subpix_half_window < 1 || subpix_half_window > 50) {
    return fail("subpix_half_window must lie in [1, 50] pixels");
  }
  return true;
}

OptionTable<ChessboardOptions> ChessboardOptions::Describe() {
  using O = ChessboardOptions;
  return OptionTable<O>("calib.board")
      .Int("columns", &O::columns, "", 3, 100, 1, "Inner corners along a row of the board.")
      .Int("rows", &O::rows, "", 3, 100, 1, "Inner corners along a column of the board.")
      .Double("square_size_m", &O::square_size_m, "m", 0.001, 1, 0.001,
              "Edge length of one chessboard square.")
      .Bool("sector_based", &O::sector_based,
            "Use the sector-based detector (robust to blur) instead of the classic one.")
      .Int("subpix_half_window", &O::subpix_half_window, "px", 1, 50, 1,
           "Half window of the sub-pixel corner refinement (classic detector).");
}

std::string ChessboardOptions::SizeText() const {
  return std::to_string(columns) + "x" + std::to_string(rows);
}

std::vector<cv::Point3f> ChessboardOptions::ObjectPoints() const {
  std::vector<cv::Point3f> points;
  points.reserve(static_cast<size_t>(columns) * rows);
  for (int r = 0; r < rows; ++r) {
    for (int c = 0; c < columns; ++c) {
      points.emplace_back(static_cast<float>(c * square_size_m),
                          static_cast<float>(r * square_size_m), 0.f);
    }
  }
  return points;
}

Status ParseBoardSize(const std::string& text, ChessboardOptions* options) {
  int columns = 0, rows = 0;
  char tail = 0;
  if (std::sscanf(text.c_str(), "%dx%d%c", &columns, &rows, &tail) != 2 || columns < 3 ||
      rows < 3 || columns > 100 || rows > 100) {
    return InvalidArgument("board size '" + text +
                           "': expected inner corners as COLUMNSxROWS, e.g. 9x6 (3 to 100 each)");
  }
  options->columns = columns;
  options->rows = rows;
  return Status::Ok();
}

bool FindChessboard(const cv::Mat& image, const ChessboardOptions& options,
                    std::vector<cv::Point2f>* corners) {
  corners->clear();
  if (image.empty()) return false;
  cv::Mat gray;
  if (image.channels() == 3) {
    cv::cvtColor(image, gray, cv::COLOR_BGR2GRAY);
  } else if (image.channels() == 4) {
    cv::cvtColor(image, gray, cv::COLOR_BGRA2GRAY);
  } else {
    gray = image;
  }
  if (gray.depth() != CV_8U) gray.convertTo(gray, CV_8U);
  const cv::Size pattern(options.columns, options.rows);
  if (options.sector_based) {
    return cv::findChessboardCornersSB(gray, pattern, *corners,
                                       cv::CALIB_CB_NORMALIZE_IMAGE | cv::CALIB_CB_ACCURACY);
  }
  const bool found = cv::findChessboardCorners(
      gray, pattern, *corners,
      cv::CALIB_CB_ADAPTIVE_THRESH | cv::CALIB_CB_NORMALIZE_IMAGE | cv::CALIB_CB_FAST_CHECK);
  if (!found) {
    corners->clear();
    return false;
  }
  const int w = options.subpix_half_window;
  cv::cornerSubPix(gray, *corners, cv::Size(w, w), cv::Size(-1, -1),
                   cv::TermCriteria(cv::TermCriteria::COUNT + cv::TermCriteria::EPS, 30, 0.01));
  return true;
}

}  // namespace sightline
