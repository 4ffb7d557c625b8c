#include "core/button/arm_plane_normal.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>
#include <opencv2/calib3d.hpp>
#include <opencv2/imgproc.hpp>
#include <opencv2/video/tracking.hpp>
#include <optional>
#include <random>
#include <string>

namespace sightline {

namespace {

constexpr double kBackTrackPx = 0.5;  // A track must come back this near its start.
constexpr int kRefineIterations = 8;  // Gauss-Newton steps on the inliers.
constexpr int kWideIterations = 3;    // The first steps take inliers within ...
constexpr double kWideGate = 4;       // ... this many times arm_inlier_px.
// Fewer of the tracks on the plane: the tracks or the poses are not sound (a zoom the
// tracker follows badly, another surface); the anchor starts again.
constexpr double kMinInlierFraction = 0.8;

Eigen::Matrix3d SkewOf(const Eigen::Vector3d& v) {
  Eigen::Matrix3d s;
  s << 0, -v.z(), v.y(), v.z(), 0, -v.x(), -v.y(), v.x(), 0;
  return s;
}

// The plane m (m . X = 1 in the anchor camera) maps an anchor ray x1 to the current view at
// R x1 + t (m . x1) (homogeneous): the transfer of the plane's homography R + t m^T.
Eigen::Vector3d Transfer(const Eigen::Matrix3d& R, const Eigen::Vector3d& t,
                         const Eigen::Vector3d& m, const Eigen::Vector3d& x1) {
  return R * x1 + t * m.dot(x1);
}

// Pixel residual (2) of one track, in pixels of focal length f; NaN behind the camera.
Eigen::Vector2d Residual(const Eigen::Matrix3d& R, const Eigen::Vector3d& t,
                         const Eigen::Vector3d& m, const Eigen::Vector3d& x1,
                         const Eigen::Vector3d& x2, double f) {
  const Eigen::Vector3d p = Transfer(R, t, m, x1);
  if (!(p.z() > 1e-9) || !(m.dot(x1) > 0)) return Eigen::Vector2d::Constant(std::nan(""));
  return f * (p.head<2>() / p.z() - x2.head<2>());
}

// The plane through the tracks `idx` by linear least squares on x2 x (R x1 + t (m . x1)) = 0.
std::optional<Eigen::Vector3d> LinearPlane(const Eigen::Matrix3d& R, const Eigen::Vector3d& t,
                                           const std::vector<Eigen::Vector3d>& x1,
                                           const std::vector<Eigen::Vector3d>& x2,
                                           const std::vector<int>& idx) {
  Eigen::MatrixXd A(3 * idx.size(), 3);
  Eigen::VectorXd b(3 * idx.size());
  for (size_t k = 0; k < idx.size(); ++k) {
    const Eigen::Vector3d& a = x1[idx[k]];
    const Eigen::Vector3d& c = x2[idx[k]];
    A.block<3, 3>(3 * k, 0) = c.cross(t) * a.transpose();
    b.segment<3>(3 * k) = -c.cross(R * a);
  }
  Eigen::JacobiSVD<Eigen::MatrixXd> svd(A, Eigen::ComputeThinU | Eigen::ComputeThinV);
  const Eigen::VectorXd s = svd.singularValues();
  if (s.size() < 3 || !(s(2) > 1e-9 * std::max(1e-12, s(0)))) return std::nullopt;
  const Eigen::Vector3d m = svd.solve(b);
  if (!m.allFinite() || !(m.norm() > 1e-9)) return std::nullopt;
  return m;
}

}  // namespace

void ArmPlaneNormal::Reset() {
  previous_.release();
  anchor_.clear();
  current_.clear();
  anchored_ = 0;
}

std::vector<Eigen::Vector3d> ArmPlaneNormal::Normalised(const std::vector<cv::Point2f>& px,
                                                        const PinholeCamera& camera) {
  std::vector<Eigen::Vector3d> out;
  out.reserve(px.size());
  if (camera.HasDistortion() && !px.empty()) {
    cv::Mat K =
        (cv::Mat_<double>(3, 3) << camera.fx, 0, camera.cx, 0, camera.fy, camera.cy, 0, 0, 1);
    cv::Mat dist(1, 5, CV_64F);
    for (int i = 0; i < 5; ++i) dist.at<double>(i) = camera.distortion[i];
    std::vector<cv::Point2f> undistorted;
    cv::undistortPoints(px, undistorted, K, dist);
    for (const auto& p : undistorted) out.emplace_back(p.x, p.y, 1.0);
    return out;
  }
  for (const auto& p : px) {
    out.emplace_back((p.x - camera.cx) / camera.fx, (p.y - camera.cy) / camera.fy, 1.0);
  }
  return out;
}

bool ArmPlaneNormal::Anchor(const cv::Mat& grey, const ArmPlaneView& view) {
  Reset();
  cv::Mat mask = cv::Mat::zeros(grey.size(), CV_8U);
  const double radius =
      view.region_radius_px > 0 ? view.region_radius_px : std::hypot(grey.cols, grey.rows);
  cv::circle(mask, cv::Point(cvRound(view.button_px.x()), cvRound(view.button_px.y())),
             std::max(1, static_cast<int>(std::min(radius, 1e5))), cv::Scalar(255), cv::FILLED);
  std::vector<cv::Point2f> corners;
  cv::goodFeaturesToTrack(grey, corners, options_.arm_max_corners, 0.01, 7, mask);
  if (static_cast<int>(corners.size()) < options_.min_points) return false;
  previous_ = grey.clone();
  base_from_anchor_ = view.base_from_camera;
  anchor_ = corners;
  current_ = corners;
  anchored_ = corners.size();
  return true;
}

StatusOr<PanelNormal> ArmPlaneNormal::Add(const ArmPlaneView& view) {
  std::string error;
  if (!options_.IsValid(&error)) return InvalidArgument(error);
  if (view.image.empty()) return InvalidArgument("panel plane from the arm: empty image");
  cv::Mat grey;
  if (view.image.channels() == 3) {
    cv::cvtColor(view.image, grey, cv::COLOR_BGR2GRAY);
  } else if (view.image.channels() == 4) {
    cv::cvtColor(view.image, grey, cv::COLOR_BGRA2GRAY);
  } else {
    grey = view.image;
  }
  if (grey.depth() != CV_8U) grey.convertTo(grey, CV_8U);
  const auto anchor_again = [&](const std::string& why) -> Status {
    const bool ok = Anchor(grey, view);
    return NotFound("panel plane from the arm: " + why +
                    (ok ? "; anchored on " + std::to_string(anchored_) + " corners"
                        : "; too few corners around the button to anchor"));
  };
  if (anchored_ == 0 || previous_.size() != grey.size()) return anchor_again("no anchor");

  // Frame to frame, forward and back.
  std::vector<cv::Point2f> next, back;
  std::vector<uchar> ok_fwd, ok_back;
  std::vector<float> err;
  const cv::TermCriteria stop(cv::TermCriteria::COUNT | cv::TermCriteria::EPS, 30, 0.01);
  cv::calcOpticalFlowPyrLK(previous_, grey, current_, next, ok_fwd, err, cv::Size(21, 21), 3, stop);
  cv::calcOpticalFlowPyrLK(grey, previous_, next, back, ok_back, err, cv::Size(21, 21), 3, stop);
  previous_ = grey.clone();
  size_t kept = 0;
  for (size_t i = 0; i < current_.size(); ++i) {
    const cv::Point2f& p = next[i];
    const bool inside = p.x >= 0 && p.y >= 0 && p.x < grey.cols - 1 && p.y < grey.rows - 1;
    if (!ok_fwd[i] || !ok_back[i] || !inside || cv::norm(back[i] - current_[i]) > kBackTrackPx) {
      continue;
    }
    anchor_[kept] = anchor_[i];
    current_[kept] = p;
    ++kept;
  }
  anchor_.resize(kept);
  current_.resize(kept);
  if (static_cast<int>(kept) < std::max<int>(options_.min_points, anchored_ / 3)) {
    return anchor_again(std::to_string(kept) + " of " + std::to_string(anchored_) +
                        " corners still tracked");
  }

  // The current camera from the anchor's, from the arm.
  const Eigen::Isometry3d cam_from_anchor = view.base_from_camera.inverse() * base_from_anchor_;
  const Eigen::Matrix3d R = cam_from_anchor.linear();
  const Eigen::Vector3d t = cam_from_anchor.translation();
  const std::vector<Eigen::Vector3d> x1 = Normalised(anchor_, view.camera);
  const std::vector<Eigen::Vector3d> x2 = Normalised(current_, view.camera);
  const double f = 0.5 * (view.camera.fx + view.camera.fy);
  const double thr2 = options_.arm_inlier_px * options_.arm_inlier_px;
  const double wide2 = kWideGate * kWideGate * thr2;  // The arm's poses are noisy.
  const int n = static_cast<int>(x1.size());
  if (!(t.norm() > 1e-6)) {
    return NotFound("panel plane from the arm: the arm has not moved since the anchor");
  }

  // MSAC over three-track samples (a track fixes one inverse depth, m . x1: three fix m).
  std::mt19937_64 rng(options_.seed);
  std::uniform_int_distribution<int> pick(0, n - 1);
  Eigen::Vector3d best = Eigen::Vector3d::Zero();
  double best_cost = std::numeric_limits<double>::infinity();
  for (int it = 0; it < options_.ransac_iterations; ++it) {
    const int i = pick(rng), j = pick(rng), k = pick(rng);
    if (i == j || j == k || i == k) continue;
    const std::optional<Eigen::Vector3d> m = LinearPlane(R, t, x1, x2, {i, j, k});
    if (!m) continue;
    double cost = 0;
    for (int k = 0; k < n && cost < best_cost; ++k) {
      const Eigen::Vector2d r = Residual(R, t, *m, x1[k], x2[k], f);
      cost += r.allFinite() ? std::min(wide2, r.squaredNorm()) : wide2;
    }
    if (cost < best_cost) best_cost = cost, best = *m;
  }
  if (!std::isfinite(best_cost)) {
    return NotFound("panel plane from the arm: no plane hypothesis (the arm has not moved)");
  }

  // Gauss-Newton on the inliers' pixel residuals over all that the images determine: the
  // rotation, the direction of the translation and the plane (8 parameters, the homography's);
  // the arm gives the start and the translation's length (the metric unit). Noise in the arm's
  // reported poses so moves the start, not the answer. The inliers again after each step, first
  // with a wider threshold (the arm's noise), then with arm_inlier_px.
  Eigen::Matrix3d Rf = R;
  const double length = t.norm();
  Eigen::Vector3d dir = t / length;
  Eigen::Vector3d m = best;
  std::vector<int> in;
  Eigen::Matrix<double, 8, 8> JtJ = Eigen::Matrix<double, 8, 8>::Zero();
  double sum_r2 = 0;
  for (int iter = 0; iter <= kRefineIterations; ++iter) {
    const double gate2 = iter < kWideIterations ? wide2 : thr2;
    // Two directions across the translation (its length stays the arm's).
    const Eigen::Vector3d b1 = dir.unitOrthogonal(), b2 = dir.cross(b1);
    const Eigen::Vector3d tf = length * dir;
    in.clear();
    JtJ.setZero();
    Eigen::Matrix<double, 8, 1> Jtr = Eigen::Matrix<double, 8, 1>::Zero();
    sum_r2 = 0;
    for (int k = 0; k < n; ++k) {
      const Eigen::Vector2d r = Residual(Rf, tf, m, x1[k], x2[k], f);
      if (!r.allFinite() || r.squaredNorm() > gate2) continue;
      in.push_back(k);
      const Eigen::Vector3d rx = Rf * x1[k];
      const Eigen::Vector3d p = rx + tf * m.dot(x1[k]);
      Eigen::Matrix<double, 2, 3> dproj;  // Pixels per unit of p.
      dproj << f / p.z(), 0, -f * p.x() / (p.z() * p.z()), 0, f / p.z(),
          -f * p.y() / (p.z() * p.z());
      Eigen::Matrix<double, 3, 8> dp;
      dp.block<3, 3>(0, 0) = -SkewOf(rx);  // exp(w) R x1.
      dp.col(3) = length * m.dot(x1[k]) * b1;
      dp.col(4) = length * m.dot(x1[k]) * b2;
      dp.block<3, 3>(0, 5) = tf * x1[k].transpose();
      const Eigen::Matrix<double, 2, 8> J = dproj * dp;
      JtJ += J.transpose() * J;
      Jtr += J.transpose() * r;
      sum_r2 += r.squaredNorm();
    }
    if (static_cast<int>(in.size()) < options_.min_points || iter == kRefineIterations) break;
    const Eigen::Matrix<double, 8, 1> step = JtJ.ldlt().solve(-Jtr);
    if (!step.allFinite()) break;
    const Eigen::Vector3d w = step.head<3>();
    if (w.norm() > 0) Rf = Eigen::AngleAxisd(w.norm(), w.normalized()).toRotationMatrix() * Rf;
    dir = (dir + step(3) * b1 + step(4) * b2).normalized();
    m += step.tail<3>();
  }
  PanelNormal out;
  out.points = n;
  out.inliers = static_cast<int>(in.size());
  if (out.inliers < options_.min_points) {
    return NotFound("panel plane from the arm: " + std::to_string(out.inliers) +
                    " tracks on one plane of " + std::to_string(n));
  }
  // The plane in the current camera: n2 . X = d2.
  const double d1 = 1.0 / m.norm();
  const Eigen::Vector3d n1 = m * d1;  // Away from the anchor camera.
  const Eigen::Vector3d n2 = Rf * n1;
  const double d2 = d1 + n2.dot(length * dir);
  const Eigen::Vector3d ray = Normalised(
      {cv::Point2f(static_cast<float>(view.button_px.x()), static_cast<float>(view.button_px.y()))},
      view.camera)[0];
  const double depth = d2 / n2.dot(ray);  // Along z, at the button.
  if (!(d2 > 0) || !(depth > 0) || !std::isfinite(depth)) {
    return NotFound("panel plane from the arm: the plane is not in front of the camera");
  }
  // The triangulation angle at the button: the anchor camera's centre is at length * dir in
  // this camera. A move straight at the button (the approach) gives none.
  const Eigen::Vector3d button = depth * ray;
  const double c = button.normalized().dot((button - length * dir).normalized());
  const double parallax_deg = std::acos(std::clamp(c, -1.0, 1.0)) * 180.0 / M_PI;
  if (parallax_deg < options_.arm_min_parallax_deg) {
    return NotFound("panel plane from the arm: the arm moved " + std::to_string(length) +
                    " m since the anchor, parallax " + std::to_string(parallax_deg) +
                    " deg at the button");
  }
  if (out.inliers < kMinInlierFraction * n) {
    return anchor_again("only " + std::to_string(out.inliers) + " of " + std::to_string(n) +
                        " tracks fit one plane");
  }
  if (view.button_in_camera.allFinite()) {
    const double offset = std::abs(n2.dot(view.button_in_camera) - d2);
    if (offset > options_.max_button_offset_m) {
      return NotFound("panel plane from the arm: the plane passes " + std::to_string(offset) +
                      " m from the located button");
    }
  }
  // Angular 1-sigma of the unit normal: the covariance of m across its direction, over |m|.
  const double dof = std::max(1, 2 * out.inliers - 3);
  const double sigma2_px = sum_r2 / dof;
  const Eigen::Matrix<double, 8, 8> cov = sigma2_px * JtJ.inverse();
  const Eigen::Matrix3d cov_m = cov.block<3, 3>(5, 5);
  const Eigen::Matrix3d P = Eigen::Matrix3d::Identity() - n1 * n1.transpose();
  const Eigen::Matrix3d cov_n = P * cov_m * P.transpose() / m.squaredNorm();
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(cov_n);
  const double sigma = std::sqrt(std::max(0.0, eig.eigenvalues().maxCoeff()));
  if (!std::isfinite(sigma)) return NotFound("panel plane from the arm: degenerate fit");
  out.normal_in_camera = -n2;  // Toward the camera.
  out.rms_m = std::sqrt(sigma2_px) / f * depth;
  out.sigma_rad = std::max(options_.min_sigma_deg * M_PI / 180.0, sigma);
  return out;
}

}  // namespace sightline
