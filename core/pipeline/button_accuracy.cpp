// The figures of a finished `button` run: targets, scale, time from the tap to the first target,
// and the errors against the simulator's true buttons.
#include <algorithm>
#include <cmath>

#include "core/pipeline/button_pipeline.h"

namespace sightline {

namespace {

double Median(std::vector<double> v) {
  if (v.empty()) return std::nan("");
  std::sort(v.begin(), v.end());
  return v.size() % 2 ? v[v.size() / 2] : 0.5 * (v[v.size() / 2 - 1] + v[v.size() / 2]);
}

// Per-axis median of the last `window` positions (all when 0), as the picker fuses them.
Eigen::Vector3d FuseMedian(const std::vector<Eigen::Vector3d>& values, int window) {
  const size_t n = window > 0 ? std::min(values.size(), size_t(window)) : values.size();
  Eigen::Vector3d out;
  for (int k = 0; k < 3; ++k) {
    std::vector<double> axis;
    for (size_t i = values.size() - n; i < values.size(); ++i) axis.push_back(values[i][k]);
    out[k] = Median(axis);
  }
  return out;
}

void AddTrackErrors(const ButtonRunLog& log, const TrueButton& button, RunResult* result) {
  std::vector<double> errors;
  for (const ButtonRunRow& row : log.rows) {
    const size_t f = static_cast<size_t>(row.picker.frame_id);
    if (!row.picker.track.found || f >= button.pixel.size() || !button.visible[f]) continue;
    errors.push_back(
        (Eigen::Vector2d(row.picker.track.center.x, row.picker.track.center.y) - button.pixel[f])
            .norm());
  }
  if (errors.empty()) return;
  result->accuracy.emplace_back("track_error_px_median", Median(errors));
  result->accuracy.emplace_back("track_error_px_max",
                                *std::max_element(errors.begin(), errors.end()));
  result->counts.emplace_back("track_error_frames", static_cast<double>(errors.size()));
}

// The frames that sent targets located again with the single-ratio scale and fused the same way;
// nullopt when no plane was sound.
std::optional<Eigen::Vector3d> SingleRatioTarget(const ButtonRunLog& log, double lambda_single,
                                                 const PinholeCamera& camera,
                                                 const ButtonPickerOptions& picker) {
  std::vector<Eigen::Vector3d> positions;
  for (const SentTarget& t : log.sent) {
    if (!t.map) continue;
    const SlamView single =
        MetricSlamView::MakeView(camera, true, t.map_from_camera, *t.map, lambda_single);
    LocatorInput in;
    in.camera = single.camera;
    in.camera_from_world = single.camera_from_world;
    in.points_in_world = single.map_points_in_world.get();
    in.button_px = {t.track.center.x, t.track.center.y};
    in.button_radius_px = t.track.radius_px;
    StatusOr<ButtonLocation> at = ButtonLocator(picker.locate).Locate(in);
    if (at.ok() && at->plane_sound) positions.push_back(t.base_from_camera * at->button_in_camera);
  }
  if (positions.empty()) return std::nullopt;
  return FuseMedian(positions, picker.fuse.window);
}

void AddFinalErrors(const ButtonRunLog& log, const MetricSlamView& metric,
                    const PinholeCamera& camera, const ButtonPickerOptions& picker,
                    const Eigen::Vector3d& truth_in_base, RunResult* result,
                    std::vector<std::string>* notes) {
  const SentTarget& last = log.sent.back();
  result->accuracy.emplace_back("final_error_mm",
                                1e3 * (last.target.position_m - truth_in_base).norm());
  result->accuracy.emplace_back("final_error_mm_unfused",
                                1e3 * (last.unfused_in_base - truth_in_base).norm());
  if (metric.lambda_single() <= 0) return;
  const std::optional<Eigen::Vector3d> single =
      SingleRatioTarget(log, metric.lambda_single(), camera, picker);
  if (!single) {
    notes->push_back("single-ratio relocation found no sound plane");
    return;
  }
  result->accuracy.emplace_back("final_error_mm_single_ratio",
                                1e3 * (*single - truth_in_base).norm());
}

// The approach's angle to the truth and the share of targets whose true errors lie within 3 of
// their stated sigmas (position and approach).
void AddHonestyFigures(const ButtonRunLog& log, const TrueButton& button,
                       const Eigen::Isometry3d& world_from_base, RunResult* result) {
  const Eigen::Vector3d truth_in_base = world_from_base.inverse() * button.center_in_world;
  std::vector<double> angles;
  int position_covered = 0, approach_covered = 0;
  for (const SentTarget& t : log.sent) {
    const double angle = ApproachAngleDeg(t.target.approach, button, world_from_base);
    if (std::isfinite(angle)) angles.push_back(angle);
    approach_covered += angle <= 3 * t.target.approach_sigma_deg;
    position_covered += (t.target.position_m - truth_in_base).norm() <= 3 * t.target.uncertainty_m;
  }
  if (log.sent.empty()) return;
  const double n = static_cast<double>(log.sent.size());
  result->accuracy.emplace_back("position_within_3_sigma", position_covered / n);
  if (angles.empty()) return;
  result->accuracy.emplace_back("approach_error_deg_median", Median(angles));
  result->accuracy.emplace_back("approach_error_deg_max",
                                *std::max_element(angles.begin(), angles.end()));
  result->accuracy.emplace_back("approach_error_deg_final", angles.back());
  result->accuracy.emplace_back("approach_within_3_sigma", approach_covered / n);
}

}  // namespace

const TrueButton* TappedTrueButton(const ButtonRunLog& log, const ButtonTruth& truth,
                                   double* distance_px) {
  const TrueButton* button = nullptr;
  *distance_px = 1e18;
  if (!log.tapped_centre || log.tap_index < 0) return nullptr;
  const size_t f = static_cast<size_t>(log.tap_index);
  const Eigen::Vector2d tapped(log.tapped_centre->x, log.tapped_centre->y);
  for (const TrueButton& b : truth.buttons) {
    if (f >= b.pixel.size() || !b.visible[f]) continue;
    const double d = (b.pixel[f] - tapped).norm();
    if (d < *distance_px) *distance_px = d, button = &b;
  }
  return button;
}

double ApproachAngleDeg(const Eigen::Vector3d& approach_in_base, const TrueButton& button,
                        const Eigen::Isometry3d& world_from_base) {
  if (!approach_in_base.allFinite() || !button.normal_in_world.allFinite()) return std::nan("");
  const Eigen::Vector3d push = -(world_from_base.linear().transpose() * button.normal_in_world);
  const double c = approach_in_base.normalized().dot(push.normalized());
  return std::acos(std::clamp(c, -1.0, 1.0)) * 180.0 / M_PI;
}

void AddButtonFigures(const ButtonRunLog& log, const MetricSlamView& metric,
                      const PinholeCamera& camera, const ButtonPickerOptions& picker,
                      const std::optional<ButtonTruth>& truth, RunResult* result,
                      std::vector<std::string>* notes) {
  result->accuracy.emplace_back("targets_sent", static_cast<double>(log.sent.size()));
  if (metric.lambda_ml() > 0) result->accuracy.emplace_back("scale_ml", metric.lambda_ml());
  if (metric.lambda_single() > 0) {
    result->accuracy.emplace_back("scale_single", metric.lambda_single());
  }
  if (log.first_target_index >= 0) {
    result->counts.emplace_back("tap_to_first_target_frames",
                                static_cast<double>(log.first_target_index - log.tap_index));
    result->counts.emplace_back("tap_to_first_target_ms",
                                1e3 * (log.first_target_stamp_s - log.tap_stamp_s));
    result->counts.emplace_back("tap_to_first_target_processing_ms", log.processing_ms_to_first);
  } else {
    notes->push_back("no target was sent");
  }
  if (!truth || !log.tapped_centre) return;
  double distance_px = 0;
  const TrueButton* button = TappedTrueButton(log, *truth, &distance_px);
  if (button == nullptr) {
    notes->push_back("no true button is visible in the tap frame");
    return;
  }
  result->counts.emplace_back("true_button", button->id);
  result->accuracy.emplace_back("tap_selection_error_px", distance_px);
  AddTrackErrors(log, *button, result);
  if (!truth->world_from_base) {
    notes->push_back("hand_eye.yaml has no world_from_base: no 3D error");
  } else if (!log.sent.empty()) {
    const Eigen::Vector3d truth_in_base =
        truth->world_from_base->inverse() * button->center_in_world;
    AddFinalErrors(log, metric, camera, picker, truth_in_base, result, notes);
    AddHonestyFigures(log, *button, *truth->world_from_base, result);
  }
}

}  // namespace sightline
