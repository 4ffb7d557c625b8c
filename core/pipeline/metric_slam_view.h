// The monocular SLAM as the button picker sees it: each frame's pose and map converted to metres
// with the metric scale estimated online from the keyframes and the arm's measured camera poses
// (recomputed whenever the map changes), and the camera in the arm's base frame at the frame's
// time. Shared by the headless `button` pipeline and the GUI's operator panel.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/button/button_picker.h"
#include "core/common/trajectory.h"
#include "core/mono/mono_slam.h"
#include "core/mono/scale_estimator.h"
#include "core/options/option_table.h"

namespace sightline {

// When the metric scale counts as converged. Keys "button.scale.*".
struct MetricViewOptions {
  int min_pairs = 4;            // Displacement pairs inside the ML estimate at least.
  double max_sigma_rel = 0.02;  // Relative 1-sigma scale error at most (see MetricSlamView).

  bool IsValid(std::string* error) const;
  static OptionTable<MetricViewOptions> Describe();
};

// Not thread-safe; one per SLAM run.
//
//   MetricSlamView metric(base_from_camera_poses, scale_options, view_options, 0.02);
//   SlamView view = metric.Update(*slam_result, camera);
//   std::optional<Eigen::Isometry3d> base = metric.BaseFromCamera(time_s);
class MetricSlamView {
 public:
  // `base_from_camera`: the measured camera poses in metres (arm_poses.txt times the hand-eye
  // transform, LoadMetricCameraPoses), associated with frames within `tolerance_s`.
  MetricSlamView(Trajectory base_from_camera, ScaleEstimatorOptions scale,
                 MetricViewOptions options, double tolerance_s);

  // The view of one SLAM result (the scale is re-estimated when its map changed).
  SlamView Update(const MonoSlamResult& result, const PinholeCamera& camera);
  // A measured camera pose that arrived live (the arm's pose stream, base_from_camera in metres)
  // for the frame at `time_s`: used by BaseFromCamera and by the scale from the next map change
  // on. Ignored unless `time_s` is after the last pose's.
  void AddMeasuredPose(double time_s, const Eigen::Isometry3d& base_from_camera);
  // The measured camera pose at `time_s`; nullopt when no arm pose lies within the tolerance.
  std::optional<Eigen::Isometry3d> BaseFromCamera(double time_s) const;

  double lambda_ml() const { return lambda_ml_; }          // Map units per metre; 0 = unknown.
  double lambda_single() const { return lambda_single_; }  // First pair's ratio; 0 = unknown.
  int pairs_used() const { return pairs_used_; }
  // 1-sigma relative error of the ML scale: sqrt(sigma_map^2 / lambda^2 + sigma_metric^2) over
  // the root sum of squared measured displacements of the pairs (0 while unknown).
  double sigma_rel() const { return sigma_rel_; }
  bool converged() const;
  const std::vector<ScaleSample>& history() const { return history_; }

  // A view of `map` and `map_from_camera` with the scale `lambda` (map units per metre).
  static SlamView MakeView(const PinholeCamera& camera, bool tracked,
                           const Eigen::Isometry3d& map_from_camera, const MapSnapshot& map,
                           double lambda);

 private:
  void Rescale(const MapSnapshot& map);

  Trajectory base_from_camera_;
  ScaleEstimatorOptions scale_options_;
  MetricViewOptions options_;
  double tolerance_s_;
  std::shared_ptr<const MapSnapshot> map_;  // The map the scale and points belong to.
  std::shared_ptr<const std::vector<Eigen::Vector3d>> points_;  // Metric map points.
  double lambda_ml_ = 0, lambda_single_ = 0, sigma_rel_ = 0;
  int pairs_used_ = 0;
  std::vector<ScaleSample> history_;
};

}  // namespace sightline
