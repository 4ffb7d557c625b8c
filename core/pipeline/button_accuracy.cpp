// The figures of a finished `button` run: targets, scale, time from the tap to the first target,
// and the errors against the simulator's true buttons.
#include <algorithm>
#include <cmath>

#include "core/mono/scale_estimator.h"
#include "core/pipeline/button_pipeline.h"
#include "core/pipeline/mono_inputs.h"

namespace sightline {

namespace {

double Median(std::vector<double> v) {
  if (v.empty()) return std::nan("");
  std::sort(v.begin(), v.end());
  return v.size() % 2 ? v[v.size() / 2] : 0.5 * (v[v.size() / 2 - 1] + v[v.size() / 2]);
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

// The frames that sent targets located again with the scale `lambda` (map units per metre) and
// fused the same way; with `button` the true centre replaces the tracked one. nullopt when no
// plane was sound.
std::optional<Eigen::Vector3d> RelocatedTarget(const ButtonRunLog& log, double lambda,
                                               const PinholeCamera& camera,
                                               const ButtonPickerOptions& picker,
                                               const TrueButton* button = nullptr) {
  std::vector<FusedEstimate> estimates;
  for (const SentTarget& t : log.sent) {
    if (!t.map) continue;
    const SlamView view = MetricSlamView::MakeView(camera, true, t.map_from_camera, *t.map, lambda);
    LocatorInput in;
    in.camera = view.camera;
    in.camera_from_world = view.camera_from_world;
    in.points_in_world = view.map_points_in_world.get();
    in.button_px = {t.track.center.x, t.track.center.y};
    const size_t f = static_cast<size_t>(t.target.source_frames.back());
    if (button) {
      if (f >= button->pixel.size() || !button->visible[f]) continue;
      in.button_px = button->pixel[f];
    }
    in.button_radius_px = t.track.radius_px;
    StatusOr<ButtonLocation> at = ButtonLocator(picker.locate).Locate(in);
    if (!at.ok() || !at->plane_sound) continue;
    FusedEstimate e;  // As the picker keeps it (its own sigma: fit, scale, tracked centre).
    e.lambda = lambda;
    e.in_camera_map = at->button_in_camera * lambda;
    e.base_from_camera = t.base_from_camera;
    const double focal = std::max(1.0, 0.5 * (camera.fx + camera.fy));
    const double tracking = picker.uncertainty.tracking_sigma_px / focal *
                            at->button_in_camera.norm() / std::max(0.2, at->incidence_cos);
    e.sigma_m = std::hypot(at->uncertainty_m, tracking);
    estimates.push_back(e);
  }
  if (estimates.empty()) return std::nullopt;
  return FusePositions(estimates, picker.fuse.window, lambda, picker.fuse.weighted,
                       picker.fuse.weigh_below_m)
      .in_base;
}

// The scale of the sent targets' last map against the recording's true camera poses (map units
// per metre, the same estimator on noise-free metric displacements); 0 when unknown.
double TrueScale(const ButtonRunLog& log, const Trajectory& camera_in_world,
                 const ScaleEstimatorOptions& options, size_t last_pairs = 0) {
  if (log.sent.empty() || !log.sent.back().map) return 0;
  std::vector<ScalePair> pairs = KeyFrameScalePairs(*log.sent.back().map, camera_in_world, 0.02);
  if (last_pairs > 0 && pairs.size() > last_pairs) {
    pairs.erase(pairs.begin(), pairs.end() - static_cast<std::ptrdiff_t>(last_pairs));
  }
  StatusOr<double> lambda =
      MaxLikelihoodScale(pairs, options.sigma_map, options.sigma_metric_m * 1e-3, 0);
  return lambda.ok() ? *lambda : 0;
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
  if (last.arm_in_base.allFinite()) {  // From the arm's poses alone (button.triangulate.*).
    result->accuracy.emplace_back("final_error_mm_arm_triangulated",
                                  1e3 * (last.arm_in_base - truth_in_base).norm());
  }
  if (metric.lambda_single() <= 0) return;
  const std::optional<Eigen::Vector3d> single =
      RelocatedTarget(log, metric.lambda_single(), camera, picker);
  if (!single) {
    notes->push_back("single-ratio relocation found no sound plane");
    return;
  }
  result->accuracy.emplace_back("final_error_mm_single_ratio",
                                1e3 * (*single - truth_in_base).norm());
}

// Where the final error comes from, against the simulator's truth: the scale's error, the
// error with the true scale, and with the true scale and the true button centre.
void AddErrorComponents(const ButtonRunLog& log, const MetricSlamView& metric,
                        const PinholeCamera& camera, const ButtonPickerOptions& picker,
                        const TrueButton& button, const Eigen::Vector3d& truth_in_base,
                        const Trajectory& camera_in_world, const ScaleEstimatorOptions& scale,
                        RunResult* result) {
  const double lambda_true = TrueScale(log, camera_in_world, scale);
  if (lambda_true <= 0) return;
  result->accuracy.emplace_back("scale_true", lambda_true);
  result->accuracy.emplace_back("scale_ml_error_pct", 100 * (metric.lambda_ml() / lambda_true - 1));
  const double lambda_recent = TrueScale(log, camera_in_world, scale, 4);
  if (lambda_recent > 0) {
    result->accuracy.emplace_back("scale_true_last4_pct", 100 * (lambda_recent / lambda_true - 1));
    if (auto p = RelocatedTarget(log, lambda_recent, camera, picker)) {
      result->accuracy.emplace_back("final_error_mm_true_last4_scale",
                                    1e3 * (*p - truth_in_base).norm());
    }
  }
  if (metric.lambda_single() > 0) {
    result->accuracy.emplace_back("scale_single_error_pct",
                                  100 * (metric.lambda_single() / lambda_true - 1));
  }
  if (auto p = RelocatedTarget(log, lambda_true, camera, picker)) {
    result->accuracy.emplace_back("final_error_mm_true_scale", 1e3 * (*p - truth_in_base).norm());
  }
  if (auto p = RelocatedTarget(log, lambda_true, camera, picker, &button)) {
    result->accuracy.emplace_back("final_error_mm_true_scale_true_centre",
                                  1e3 * (*p - truth_in_base).norm());
  }
}

// The approach's angle to the truth and the share of targets whose true errors lie within 3 of
// their stated sigmas (position and approach).
void AddHonestyFigures(const ButtonRunLog& log, const TrueButton& button,
                       const Eigen::Isometry3d& world_from_base, RunResult* result) {
  const Eigen::Vector3d truth_in_base = world_from_base.inverse() * button.center_in_world;
  std::vector<double> angles;
  int position_covered = 0, approach_covered = 0, position_2 = 0, approach_2 = 0;
  for (const SentTarget& t : log.sent) {
    const double angle = ApproachAngleDeg(t.target.approach, button, world_from_base);
    if (std::isfinite(angle)) angles.push_back(angle);
    approach_covered += angle <= 3 * t.target.approach_sigma_deg;
    const double error_m = (t.target.position_m - truth_in_base).norm();
    position_covered += error_m <= 3 * t.target.uncertainty_m;
    position_2 += error_m <= 2 * t.target.uncertainty_m;
    approach_2 += angle <= 2 * t.target.approach_sigma_deg;
  }
  if (log.sent.empty()) return;
  const double n = static_cast<double>(log.sent.size());
  result->accuracy.emplace_back("position_within_3_sigma", position_covered / n);
  result->accuracy.emplace_back("position_within_2_sigma", position_2 / n);
  if (angles.empty()) return;
  result->accuracy.emplace_back("approach_error_deg_median", Median(angles));
  result->accuracy.emplace_back("approach_error_deg_max",
                                *std::max_element(angles.begin(), angles.end()));
  result->accuracy.emplace_back("approach_error_deg_final", angles.back());
  result->accuracy.emplace_back("approach_within_3_sigma", approach_covered / n);
  result->accuracy.emplace_back("approach_within_2_sigma", approach_2 / n);
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
                      const ScaleEstimatorOptions& scale, const std::optional<ButtonTruth>& truth,
                      RunResult* result, std::vector<std::string>* notes) {
  result->accuracy.emplace_back("targets_sent", static_cast<double>(log.sent.size()));
  if (metric.lambda_ml() > 0) result->accuracy.emplace_back("scale_ml", metric.lambda_ml());
  if (metric.lambda_single() > 0) {
    result->accuracy.emplace_back("scale_single", metric.lambda_single());
  }
  for (const std::string& warning : LooserGateWarnings(picker.gate)) notes->push_back(warning);
  const HandEyeCheck& hand_eye = metric.hand_eye_check();
  result->accuracy.emplace_back("hand_eye_direction_deg", hand_eye.direction_deg);
  result->accuracy.emplace_back("hand_eye_direction_rms_deg", hand_eye.direction_rms_deg);
  result->counts.emplace_back("hand_eye_arm_rotation_deg", hand_eye.arm_rotation_deg);
  if (hand_eye.translation_observable) {
    result->accuracy.emplace_back("hand_eye_translation_mm", 1e3 * hand_eye.translation_m);
  }
  notes->push_back(hand_eye.Describe());
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
    if (truth->camera_in_world) {
      AddErrorComponents(log, metric, camera, picker, *button, truth_in_base,
                         *truth->camera_in_world, scale, result);
    }
  }
}

}  // namespace sightline
