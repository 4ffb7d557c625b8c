#include "core/pipeline/metric_slam_view.h"

#include <cmath>

#include "core/pipeline/mono_inputs.h"

namespace sightline {

bool MetricViewOptions::IsValid(std::string* error) const {
  if (min_pairs < 1) {
    if (error) *error = "button.scale.min_pairs must be >= 1";
    return false;
  }
  if (!(max_sigma_rel > 0)) {
    if (error) *error = "button.scale.max_sigma_rel must be > 0";
    return false;
  }
  return true;
}

OptionTable<MetricViewOptions> MetricViewOptions::Describe() {
  using O = MetricViewOptions;
  return OptionTable<O>("button.scale")
      .Int("min_pairs", &O::min_pairs, "pairs", 1, 1000, 1,
           "The metric scale counts as converged with this many displacement pairs in the ML "
           "estimate at least ...")
      .Double("max_sigma_rel", &O::max_sigma_rel, "", 1e-6, 1, 0.005,
              "... and a relative 1-sigma scale error at most this.");
}

MetricSlamView::MetricSlamView(Trajectory base_from_camera, ScaleEstimatorOptions scale,
                               MetricViewOptions options, double tolerance_s)
    : base_from_camera_(std::move(base_from_camera)),
      scale_options_(scale),
      options_(options),
      tolerance_s_(tolerance_s) {}

bool MetricSlamView::converged() const {
  return lambda_ml_ > 0 && pairs_used_ >= options_.min_pairs &&
         sigma_rel_ <= options_.max_sigma_rel;
}

void MetricSlamView::AddMeasuredPose(double time_s, const Eigen::Isometry3d& base_from_camera) {
  const std::vector<TimedPose>& poses = base_from_camera_.poses();
  if (!poses.empty() && !(time_s > poses.back().time_s)) return;  // Nearest needs sorted times.
  base_from_camera_.Add(time_s, base_from_camera);
}

std::optional<Eigen::Isometry3d> MetricSlamView::BaseFromCamera(double time_s) const {
  std::optional<size_t> i = base_from_camera_.Nearest(time_s, tolerance_s_);
  if (!i) return std::nullopt;
  return base_from_camera_.poses()[*i].world_from_sensor;
}

void MetricSlamView::Rescale(const MapSnapshot& map) {
  ScaleEstimator scale(scale_options_);
  for (const ScalePair& pair : KeyFrameScalePairs(map, base_from_camera_, tolerance_s_))
    scale.Add(pair);
  lambda_ml_ = scale.max_likelihood();
  lambda_single_ = scale.single_ratio();
  pairs_used_ = scale.pairs_used();
  history_ = scale.history();
  sigma_rel_ = 0;
  if (lambda_ml_ > 0) {
    double sum_yy = 0;
    for (const ScalePair& p : scale.pairs()) sum_yy += p.metric_displacement.squaredNorm();
    const double sx = scale_options_.sigma_map / lambda_ml_;
    const double sy = scale_options_.sigma_metric_m;
    if (sum_yy > 0) sigma_rel_ = std::sqrt(sx * sx + sy * sy) / std::sqrt(sum_yy);
  }
}

namespace {

// Map points divided by `lambda` (map units per metre): the metric map.
std::shared_ptr<const std::vector<Eigen::Vector3d>> MetricPoints(const MapSnapshot& map,
                                                                 double lambda) {
  auto points = std::make_shared<std::vector<Eigen::Vector3d>>();
  points->reserve(map.points.size());
  for (const MapSnapshot::Point& p : map.points) points->push_back(p.position / lambda);
  return points;
}

// The camera's metric pose, as the button picker takes it.
Eigen::Isometry3d MetricCameraFromWorld(const Eigen::Isometry3d& map_from_camera, double lambda) {
  Eigen::Isometry3d world_from_camera = map_from_camera;
  world_from_camera.translation() /= lambda;
  return world_from_camera.inverse();
}

}  // namespace

SlamView MetricSlamView::MakeView(const PinholeCamera& camera, bool tracked,
                                  const Eigen::Isometry3d& map_from_camera, const MapSnapshot& map,
                                  double lambda) {
  SlamView view;
  view.camera = camera;
  view.tracking = tracked && lambda > 0;
  if (lambda <= 0) return view;
  view.camera_from_world = MetricCameraFromWorld(map_from_camera, lambda);
  view.map_points_in_world = MetricPoints(map, lambda);
  return view;
}

SlamView MetricSlamView::Update(const MonoSlamResult& result, const PinholeCamera& camera) {
  if (result.map && result.map != map_) {
    map_ = result.map;
    Rescale(*map_);
    points_ = lambda_ml_ > 0 ? MetricPoints(*map_, lambda_ml_) : nullptr;
  }
  SlamView view;
  view.camera = camera;
  view.tracking = result.tracked && lambda_ml_ > 0;
  view.scale_converged = converged();
  view.scale_sigma_rel = sigma_rel_;
  if (lambda_ml_ <= 0) return view;
  view.camera_from_world = MetricCameraFromWorld(result.map_from_camera, lambda_ml_);
  view.map_points_in_world = points_;
  return view;
}

}  // namespace sightline
