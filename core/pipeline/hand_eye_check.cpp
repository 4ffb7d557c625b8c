#include "core/pipeline/hand_eye_check.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <vector>

#include "core/io/hand_eye_file.h"

namespace sightline {

namespace {

double AngleRad(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  return std::atan2(a.cross(b).norm(), a.dot(b));
}

double RotationRad(const Eigen::Matrix3d& r) { return Eigen::AngleAxisd(r).angle(); }

constexpr double kDeg = 180.0 / M_PI;

}  // namespace

std::string HandEyeCheck::Describe() const {
  char text[320];
  if (pairs == 0) {
    std::snprintf(text, sizeof(text), "hand-eye check: no keyframe pair to compare");
  } else if (translation_observable) {
    std::snprintf(text, sizeof(text),
                  "hand-eye check on %d keyframe pairs: displacement directions off by %.2f deg, "
                  "arm rotated up to %.1f deg, mount translation residual %.1f mm",
                  pairs, direction_deg, arm_rotation_deg, translation_m * 1e3);
  } else {
    std::snprintf(text, sizeof(text),
                  "hand-eye check on %d keyframe pairs: displacement directions off by %.2f deg; "
                  "the arm rotated at most %.1f deg, so a wrong mount translation cannot be seen "
                  "(it moves every target by itself): the stated hand-eye translation sigma is "
                  "taken from hand_eye.yaml's residuals or button.uncertainty.hand_eye_sigma_m",
                  pairs, direction_deg, arm_rotation_deg);
  }
  return text;
}

HandEyeCheck CheckHandEye(const MapSnapshot& map, const Trajectory& base_from_camera,
                          double tolerance_s, double lambda, const ScaleEstimatorOptions& noise,
                          double min_rotation_deg, double min_baseline_m) {
  struct Dual {
    Eigen::Isometry3d map, metric;
  };
  std::vector<Dual> keyframes;
  for (const MapSnapshot::Frame& k : map.keyframes) {
    if (std::optional<size_t> i = base_from_camera.Nearest(k.time_s, tolerance_s)) {
      keyframes.push_back({k.map_from_camera, base_from_camera.poses()[*i].world_from_sensor});
    }
  }
  HandEyeCheck out;
  double sum_w = 0, sum_excess = 0, sum_raw = 0, sum_t2 = 0;
  int rotated = 0;
  const double min_length = std::max({noise.min_metric_length_m, min_baseline_m, 1e-9});
  for (size_t a = 0; a < keyframes.size(); ++a) {
    for (size_t b = a + 1; b < keyframes.size(); ++b) {
      const Dual &ka = keyframes[a], &kb = keyframes[b];
      const Eigen::Vector3d x =
          ka.map.linear().transpose() * (kb.map.translation() - ka.map.translation());
      const Eigen::Vector3d y =
          ka.metric.linear().transpose() * (kb.metric.translation() - ka.metric.translation());
      const double ny = y.norm(), nx = x.norm();
      if (ny < min_length || !(nx > 0)) continue;
      const double phi = AngleRad(x, y);
      const double sigma2 =
          std::pow(noise.sigma_map / nx, 2) + std::pow(noise.sigma_metric_m / ny, 2);
      sum_w += ny * ny;
      sum_excess += ny * ny * (phi * phi - sigma2);
      sum_raw += ny * ny * phi * phi;
      ++out.pairs;
      const double theta = RotationRad(ka.metric.linear().transpose() * kb.metric.linear());
      out.arm_rotation_deg = std::max(out.arm_rotation_deg, theta * kDeg);
      if (lambda > 0 && theta * kDeg >= min_rotation_deg) {
        sum_t2 += std::pow((x / lambda - y).norm() / (2 * std::sin(theta / 2)), 2);
        ++rotated;
      }
    }
  }
  if (sum_w > 0) {
    out.direction_deg = std::sqrt(std::max(0.0, sum_excess / sum_w)) * kDeg;
    out.direction_rms_deg = std::sqrt(sum_raw / sum_w) * kDeg;
  }
  out.translation_observable = rotated > 0;
  if (rotated > 0) out.translation_m = std::sqrt(sum_t2 / rotated);
  return out;
}

std::string HandEyePathFor(const std::string& dataset_path, const MonoSlamRunOptions& run) {
  if (!run.hand_eye.empty()) return run.hand_eye;
  const std::string arm =
      run.arm_poses.empty() ? FindBeside(dataset_path, "arm_poses.txt") : run.arm_poses;
  if (arm.empty()) return "";
  const std::filesystem::path beside = std::filesystem::path(arm).parent_path() / "hand_eye.yaml";
  return std::filesystem::exists(beside) ? beside.string() : "";
}

StatusOr<std::string> StateHandEyeSigmas(const std::string& hand_eye_path, double* sigma_m,
                                         double* sigma_deg) {
  char text[400];
  if (hand_eye_path.empty() || hand_eye_path == "none") {
    std::snprintf(text, sizeof(text),
                  "hand-eye: no hand_eye.yaml; stated mount sigma %.1f mm, %.2f deg "
                  "(button.uncertainty.hand_eye_sigma_m, hand_eye_sigma_deg)",
                  *sigma_m * 1e3, *sigma_deg);
    return std::string(text);
  }
  StatusOr<HandEye> read = ReadHandEyeFile(hand_eye_path);
  if (!read.ok()) return read.status();
  if (!read->fit) {
    std::snprintf(text, sizeof(text),
                  "hand-eye: %s states no calibration residuals; stated mount sigma %.1f mm, "
                  "%.2f deg from button.uncertainty.hand_eye_sigma_m, hand_eye_sigma_deg",
                  hand_eye_path.c_str(), *sigma_m * 1e3, *sigma_deg);
    return std::string(text);
  }
  *sigma_m = std::max(*sigma_m, read->fit->board_translation_rms_m);
  *sigma_deg = std::max(*sigma_deg, read->fit->board_rotation_rms_deg);
  std::snprintf(text, sizeof(text),
                "hand-eye: %s states residuals %.1f mm, %.2f deg (%s, %d pairs, arm rotated up to "
                "%.1f deg); stated mount sigma %.1f mm, %.2f deg",
                hand_eye_path.c_str(), read->fit->board_translation_rms_m * 1e3,
                read->fit->board_rotation_rms_deg, read->fit->method.c_str(), read->fit->pairs,
                read->fit->max_rotation_deg, *sigma_m * 1e3, *sigma_deg);
  return std::string(text);
}

}  // namespace sightline
