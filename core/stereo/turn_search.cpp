#include "core/stereo/turn_search.h"

#include <Eigen/Geometry>
#include <cmath>
#include <limits>
#include <opencv2/imgproc.hpp>

namespace sightline {
namespace {

double Radians(double deg) { return deg * M_PI / 180.0; }

// Yaw about `axis` tilted by `tilt_deg` about the camera's x axis, then pitch about x.
Eigen::Matrix3d Rotation(double yaw_deg, double pitch_deg, double tilt_deg,
                         const Eigen::Vector3d& axis) {
  const Eigen::Vector3d tilted =
      Eigen::AngleAxisd(Radians(tilt_deg), Eigen::Vector3d::UnitX()) * axis;
  return (Eigen::AngleAxisd(Radians(yaw_deg), tilted) *
          Eigen::AngleAxisd(Radians(pitch_deg), Eigen::Vector3d::UnitX()))
      .toRotationMatrix();
}

// Turns of at least this much count toward the axis; together they must reach kMinTurnDeg.
constexpr double kMinStepDeg = 2;
constexpr double kMinTurnDeg = 10;

// Compares `current` with `previous` warped by the rotation; the correlation over the pixels
// both see and their fraction.
struct Match {
  double correlation = -1, overlap = 0;
};

class Comparer {
 public:
  Comparer(const cv::Mat& previous, const cv::Mat& current, const Eigen::Matrix3d& k,
           const Eigen::Vector3d& axis)
      : previous_(previous), current_(current), k_(k), k_inv_(k.inverse()), axis_(axis) {}

  Match operator()(double yaw_deg, double pitch_deg, double tilt_deg) {
    const Eigen::Matrix3d h = k_ * Rotation(yaw_deg, pitch_deg, tilt_deg, axis_) * k_inv_;
    cv::Mat hm(3, 3, CV_64F);
    for (int r = 0; r < 3; ++r) {
      for (int c = 0; c < 3; ++c) hm.at<double>(r, c) = h(r, c);
    }
    // Pixels the previous view did not see come out NaN (and so do their neighbours).
    cv::warpPerspective(previous_, warped_, hm, previous_.size(), cv::INTER_LINEAR,
                        cv::BORDER_CONSTANT,
                        cv::Scalar::all(std::numeric_limits<double>::quiet_NaN()));
    double n = 0, sa = 0, sb = 0, saa = 0, sbb = 0, sab = 0;
    for (int v = 0; v < warped_.rows; ++v) {
      const float* a = warped_.ptr<float>(v);
      const float* b = current_.ptr<float>(v);
      for (int u = 0; u < warped_.cols; ++u) {
        if (std::isnan(a[u])) continue;
        n += 1;
        sa += a[u], sb += b[u];
        saa += a[u] * a[u], sbb += b[u] * b[u], sab += a[u] * b[u];
      }
    }
    Match out;
    out.overlap = n / (static_cast<double>(warped_.rows) * warped_.cols);
    if (n < 16) return out;
    const double va = saa - sa * sa / n, vb = sbb - sb * sb / n;
    if (!(va > 0.01 * n && vb > 0.01 * n)) return out;  // Flat (a tenth of a grey level).
    out.correlation = (sab - sa * sb / n) / std::sqrt(va * vb);
    return out;
  }

 private:
  const cv::Mat& previous_;
  const cv::Mat& current_;
  Eigen::Matrix3d k_, k_inv_;
  Eigen::Vector3d axis_;
  cv::Mat warped_;
};

}  // namespace

std::optional<TurnEstimate> FindTurn(const cv::Mat& previous, const cv::Mat& current,
                                     const RectifiedStereoCamera& camera,
                                     const TurnSearchOptions& options,
                                     const Eigen::Vector3d& turn_axis) {
  if (previous.empty() || current.empty() || previous.size() != current.size() ||
      previous.type() != current.type() || previous.channels() != 1 || !(camera.f > 0) ||
      options.width_px < 16 || !(options.coarse_step_deg > 0) || !turn_axis.allFinite() ||
      turn_axis.norm() < 1e-9) {
    return std::nullopt;
  }
  const Eigen::Vector3d axis = turn_axis.normalized();
  const double scale = std::min(1.0, static_cast<double>(options.width_px) / previous.cols);
  const cv::Size size(std::max(16, static_cast<int>(std::lround(previous.cols * scale))),
                      std::max(16, static_cast<int>(std::lround(previous.rows * scale))));
  const double sx = static_cast<double>(size.width) / previous.cols;
  const double sy = static_cast<double>(size.height) / previous.rows;
  cv::Mat a, b;
  cv::resize(previous, a, size, 0, 0, cv::INTER_AREA);
  cv::resize(current, b, size, 0, 0, cv::INTER_AREA);
  a.convertTo(a, CV_32F);
  b.convertTo(b, CV_32F);
  // Smoothed by a reduced pixel: the correlation's peak is then wider than the coarse step.
  cv::GaussianBlur(a, a, cv::Size(0, 0), 1.0);
  cv::GaussianBlur(b, b, cv::Size(0, 0), 1.0);
  // The reduced camera (pixel centres kept).
  Eigen::Matrix3d k = Eigen::Matrix3d::Identity();
  k(0, 0) = camera.f * sx;
  k(1, 1) = camera.f * sy;
  k(0, 2) = (camera.cx + 0.5) * sx - 0.5;
  k(1, 2) = (camera.cy + 0.5) * sy - 0.5;
  Comparer compare(a, b, k, axis);

  TurnEstimate best;
  best.correlation = -1;
  auto consider = [&](double yaw, double pitch, double tilt) {
    const Match m = compare(yaw, pitch, tilt);
    if (m.overlap >= options.min_overlap && m.correlation > best.correlation) {
      best.correlation = m.correlation;
      best.overlap = m.overlap;
      best.yaw_deg = yaw;
      best.pitch_deg = pitch;
      best.axis_tilt_deg = tilt;
    }
  };
  const double step = options.coarse_step_deg;
  for (double yaw = -options.max_yaw_deg; yaw <= options.max_yaw_deg + 1e-9; yaw += step) {
    consider(yaw, 0, 0);
  }
  if (best.correlation < 0) return std::nullopt;
  // Yaw near the best at a quarter of the coarse step; the axis' tilt (a large turn about a
  // wrong axis is found short and rolls the image) at a step; pitch at half a step; yaw again.
  const double fine = step / 4;
  const auto refine_yaw = [&]() {
    const double yaw0 = best.yaw_deg, pitch = best.pitch_deg, tilt = best.axis_tilt_deg;
    for (double yaw = yaw0 - step; yaw <= yaw0 + step + 1e-9; yaw += fine) {
      consider(yaw, pitch, tilt);
    }
  };
  refine_yaw();
  if (options.max_axis_tilt_deg > 0 && std::abs(best.yaw_deg) >= options.min_yaw_for_tilt_deg) {
    const double yaw1 = best.yaw_deg;
    for (double tilt = -options.max_axis_tilt_deg; tilt <= options.max_axis_tilt_deg + 1e-9;
         tilt += step) {
      for (double yaw = yaw1 - 2 * step; yaw <= yaw1 + 2 * step + 1e-9; yaw += step) {
        consider(yaw, 0, tilt);
      }
    }
    refine_yaw();
  }
  const double yaw2 = best.yaw_deg, tilt2 = best.axis_tilt_deg;
  for (double pitch = -options.max_pitch_deg; pitch <= options.max_pitch_deg + 1e-9;
       pitch += 2 * fine) {
    consider(yaw2, pitch, tilt2);
  }
  refine_yaw();
  if (best.correlation < options.min_correlation) return std::nullopt;
  best.current_from_previous = Rotation(best.yaw_deg, best.pitch_deg, best.axis_tilt_deg, axis);
  return best;
}

void TurnAxis::Add(const Eigen::Matrix3d& current_from_previous) {
  const Eigen::AngleAxisd turn(current_from_previous);
  if (!turn.axis().allFinite() || std::abs(turn.angle()) < Radians(kMinStepDeg)) return;
  Eigen::Vector3d v = turn.axis() * turn.angle();
  const Eigen::Vector3d reference = sum_.norm() > 0 ? sum_ : Eigen::Vector3d::UnitY();
  if (v.dot(reference) < 0) v = -v;  // Left and right turns share the axis.
  sum_ += v;
}

Eigen::Vector3d TurnAxis::axis() const {
  if (sum_.norm() < Radians(kMinTurnDeg)) return Eigen::Vector3d::UnitY();
  return sum_.normalized();
}

}  // namespace sightline
