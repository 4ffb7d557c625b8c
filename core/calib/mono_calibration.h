// Monocular chessboard calibration (cv::calibrateCamera) with per-view reprojection errors and
// rejection of bad views: views far above the rest are dropped and the camera recalibrated.
#pragma once

#include <opencv2/core.hpp>
#include <string>
#include <vector>

#include "core/calib/chessboard.h"
#include "core/calib/coverage.h"
#include "core/common/camera.h"
#include "core/common/status.h"
#include "core/options/option_table.h"

namespace sightline {

// How to calibrate one camera. Keys "calib.mono.*".
struct MonoCalibrationOptions {
  int min_views = 5;              // Fewer accepted views is an error.
  bool fix_k3 = false;            // Estimate k1 k2 p1 p2 only (k3 = 0): wide boards, few views.
  bool zero_tangential = false;   // Force p1 = p2 = 0.
  bool fix_aspect_ratio = false;  // fx = fy.
  // A view whose RMS reprojection error exceeds this is rejected and the camera recalibrated
  // without it (0 = keep every view), pixels.
  double max_view_error_px = 2.0;
  // ...and likewise a view above this multiple of the median view error (0 = off).
  double max_view_error_ratio = 0.0;

  bool IsValid(std::string* error) const;
  static OptionTable<MonoCalibrationOptions> Describe();
};

// The error of one input view.
struct ViewError {
  std::string name;
  double rms_px = 0;      // RMS reprojection error of its corners, pixels.
  bool rejected = false;  // Dropped as an outlier (rms_px is then from the calibration it failed).
};

// A calibrated camera.
struct MonoCalibration {
  PinholeCamera camera;
  double rms_px = 0;                    // RMS over every corner of the accepted views, pixels.
  std::vector<ViewError> views;         // One per input view, in input order.
  std::vector<int> used;                // Indices of the accepted views.
  std::vector<cv::Vec3d> rvecs, tvecs;  // camera_from_board of each accepted view.
  Coverage coverage;                    // Of the accepted views, with tilts.
  int rejected() const;
};

// Calibrates from views of one camera (all the same image size). InvalidArgument with a clear
// reason for too few views, mixed image sizes, wrong corner counts or invalid options.
StatusOr<MonoCalibration> CalibrateMono(const std::vector<BoardView>& views,
                                        const ChessboardOptions& board,
                                        const MonoCalibrationOptions& options = {},
                                        const CoverageOptions& coverage = {});

// Helpers shared with stereo calibration.
namespace calib_internal {
cv::Mat CameraMatrix(const PinholeCamera& camera);
cv::Mat DistortionVector(const PinholeCamera& camera);
PinholeCamera ToCamera(const cv::Mat& k, const cv::Mat& d, cv::Size size);
// Checks sizes and corner counts of views; names the offending view. `min_key` is the option
// that sets min_views, for the message.
Status CheckViews(const std::vector<BoardView>& views, const ChessboardOptions& board,
                  int min_views, const std::string& what, const std::string& min_key);
}  // namespace calib_internal

}  // namespace sightline
