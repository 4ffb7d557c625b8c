#include "core/mapping/floor_plane.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <unordered_map>

#include "core/mapping/option_check.h"
#include "core/mapping/pose2d.h"

namespace sightline {

using mapping_internal::Invalid;

bool FloorPlaneOptions::IsValid(std::string* error) const {
  if (!(epsilon_m > 0)) return Invalid(error, "mapping.floor.epsilon_m must be positive");
  if (!(fit_threshold_m > 0))
    return Invalid(error, "mapping.floor.fit_threshold_m must be positive");
  if (max_iterations < 1) return Invalid(error, "mapping.floor.max_iterations must be >= 1");
  if (!(min_inlier_ratio > 0 && min_inlier_ratio <= 1)) {
    return Invalid(error, "mapping.floor.min_inlier_ratio must lie in (0, 1]");
  }
  if (!(max_tilt_deg > 0 && max_tilt_deg < 90)) {
    return Invalid(error, "mapping.floor.max_tilt_deg must lie in (0, 90)");
  }
  if (!(min_camera_height_m >= 0 && max_camera_height_m > min_camera_height_m)) {
    return Invalid(error,
                   "mapping.floor.min_camera_height_m must be >= 0 and below "
                   "mapping.floor.max_camera_height_m");
  }
  if (!(max_below_ratio >= 0 && max_below_ratio <= 1)) {
    return Invalid(error, "mapping.floor.max_below_ratio must lie in [0, 1]");
  }
  if (!(max_depth_m > 0)) return Invalid(error, "mapping.floor.max_depth_m must be positive");
  if (max_points < 100) return Invalid(error, "mapping.floor.max_points must be >= 100");
  if (!(local_sample_size_m > 0)) {
    return Invalid(error, "mapping.floor.local_sample_size_m must be positive");
  }
  return true;
}

OptionTable<FloorPlaneOptions> FloorPlaneOptions::Describe() {
  using O = FloorPlaneOptions;
  return OptionTable<O>("mapping.floor")
      .Double("epsilon_m", &O::epsilon_m, "m", 0.001, 0.5, 0.005,
              "epsilon_floor: a point within this height of the floor plane is floor (published "
              "value 3.5, "
              "read as 3.5 cm: generous so that no floor pixel is labelled occupied).")
      .Double("fit_threshold_m", &O::fit_threshold_m, "m", 0.001, 0.5, 0.005,
              "Point-to-plane distance of an inlier while fitting the floor.")
      .Int("max_iterations", &O::max_iterations, "", 1, 100000, 50,
           "RANSAC plane hypotheses (half of them sampled within one voxel).")
      .Double("local_sample_size_m", &O::local_sample_size_m, "m", 0.02, 10, 0.05,
              "Voxel size for locally sampled hypotheses (finds a floor that covers little of "
              "the view).")
      .Double("min_inlier_ratio", &O::min_inlier_ratio, "", 0.01, 1, 0.01,
              "The floor must hold at least this fraction of the valid points.")
      .Double("max_tilt_deg", &O::max_tilt_deg, "deg", 1, 89, 1,
              "Largest angle between the floor normal and the camera's up axis (-y).")
      .Double("min_camera_height_m", &O::min_camera_height_m, "m", 0, 10, 0.05,
              "Lowest plausible camera height above the floor.")
      .Double("max_camera_height_m", &O::max_camera_height_m, "m", 0.01, 20, 0.05,
              "Highest plausible camera height above the floor.")
      .Double("max_below_ratio", &O::max_below_ratio, "", 0, 1, 0.01,
              "The floor is the lowest plane: at most this fraction of points may lie clearly "
              "below it (rejects table tops).")
      .Double("max_depth_m", &O::max_depth_m, "m", 0.1, 100, 0.5,
              "Points farther than this are not used for the fit.")
      .Int("max_points", &O::max_points, "", 100, 10000000, 1000,
           "Points are subsampled evenly to at most this many.")
      .Int("seed", &O::seed, "", 0, 2147483647, 1, "Random seed of the plane RANSAC.");
}

namespace {

// Least-squares plane through points: unit normal oriented so that d > 0.
bool FitPlaneLeastSquares(const std::vector<Eigen::Vector3f>& points,
                          const std::vector<int>& indices, Eigen::Vector3d* normal, double* d) {
  if (indices.size() < 3) return false;
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (int i : indices) mean += points[i].cast<double>();
  mean /= static_cast<double>(indices.size());
  Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
  for (int i : indices) {
    const Eigen::Vector3d q = points[i].cast<double>() - mean;
    cov += q * q.transpose();
  }
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(cov);
  if (solver.info() != Eigen::Success) return false;
  Eigen::Vector3d n = solver.eigenvectors().col(0).normalized();
  double offset = -n.dot(mean);
  if (offset < 0) {
    n = -n;
    offset = -offset;
  }
  *normal = n;
  *d = offset;
  return true;
}

struct PlaneScore {
  int inliers = 0;
  int below = 0;
  double cost = 0;  // MSAC: sum of min(h^2, threshold^2).
};

PlaneScore ScorePlane(const std::vector<Eigen::Vector3f>& points, const Eigen::Vector3f& n, float d,
                      float threshold, std::vector<int>* inliers) {
  PlaneScore score;
  if (inliers != nullptr) inliers->clear();
  const float below_limit = -3.0f * threshold;
  const float t2 = threshold * threshold;
  double cost = 0;
  for (size_t i = 0; i < points.size(); ++i) {
    const float h = n.dot(points[i]) + d;
    cost += std::min(h * h, t2);
    if (std::abs(h) < threshold) {
      ++score.inliers;
      if (inliers != nullptr) inliers->push_back(static_cast<int>(i));
    } else if (h < below_limit) {
      ++score.below;
    }
  }
  score.cost = cost;
  return score;
}

}  // namespace

void AppendDepthPoints(const cv::Mat& depth_m, const PinholeCamera& camera, double max_depth_m,
                       int step, std::vector<Eigen::Vector3f>* points) {
  if (depth_m.empty() || depth_m.type() != CV_32FC1 || camera.fx <= 0 || camera.fy <= 0) return;
  step = std::max(1, step);
  // Intrinsics may be given at another resolution than the depth image.
  const PinholeCamera cam = (camera.width == depth_m.cols && camera.height == depth_m.rows) ||
                                    camera.width <= 0 || camera.height <= 0
                                ? camera
                                : camera.Scaled(depth_m.cols, depth_m.rows);
  const double fx = cam.fx, fy = cam.fy, cx = cam.cx, cy = cam.cy;
  for (int v = 0; v < depth_m.rows; v += step) {
    const float* row = depth_m.ptr<float>(v);
    for (int u = 0; u < depth_m.cols; u += step) {
      const float z = row[u];
      if (!(z > 0) || z > max_depth_m) continue;
      points->emplace_back(static_cast<float>((u - cx) / fx * z),
                           static_cast<float>((v - cy) / fy * z), z);
    }
  }
}

StatusOr<FloorFitResult> FloorPlaneEstimator::Fit(
    const std::vector<Eigen::Vector3f>& points_in_camera) const {
  std::string error;
  if (!options_.IsValid(&error)) return InvalidArgument(error);

  // Valid points, subsampled evenly.
  size_t valid = 0;
  for (const auto& p : points_in_camera) {
    if (p.allFinite() && p.z() > 0 && p.z() <= options_.max_depth_m) ++valid;
  }
  if (valid < 100) {
    return FailedPrecondition("floor fit: only " + std::to_string(valid) +
                              " valid depth points (need >= 100): is the depth empty or all "
                              "invalid?");
  }
  const size_t stride = (valid + options_.max_points - 1) / options_.max_points;
  std::vector<Eigen::Vector3f> points;
  points.reserve(valid / stride + 1);
  size_t k = 0;
  for (const auto& p : points_in_camera) {
    if (!(p.allFinite() && p.z() > 0 && p.z() <= options_.max_depth_m)) continue;
    if (k++ % stride == 0) points.push_back(p);
  }
  const int n_points = static_cast<int>(points.size());
  const float threshold = static_cast<float>(options_.fit_threshold_m);
  const double cos_tilt = std::cos(DegToRad(options_.max_tilt_deg));
  const Eigen::Vector3d up(0, -1, 0);

  std::mt19937 rng(static_cast<uint32_t>(options_.seed));
  std::uniform_int_distribution<int> pick(0, n_points - 1);
  int best_inliers = -1;
  double best_cost = 0;
  Eigen::Vector3d best_n = up;
  double best_d = 0;
  int rejected_orientation = 0, rejected_below = 0;
  // Local sampling (as in NAPSAC): every other hypothesis takes its three points from one voxel,
  // so that a floor covering only a few percent of the view is still sampled often; the others
  // sample the whole cloud (long baselines, accurate normals).
  const double voxel = options_.local_sample_size_m;
  std::unordered_map<int64_t, std::vector<int>> voxels;
  auto key_of = [voxel](const Eigen::Vector3f& p) {
    const int64_t x = static_cast<int64_t>(std::floor(p.x() / voxel)) & 0x1FFFFF;
    const int64_t y = static_cast<int64_t>(std::floor(p.y() / voxel)) & 0x1FFFFF;
    const int64_t z = static_cast<int64_t>(std::floor(p.z() / voxel)) & 0x1FFFFF;
    return (x << 42) | (y << 21) | z;
  };
  for (int i = 0; i < n_points; ++i) voxels[key_of(points[i])].push_back(i);
  for (int it = 0; it < options_.max_iterations; ++it) {
    int i0 = pick(rng), i1 = pick(rng), i2 = pick(rng);
    if (it % 2 == 1) {
      const std::vector<int>& cell = voxels[key_of(points[i0])];
      if (cell.size() < 3) continue;
      std::uniform_int_distribution<size_t> in_cell(0, cell.size() - 1);
      i1 = cell[in_cell(rng)];
      i2 = cell[in_cell(rng)];
    }
    if (i0 == i1 || i1 == i2 || i0 == i2) continue;
    const Eigen::Vector3d p0 = points[i0].cast<double>();
    Eigen::Vector3d n = (points[i1].cast<double>() - p0).cross(points[i2].cast<double>() - p0);
    if (n.norm() < 1e-9) continue;
    n.normalize();
    double d = -n.dot(p0);
    if (d < 0) {
      n = -n;
      d = -d;
    }
    if (n.dot(up) < cos_tilt || d < options_.min_camera_height_m ||
        d > options_.max_camera_height_m) {
      ++rejected_orientation;
      continue;
    }
    const PlaneScore score =
        ScorePlane(points, n.cast<float>(), static_cast<float>(d), threshold, nullptr);
    if (score.below > options_.max_below_ratio * n_points) {
      ++rejected_below;
      continue;
    }
    // MSAC: the lowest truncated quadratic cost, so that a plane tilted to catch the foot of a
    // wall does not beat the true floor on inlier count alone.
    if (best_inliers < 0 || score.cost < best_cost) {
      best_cost = score.cost;
      best_inliers = score.inliers;
      best_n = n;
      best_d = d;
    }
  }
  if (best_inliers < 3) {
    return FailedPrecondition("floor fit: no plane below the camera within " +
                              std::to_string(options_.max_tilt_deg) + " deg of level (" +
                              std::to_string(rejected_orientation) +
                              " hypotheses had the wrong "
                              "orientation or height, " +
                              std::to_string(rejected_below) +
                              " had points below them): "
                              "is the floor visible?");
  }

  // Least-squares refinement on the inliers: twice at the RANSAC threshold, then once with half
  // of it, so that the foot of a wall (points just above the floor) does not tilt the plane.
  std::vector<int> inliers;
  PlaneScore score =
      ScorePlane(points, best_n.cast<float>(), static_cast<float>(best_d), threshold, &inliers);
  for (int round = 0; round < 3; ++round) {
    const float round_threshold = round < 2 ? threshold : 0.5f * threshold;
    std::vector<int> fit_set;
    if (round < 2) {
      fit_set = inliers;
    } else {
      ScorePlane(points, best_n.cast<float>(), static_cast<float>(best_d), round_threshold,
                 &fit_set);
    }
    Eigen::Vector3d n;
    double d = 0;
    if (!FitPlaneLeastSquares(points, fit_set, &n, &d)) break;
    std::vector<int> refit_inliers;
    const PlaneScore refit =
        ScorePlane(points, n.cast<float>(), static_cast<float>(d), threshold, &refit_inliers);
    if (round < 2 && refit.cost > score.cost) break;
    best_n = n;
    best_d = d;
    score = refit;
    inliers.swap(refit_inliers);
  }

  FloorFitResult result;
  result.points = n_points;
  result.inliers = score.inliers;
  result.inlier_ratio = static_cast<double>(score.inliers) / n_points;
  result.below_ratio = static_cast<double>(score.below) / n_points;
  double sum_sq = 0;
  for (int i : inliers) {
    const double h = best_n.dot(points[i].cast<double>()) + best_d;
    sum_sq += h * h;
  }
  result.rms_m = inliers.empty() ? 0 : std::sqrt(sum_sq / inliers.size());
  result.plane.normal = best_n;
  result.plane.d = best_d;
  result.plane.epsilon_m = options_.epsilon_m;
  if (result.inlier_ratio < options_.min_inlier_ratio) {
    char message[200];
    std::snprintf(message, sizeof(message),
                  "floor fit: the best floor candidate holds %.1f %% of the points (need %.1f %%): "
                  "too little floor visible",
                  100 * result.inlier_ratio, 100 * options_.min_inlier_ratio);
    return FailedPrecondition(message);
  }
  return result;
}

void FloorCalibrator::AddDepth(const cv::Mat& depth_m, const PinholeCamera& camera) {
  AppendDepthPoints(depth_m, camera, estimator_.options().max_depth_m, 2, &points_);
  ++frames_;
}

void FloorCalibrator::AddCloud(const std::vector<Eigen::Vector3f>& points) {
  points_.insert(points_.end(), points.begin(), points.end());
  ++frames_;
}

StatusOr<FloorFitResult> FloorCalibrator::Fit() const { return estimator_.Fit(points_); }

StatusOr<FloorCalibration> FloorCalibrator::Calibrate(const std::string& source) const {
  StatusOr<FloorFitResult> fit = Fit();
  if (!fit.ok()) return fit.status();
  FloorCalibration calibration;
  calibration.plane = fit->plane;
  calibration.inlier_ratio = fit->inlier_ratio;
  calibration.frames = frames_;
  calibration.source = source;
  return calibration;
}

void FloorCalibrator::Clear() {
  points_.clear();
  frames_ = 0;
}

}  // namespace sightline
