#include "core/calib/mono_calibration.h"

#include <algorithm>
#include <opencv2/calib3d.hpp>

namespace sightline {

bool MonoCalibrationOptions::IsValid(std::string* error) const {
  auto fail = [&](const std::string& m) {
    if (error) *error = "calib.mono." + m;
    return false;
  };
  if (min_views < 3 || min_views > 1000) return fail("min_views must lie in [3, 1000]");
  if (!(max_view_error_px >= 0)) return fail("max_view_error_px must be >= 0 (0 = off)");
  if (!(max_view_error_ratio == 0 || max_view_error_ratio >= 1)) {
    return fail("max_view_error_ratio must be 0 (off) or >= 1");
  }
  return true;
}

OptionTable<MonoCalibrationOptions> MonoCalibrationOptions::Describe() {
  using O = MonoCalibrationOptions;
  return OptionTable<O>("calib.mono")
      .Int("min_views", &O::min_views, "", 3, 1000, 1, "Fewer accepted board views is an error.")
      .Bool("fix_k3", &O::fix_k3, "Estimate k1 k2 p1 p2 only; k3 stays 0.")
      .Bool("zero_tangential", &O::zero_tangential, "Force the tangential distortion to zero.")
      .Bool("fix_aspect_ratio", &O::fix_aspect_ratio, "Estimate one focal length (fx = fy).")
      .Double("max_view_error_px", &O::max_view_error_px, "px", 0, 100, 0.1,
              "Reject views whose RMS reprojection error exceeds this (0 = keep all).")
      .Double("max_view_error_ratio", &O::max_view_error_ratio, "", 0, 100, 0.5,
              "Reject views above this multiple of the median view error (0 = off).");
}

int MonoCalibration::rejected() const {
  return static_cast<int>(
      std::count_if(views.begin(), views.end(), [](const ViewError& v) { return v.rejected; }));
}

namespace calib_internal {

cv::Mat CameraMatrix(const PinholeCamera& c) {
  return (cv::Mat_<double>(3, 3) << c.fx, 0, c.cx, 0, c.fy, c.cy, 0, 0, 1);
}

cv::Mat DistortionVector(const PinholeCamera& c) {
  cv::Mat d(1, 5, CV_64F);
  for (int i = 0; i < 5; ++i) d.at<double>(0, i) = c.distortion[i];
  return d;
}

PinholeCamera ToCamera(const cv::Mat& k, const cv::Mat& d, cv::Size size) {
  PinholeCamera c;
  c.width = size.width;
  c.height = size.height;
  c.fx = k.at<double>(0, 0);
  c.fy = k.at<double>(1, 1);
  c.cx = k.at<double>(0, 2);
  c.cy = k.at<double>(1, 2);
  for (int i = 0; i < 5 && i < static_cast<int>(d.total()); ++i) {
    c.distortion[i] = d.at<double>(i);
  }
  return c;
}

Status CheckViews(const std::vector<BoardView>& views, const ChessboardOptions& board,
                  int min_views, const std::string& what, const std::string& min_key) {
  std::string error;
  if (!board.IsValid(&error)) return InvalidArgument(error);
  if (static_cast<int>(views.size()) < min_views) {
    return InvalidArgument(what + ": " + std::to_string(views.size()) + " views with a " +
                           board.SizeText() + " board, at least " + std::to_string(min_views) +
                           " needed (" + min_key + ")");
  }
  const size_t corners = static_cast<size_t>(board.columns) * board.rows;
  for (const BoardView& view : views) {
    if (view.image_size != views[0].image_size) {
      return InvalidArgument(what + ": view '" + view.name + "' is " +
                             std::to_string(view.image_size.width) + "x" +
                             std::to_string(view.image_size.height) + " but '" + views[0].name +
                             "' is " + std::to_string(views[0].image_size.width) + "x" +
                             std::to_string(views[0].image_size.height));
    }
    if (view.corners.size() != corners) {
      return InvalidArgument(what + ": view '" + view.name + "' has " +
                             std::to_string(view.corners.size()) + " corners, the " +
                             board.SizeText() + " board has " + std::to_string(corners));
    }
  }
  return Status::Ok();
}

}  // namespace calib_internal

namespace {

using calib_internal::ToCamera;

struct Fit {
  cv::Mat k, d;
  std::vector<cv::Mat> rvecs, tvecs;
  std::vector<double> view_errors;
  double rms = 0;
};

int Flags(const MonoCalibrationOptions& o) {
  int flags = 0;
  if (o.fix_k3) flags |= cv::CALIB_FIX_K3;
  if (o.zero_tangential) flags |= cv::CALIB_ZERO_TANGENT_DIST;
  if (o.fix_aspect_ratio) flags |= cv::CALIB_FIX_ASPECT_RATIO;
  return flags;
}

Fit Calibrate(const std::vector<BoardView>& views, const std::vector<int>& used,
              const ChessboardOptions& board, int flags) {
  const std::vector<cv::Point3f> object = board.ObjectPoints();
  std::vector<std::vector<cv::Point3f>> objects(used.size(), object);
  std::vector<std::vector<cv::Point2f>> images;
  images.reserve(used.size());
  for (int i : used) images.push_back(views[i].corners);
  Fit fit;
  fit.k = cv::Mat::eye(3, 3, CV_64F);
  fit.d = cv::Mat::zeros(1, 5, CV_64F);
  cv::Mat std_intrinsics, std_extrinsics, view_errors;
  fit.rms = cv::calibrateCamera(objects, images, views[0].image_size, fit.k, fit.d, fit.rvecs,
                                fit.tvecs, std_intrinsics, std_extrinsics, view_errors, flags);
  for (int i = 0; i < view_errors.rows; ++i) fit.view_errors.push_back(view_errors.at<double>(i));
  return fit;
}

// Indices (into `used`) of the views the options reject.
std::vector<size_t> Outliers(const Fit& fit, const MonoCalibrationOptions& o) {
  std::vector<double> sorted = fit.view_errors;
  std::sort(sorted.begin(), sorted.end());
  const double median = sorted.empty() ? 0 : sorted[sorted.size() / 2];
  std::vector<size_t> out;
  for (size_t i = 0; i < fit.view_errors.size(); ++i) {
    const double e = fit.view_errors[i];
    if ((o.max_view_error_px > 0 && e > o.max_view_error_px) ||
        (o.max_view_error_ratio > 0 && e > o.max_view_error_ratio * median)) {
      out.push_back(i);
    }
  }
  return out;
}

}  // namespace

StatusOr<MonoCalibration> CalibrateMono(const std::vector<BoardView>& views,
                                        const ChessboardOptions& board,
                                        const MonoCalibrationOptions& options,
                                        const CoverageOptions& coverage) {
  std::string error;
  if (!options.IsValid(&error) || !coverage.IsValid(&error)) return InvalidArgument(error);
  SIGHTLINE_RETURN_IF_ERROR(calib_internal::CheckViews(views, board, options.min_views,
                                                       "mono calibration", "calib.mono.min_views"));
  MonoCalibration result;
  result.views.resize(views.size());
  for (size_t i = 0; i < views.size(); ++i) {
    result.views[i].name = views[i].name;
    result.used.push_back(static_cast<int>(i));
  }
  const int flags = Flags(options);
  Fit fit;
  try {
    fit = Calibrate(views, result.used, board, flags);
    const std::vector<size_t> outliers = Outliers(fit, options);
    if (!outliers.empty()) {
      std::vector<int> kept;
      for (size_t j = 0; j < result.used.size(); ++j) {
        const int view = result.used[j];
        result.views[view].rms_px = fit.view_errors[j];
        if (std::find(outliers.begin(), outliers.end(), j) != outliers.end()) {
          result.views[view].rejected = true;
        } else {
          kept.push_back(view);
        }
      }
      if (static_cast<int>(kept.size()) < options.min_views) {
        return InvalidArgument(
            "mono calibration: only " + std::to_string(kept.size()) +
            " views left after rejecting views above " + std::to_string(options.max_view_error_px) +
            " px (calib.mono.max_view_error_px); " + std::to_string(options.min_views) + " needed");
      }
      result.used = kept;
      fit = Calibrate(views, result.used, board, flags);
    }
  } catch (const cv::Exception& e) {
    return InvalidArgument("mono calibration failed: " + std::string(e.what()));
  }
  result.camera = ToCamera(fit.k, fit.d, views[0].image_size);
  result.rms_px = fit.rms;
  std::vector<BoardView> accepted;
  for (size_t j = 0; j < result.used.size(); ++j) {
    result.views[result.used[j]].rms_px = fit.view_errors[j];
    result.rvecs.emplace_back(fit.rvecs[j]);
    result.tvecs.emplace_back(fit.tvecs[j]);
    accepted.push_back(views[result.used[j]]);
  }
  result.coverage = ComputeCoverage(accepted, views[0].image_size, coverage);
  SetCoverageTilts(result.rvecs, &result.coverage);
  Status valid = result.camera.Validate();
  if (!valid.ok())
    return InvalidArgument("mono calibration gave an invalid camera: " + valid.message());
  return result;
}

}  // namespace sightline
