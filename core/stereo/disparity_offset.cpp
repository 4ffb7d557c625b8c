#include "core/stereo/disparity_offset.h"

#include <Eigen/Cholesky>
#include <Eigen/LU>
#include <algorithm>
#include <cmath>

#include "core/stereo/motion_estimator.h"
#include "core/stereo/option_check.h"
#include "core/stereo/reprojection.h"

namespace sightline {

using stereo_internal::Invalid;
using stereo_internal::Skew;
using stereo_internal::StereoHuberWeights;
using stereo_internal::StereoResidual;

bool DisparityOffsetOptions::IsValid(std::string* error) const {
  if (!(prior_sigma_px > 0))
    return Invalid(error, "stereo.disparity_offset.prior_sigma_px must be > 0");
  if (!(max_offset_px >= 0))
    return Invalid(error, "stereo.disparity_offset.max_offset_px must be >= 0");
  if (!(huber_px > 0)) return Invalid(error, "stereo.disparity_offset.huber_px must be > 0");
  if (!(min_noise_px > 0))
    return Invalid(error, "stereo.disparity_offset.min_noise_px must be > 0");
  if (!(min_parallax >= 0))
    return Invalid(error, "stereo.disparity_offset.min_parallax must be >= 0");
  if (max_span_frames < 1) {
    return Invalid(error, "stereo.disparity_offset.max_span_frames must be >= 1");
  }
  if (!(min_applied_px >= 0))
    return Invalid(error, "stereo.disparity_offset.min_applied_px must be >= 0");
  return true;
}

OptionTable<DisparityOffsetOptions> DisparityOffsetOptions::Describe() {
  using O = DisparityOffsetOptions;
  return OptionTable<O>("stereo.disparity_offset")
      .Bool("enabled", &O::enabled,
            "Estimate a constant disparity offset of the rig (rectification or matcher bias) "
            "online from the motion, and add it to every disparity; an offset of a fraction of a "
            "pixel moves far points most and makes the translation too long or too short.")
      .Double("prior_sigma_px", &O::prior_sigma_px, "px", 1e-3, 10, 0.01,
              "Prior standard deviation of the offset around zero; smaller trusts the "
              "calibration longer.")
      .Double("max_offset_px", &O::max_offset_px, "px", 0, 10, 0.1,
              "The estimated offset is clamped to +- this.")
      .Double("huber_px", &O::huber_px, "px", 0.01, 100, 0.1,
              "Huber threshold of the robust weights of the offset measurement.")
      .Double("min_noise_px", &O::min_noise_px, "px", 1e-3, 10, 0.01,
              "Floor of the residual RMS by which each frame pair's measurement is weighted.")
      .Double("min_parallax", &O::min_parallax, "", 0, 10, 0.01,
              "The offset is measured between an anchor frame and the first later frame whose "
              "translation from it reaches this fraction of the common tracks' median depth: "
              "with less parallax, tracking errors dominate the measurement.")
      .Int("max_span_frames", &O::max_span_frames, "frames", 1, 1000, 1,
           "... reached within this many frames; otherwise the anchor starts again (tracks "
           "followed over many frames drift, and their drift reads as an offset).")
      .Double("min_applied_px", &O::min_applied_px, "px", 0, 10, 0.01,
              "Smaller estimates are not applied: within the spread the estimate shows on a rig "
              "without offset (the simulator: +-0.03 px).");
}

namespace {

using Vector7d = Eigen::Matrix<double, 7, 1>;
using Matrix7d = Eigen::Matrix<double, 7, 7>;

}  // namespace

DisparityOffsetMeasurement MeasureDisparityOffset(
    const RectifiedStereoCamera& camera, const std::vector<StereoCorrespondence>& correspondences,
    const std::vector<int>& inliers, const Eigen::Isometry3d& current_from_previous,
    const DisparityOffsetOptions& options) {
  DisparityOffsetMeasurement m;
  const Eigen::Matrix3d rotation = current_from_previous.rotation();
  Matrix7d s = Matrix7d::Zero();
  Vector7d b = Vector7d::Zero();
  double weighted_sq = 0, weight_sum = 0;
  for (int i : inliers) {
    const StereoCorrespondence& c = correspondences[static_cast<size_t>(i)];
    // The point that best explains both observations under the motion (a few Gauss-Newton
    // steps from the previous triangulation).
    Eigen::Vector3d x = c.x_previous;
    Eigen::Vector4d r0, r1, w0, w1;
    Eigen::Matrix<double, 4, 3> a0, d1;
    bool ok = true;
    for (int it = 0; it < 3 && ok; ++it) {
      ok = StereoResidual(camera, x, c.previous, &r0, &a0) &&
           StereoResidual(camera, current_from_previous * x, c.current, &r1, &d1);
      if (!ok) break;
      w0 = StereoHuberWeights(r0, options.huber_px);
      w1 = StereoHuberWeights(r1, options.huber_px);
      const Eigen::Matrix<double, 4, 3> a1 = d1 * rotation;
      const Eigen::Matrix3d h = a0.transpose() * w0.asDiagonal() * a0 +
                                a1.transpose() * w1.asDiagonal() * a1 +
                                1e-9 * Eigen::Matrix3d::Identity();
      const Eigen::Vector3d g =
          a0.transpose() * w0.asDiagonal() * r0 + a1.transpose() * w1.asDiagonal() * r1;
      x -= h.ldlt().solve(g);
    }
    const Eigen::Vector3d y = current_from_previous * x;
    if (!ok || !StereoResidual(camera, x, c.previous, &r0, &a0) ||
        !StereoResidual(camera, y, c.current, &r1, &d1)) {
      continue;
    }
    w0 = StereoHuberWeights(r0, options.huber_px);
    w1 = StereoHuberWeights(r1, options.huber_px);
    const Eigen::Matrix<double, 4, 3> a1 = d1 * rotation;
    // Unknowns theta = (translation, rotation of the motion, offset); the offset adds to the
    // predicted right column in both frames.
    Eigen::Matrix<double, 4, 7> j0 = Eigen::Matrix<double, 4, 7>::Zero();
    Eigen::Matrix<double, 4, 7> j1 = Eigen::Matrix<double, 4, 7>::Zero();
    Eigen::Matrix<double, 3, 6> dy_dpose;
    dy_dpose << Eigen::Matrix3d::Identity(), -Skew(y);
    j1.leftCols<6>() = d1 * dy_dpose;
    j0(2, 6) = 1;
    j1(2, 6) = 1;
    const Matrix7d htt =
        j0.transpose() * w0.asDiagonal() * j0 + j1.transpose() * w1.asDiagonal() * j1;
    const Eigen::Matrix<double, 7, 3> htx =
        j0.transpose() * w0.asDiagonal() * a0 + j1.transpose() * w1.asDiagonal() * a1;
    const Eigen::Matrix3d hxx = a0.transpose() * w0.asDiagonal() * a0 +
                                a1.transpose() * w1.asDiagonal() * a1 +
                                1e-9 * Eigen::Matrix3d::Identity();
    const Vector7d gt =
        j0.transpose() * w0.asDiagonal() * r0 + j1.transpose() * w1.asDiagonal() * r1;
    const Eigen::Vector3d gx =
        a0.transpose() * w0.asDiagonal() * r0 + a1.transpose() * w1.asDiagonal() * r1;
    const Eigen::Matrix3d hxx_inv = hxx.inverse();
    s += htt - htx * hxx_inv * htx.transpose();
    b += gt - htx * hxx_inv * gx;
    weighted_sq +=
        (w0.array() * r0.array().square()).sum() + (w1.array() * r1.array().square()).sum();
    weight_sum += w0.sum() + w1.sum();
    ++m.points;
  }
  if (m.points < 6 || !(weight_sum > 0)) return m;
  // Marginalise the motion.
  const Eigen::Matrix<double, 6, 6> spp = s.topLeftCorner<6, 6>();
  const Eigen::LDLT<Eigen::Matrix<double, 6, 6>> ldlt(spp);
  if (ldlt.info() != Eigen::Success) return m;
  const Eigen::Matrix<double, 6, 1> spo = s.block<6, 1>(0, 6);
  const double information = s(6, 6) - spo.dot(ldlt.solve(spo));
  const double gradient = b(6) - spo.dot(ldlt.solve(b.head<6>()));
  // Weight by the pair's own residual noise (Gauss-Newton assumed 1 px).
  const double noise2 =
      std::max(options.min_noise_px * options.min_noise_px, weighted_sq / weight_sum);
  if (!std::isfinite(information) || !std::isfinite(gradient) || information < 0) return m;
  m.information = information / noise2;
  m.gradient = gradient / noise2;
  m.valid = true;
  return m;
}

void DisparityOffsetEstimator::Reset() {
  offset_px_ = 0;
  anchor_.clear();
  world_from_anchor_ = Eigen::Isometry3d::Identity();
  frames_since_anchor_ = 0;
  information_ = 1.0 / (options_.prior_sigma_px * options_.prior_sigma_px);
}

void DisparityOffsetEstimator::Apply(StereoCorrespondence* c) const {
  const double d = offset_px();
  c->previous.u_right -= d;
  c->current.u_right -= d;
}

void DisparityOffsetEstimator::Update(const DisparityOffsetMeasurement& m) {
  if (!options_.enabled || !m.valid || !(m.information > 1e-9)) return;
  // The pair's own estimate: the offset it was measured with plus its correction. The running
  // estimate is the information-weighted mean of the prior and all pairs.
  const double pair = offset_px() - m.gradient / m.information;
  offset_px_ = (information_ * offset_px_ + m.information * pair) / (information_ + m.information);
  offset_px_ = std::clamp(offset_px_, -options_.max_offset_px, options_.max_offset_px);
  information_ += m.information;
}

void DisparityOffsetEstimator::Observe(const RectifiedStereoCamera& camera,
                                       const MotionRefiner& refiner, double inlier_threshold_px,
                                       std::vector<OffsetTrack> tracks,
                                       const Eigen::Isometry3d& world_from_camera,
                                       bool motion_accepted) {
  if (!options_.enabled) return;
  std::sort(tracks.begin(), tracks.end(),
            [](const OffsetTrack& a, const OffsetTrack& b) { return a.id < b.id; });
  auto make_anchor = [&]() {
    anchor_ = std::move(tracks);
    world_from_anchor_ = world_from_camera;
    frames_since_anchor_ = 0;
  };
  if (anchor_.empty() || !motion_accepted) {
    make_anchor();
    return;
  }
  // Tracks seen at the anchor and now.
  std::vector<StereoCorrespondence> correspondences;
  size_t a = 0;
  for (const OffsetTrack& t : tracks) {
    while (a < anchor_.size() && anchor_[a].id < t.id) ++a;
    if (a == anchor_.size()) break;
    if (anchor_[a].id != t.id) continue;
    StereoCorrespondence c;
    c.previous = anchor_[a].observation;
    c.current = t.observation;
    Apply(&c);
    if (!(c.previous.disparity() > 0) || !(c.current.disparity() > 0)) continue;
    Triangulate(camera, &c);
    correspondences.push_back(c);
  }
  constexpr size_t kMinTracks = 20;  // Fewer common tracks or inliers: start a new anchor.
  if (correspondences.size() < kMinTracks) {
    make_anchor();
    return;
  }
  Eigen::Isometry3d motion = world_from_camera.inverse() * world_from_anchor_;
  std::vector<double> depths;
  depths.reserve(correspondences.size());
  for (const StereoCorrespondence& c : correspondences) depths.push_back(c.x_previous.z());
  std::nth_element(depths.begin(), depths.begin() + depths.size() / 2, depths.end());
  if (!(depths[depths.size() / 2] > 0) ||
      motion.translation().norm() < options_.min_parallax * depths[depths.size() / 2]) {
    // Not enough parallax yet: keep the anchor, unless its tracks have been followed too long.
    if (++frames_since_anchor_ >= options_.max_span_frames) make_anchor();
    return;
  }
  // The accumulated motion is close; refine it on the anchor pair's own inliers.
  std::vector<int> inliers =
      MotionEstimator::Inliers(camera, correspondences, motion, 2 * inlier_threshold_px);
  if (inliers.size() >= kMinTracks) {
    refiner.Refine(camera, correspondences, inliers, &motion);
    inliers = MotionEstimator::Inliers(camera, correspondences, motion, inlier_threshold_px);
    if (inliers.size() >= kMinTracks) {
      Update(MeasureDisparityOffset(camera, correspondences, inliers, motion, options_));
    }
  }
  make_anchor();
}

}  // namespace sightline
