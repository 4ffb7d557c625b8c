#include "core/calib/stereo_calibration.h"

#include <Eigen/Core>
#include <algorithm>
#include <opencv2/calib3d.hpp>

namespace sightline {

bool StereoCalibrationOptions::IsValid(std::string* error) const {
  auto fail = [&](const std::string& m) {
    if (error) *error = "calib.stereo." + m;
    return false;
  };
  if (min_pairs < 3 || min_pairs > 1000) return fail("min_pairs must lie in [3, 1000]");
  if (!(max_pair_error_px >= 0)) return fail("max_pair_error_px must be >= 0 (0 = off)");
  if (!(rectify_alpha == -1 || (rectify_alpha >= 0 && rectify_alpha <= 1))) {
    return fail("rectify_alpha must be -1 or lie in [0, 1]");
  }
  return true;
}

OptionTable<StereoCalibrationOptions> StereoCalibrationOptions::Describe() {
  using O = StereoCalibrationOptions;
  return OptionTable<O>("calib.stereo")
      .Int("min_pairs", &O::min_pairs, "", 3, 1000, 1, "Fewer usable stereo pairs is an error.")
      .Bool("fix_intrinsics", &O::fix_intrinsics,
            "Keep each camera's own calibration and estimate only the rig transform.")
      .Double("max_pair_error_px", &O::max_pair_error_px, "px", 0, 100, 0.1,
              "Drop pairs whose RMS error in either image exceeds this (0 = keep all).")
      .Double("rectify_alpha", &O::rectify_alpha, "", -1, 1, 0.05,
              "Free scaling of the rectification: -1 default, 0 valid pixels, 1 all pixels.");
}

int StereoCalibration::used_pairs() const {
  return static_cast<int>(
      std::count_if(pairs.begin(), pairs.end(), [](const PairError& p) { return !p.rejected; }));
}

namespace {

using calib_internal::CameraMatrix;
using calib_internal::DistortionVector;

struct RigFit {
  double rms = 0;
  cv::Mat r, t, e, f, view_errors;
};

RigFit FitRig(const std::vector<BoardView>& left, const std::vector<BoardView>& right,
              const std::vector<int>& used, const ChessboardOptions& board,
              StereoCalibration* result, bool fix_intrinsics) {
  std::vector<std::vector<cv::Point3f>> objects(used.size(), board.ObjectPoints());
  std::vector<std::vector<cv::Point2f>> l, r;
  for (int i : used) {
    l.push_back(left[i].corners);
    r.push_back(right[i].corners);
  }
  cv::Mat k1 = CameraMatrix(result->rig.left), d1 = DistortionVector(result->rig.left);
  cv::Mat k2 = CameraMatrix(result->rig.right), d2 = DistortionVector(result->rig.right);
  RigFit fit;
  const int flags = fix_intrinsics ? cv::CALIB_FIX_INTRINSIC : cv::CALIB_USE_INTRINSIC_GUESS;
  fit.rms = cv::stereoCalibrate(
      objects, l, r, k1, d1, k2, d2, left[0].image_size, fit.r, fit.t, fit.e, fit.f,
      fit.view_errors, flags,
      cv::TermCriteria(cv::TermCriteria::COUNT + cv::TermCriteria::EPS, 100, 1e-6));
  if (!fix_intrinsics) {
    result->rig.left = calib_internal::ToCamera(k1, d1, left[0].image_size);
    result->rig.right = calib_internal::ToCamera(k2, d2, right[0].image_size);
  }
  return fit;
}

void StoreRig(const RigFit& fit, cv::Size size, double alpha, StereoCalibration* result) {
  Eigen::Isometry3d right_from_left = Eigen::Isometry3d::Identity();
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) right_from_left.linear()(r, c) = fit.r.at<double>(r, c);
    right_from_left.translation()(r) = fit.t.at<double>(r);
  }
  result->rig.right_from_left = right_from_left;
  result->rig.rectified = false;
  result->rms_px = fit.rms;
  fit.e.copyTo(cv::Mat(result->essential));
  fit.f.copyTo(cv::Mat(result->fundamental));
  cv::Mat r1, r2, p1, p2, q;
  cv::stereoRectify(CameraMatrix(result->rig.left), DistortionVector(result->rig.left),
                    CameraMatrix(result->rig.right), DistortionVector(result->rig.right), size,
                    fit.r, fit.t, r1, r2, p1, p2, q, cv::CALIB_ZERO_DISPARITY, alpha);
  r1.copyTo(cv::Mat(result->rect_left));
  r2.copyTo(cv::Mat(result->rect_right));
  p1.copyTo(cv::Mat(result->proj_left));
  p2.copyTo(cv::Mat(result->proj_right));
  q.copyTo(cv::Mat(result->disparity_to_depth));
}

}  // namespace

StatusOr<StereoCalibration> CalibrateStereo(const std::vector<BoardView>& left,
                                            const std::vector<BoardView>& right,
                                            const ChessboardOptions& board,
                                            const MonoCalibrationOptions& mono,
                                            const StereoCalibrationOptions& options,
                                            const CoverageOptions& coverage) {
  std::string error;
  if (!options.IsValid(&error)) return InvalidArgument(error);
  if (left.size() != right.size()) {
    return InvalidArgument("stereo calibration: " + std::to_string(left.size()) +
                           " left views but " + std::to_string(right.size()) +
                           " right views; they must pair up one to one");
  }
  if (!left.empty() && left[0].image_size != right[0].image_size) {
    return InvalidArgument("stereo calibration: left images are " +
                           std::to_string(left[0].image_size.width) + "x" +
                           std::to_string(left[0].image_size.height) + ", right images " +
                           std::to_string(right[0].image_size.width) + "x" +
                           std::to_string(right[0].image_size.height));
  }
  StereoCalibration result;
  auto left_mono = CalibrateMono(left, board, mono, coverage);
  if (!left_mono.ok()) return left_mono.status().WithContext("left camera");
  auto right_mono = CalibrateMono(right, board, mono, coverage);
  if (!right_mono.ok()) return right_mono.status().WithContext("right camera");
  result.left = std::move(*left_mono);
  result.right = std::move(*right_mono);
  result.rig.left = result.left.camera;
  result.rig.right = result.right.camera;
  std::vector<int> used;
  for (size_t i = 0; i < left.size(); ++i) {
    PairError pair;
    pair.name = left[i].name + " | " + right[i].name;
    pair.rejected = result.left.views[i].rejected || result.right.views[i].rejected;
    if (!pair.rejected) used.push_back(static_cast<int>(i));
    result.pairs.push_back(pair);
  }
  auto too_few = [&](const std::string& why) {
    return InvalidArgument("stereo calibration: " + std::to_string(used.size()) + " usable pairs " +
                           why + ", at least " + std::to_string(options.min_pairs) +
                           " needed (calib.stereo.min_pairs)");
  };
  if (static_cast<int>(used.size()) < options.min_pairs) return too_few("after mono rejection");
  try {
    RigFit fit = FitRig(left, right, used, board, &result, options.fix_intrinsics);
    std::vector<int> kept;
    for (size_t j = 0; j < used.size(); ++j) {
      PairError& pair = result.pairs[used[j]];
      pair.left_rms_px = fit.view_errors.at<double>(static_cast<int>(j), 0);
      pair.right_rms_px = fit.view_errors.at<double>(static_cast<int>(j), 1);
      const bool bad = options.max_pair_error_px > 0 &&
                       std::max(pair.left_rms_px, pair.right_rms_px) > options.max_pair_error_px;
      pair.rejected = bad;
      if (!bad) kept.push_back(used[j]);
    }
    if (kept.size() != used.size()) {
      used = kept;
      if (static_cast<int>(used.size()) < options.min_pairs) {
        return too_few("after dropping pairs above calib.stereo.max_pair_error_px");
      }
      fit = FitRig(left, right, used, board, &result, options.fix_intrinsics);
      for (size_t j = 0; j < used.size(); ++j) {
        result.pairs[used[j]].left_rms_px = fit.view_errors.at<double>(static_cast<int>(j), 0);
        result.pairs[used[j]].right_rms_px = fit.view_errors.at<double>(static_cast<int>(j), 1);
      }
    }
    StoreRig(fit, left[0].image_size, options.rectify_alpha, &result);
  } catch (const cv::Exception& e) {
    return InvalidArgument("stereo calibration failed: " + std::string(e.what()));
  }
  Status valid = result.rig.Validate();
  if (!valid.ok())
    return InvalidArgument("stereo calibration gave an invalid rig: " + valid.message());
  return result;
}

}  // namespace sightline
