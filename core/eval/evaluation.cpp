#include "core/eval/evaluation.h"

#include <cmath>
#include <cstdio>

#include "core/eval/association.h"

namespace sightline {

bool EvaluationOptions::IsValid(std::string* error) const {
  auto fail = [error](const std::string& message) {
    if (error) *error = message;
    return false;
  };
  if (StatusOr<AlignmentMode> a = ParseAlignmentMode(align); !a.ok()) {
    return fail("eval.align: " + a.status().message());
  }
  if (StatusOr<AssociationMode> a = ParseAssociationMode(associate); !a.ok()) {
    return fail("eval.associate: " + a.status().message());
  }
  if (!(max_time_difference_s >= 0) || !std::isfinite(max_time_difference_s)) {
    return fail("eval.max_time_difference_s must be a finite time >= 0 s");
  }
  if (rpe_delta_frames < 1) return fail("eval.rpe_delta_frames must be >= 1");
  if (!(rpe_delta_m >= 0) || !std::isfinite(rpe_delta_m)) {
    return fail("eval.rpe_delta_m must be >= 0 m (0 uses rpe_delta_frames)");
  }
  if (StatusOr<std::vector<double>> l = ParseSegmentLengths(segment_lengths_m); !l.ok()) {
    return fail("eval.segment_lengths_m: " + l.status().message());
  }
  if (segment_step_frames < 1) return fail("eval.segment_step_frames must be >= 1");
  return true;
}

OptionTable<EvaluationOptions> EvaluationOptions::Describe() {
  return OptionTable<EvaluationOptions>("eval")
      .Choice("align", &EvaluationOptions::align, {"se3", "sim3", "none"},
              "Alignment before measuring: se3 for metric estimates, sim3 for monocular ones "
              "(also fits scale), none when both already share a world frame.")
      .Choice("associate", &EvaluationOptions::associate, {"time", "index"},
              "Pair poses by nearest timestamp, or the i-th with the i-th (equal lengths).")
      .Double("max_time_difference_s", &EvaluationOptions::max_time_difference_s, "s", 0, 1, 0.005,
              "Largest time difference of an associated pair; others are dropped.")
      .Int("rpe_delta_frames", &EvaluationOptions::rpe_delta_frames, "frames", 1, 100000, 1,
           "RPE compares the motion over this many associated poses.")
      .Double("rpe_delta_m", &EvaluationOptions::rpe_delta_m, "m", 0, 10000, 0.5,
              "RPE % and deg/m over pairs this far apart along the ground truth; 0 uses the "
              "rpe_delta_frames pairs.")
      .String("segment_lengths_m", &EvaluationOptions::segment_lengths_m,
              "KITTI segment lengths in metres, e.g. 5,10,20,40 for short clips, or kitti for "
              "the leaderboard's 100..800 m.")
      .Int("segment_step_frames", &EvaluationOptions::segment_step_frames, "frames", 1, 100000, 1,
           "A KITTI segment starts at every this-many-th pose (the devkit uses 10).");
}

const RelativeErrorSummary* TrajectoryErrors::RpeForRatios() const {
  if (rpe_delta_m > 0) return rpe_over_distance ? &*rpe_over_distance : nullptr;
  return &rpe;
}

namespace {

Status CheckFinite(const Trajectory& trajectory, const char* what) {
  for (size_t i = 0; i < trajectory.size(); ++i) {
    const TimedPose& p = trajectory.poses()[i];
    if (!std::isfinite(p.time_s) || !p.world_from_sensor.matrix().allFinite()) {
      char time[32];
      std::snprintf(time, sizeof(time), "%.6f", p.time_s);
      return InvalidArgument(std::string(what) + " pose " + std::to_string(i) + " (t=" + time +
                             " s) is not finite (NaN or infinity)");
    }
  }
  return Status::Ok();
}

std::string TimeSpan(const Trajectory& t) {
  if (t.empty()) return "no poses";
  char text[96];
  std::snprintf(text, sizeof(text), "%zu poses, t=%.3f..%.3f s", t.size(), t.poses().front().time_s,
                t.poses().back().time_s);
  return text;
}

std::string Metres(double value) {
  char text[32];
  std::snprintf(text, sizeof(text), "%.3g m", value);
  return text;
}

}  // namespace

StatusOr<TrajectoryErrors> EvaluateTrajectory(const Trajectory& estimate,
                                              const Trajectory& ground_truth,
                                              const EvaluationOptions& options) {
  std::string invalid;
  if (!options.IsValid(&invalid)) return InvalidArgument(invalid);
  const AlignmentMode alignment = *ParseAlignmentMode(options.align);
  const AssociationMode association = *ParseAssociationMode(options.associate);
  const std::vector<double> segment_lengths = *ParseSegmentLengths(options.segment_lengths_m);
  SIGHTLINE_RETURN_IF_ERROR(CheckFinite(estimate, "estimate"));
  SIGHTLINE_RETURN_IF_ERROR(CheckFinite(ground_truth, "ground-truth"));

  StatusOr<AssociatedPoses> associated =
      association == AssociationMode::kIndex
          ? AssociateByIndex(estimate, ground_truth)
          : AssociateByTimestamp(estimate, ground_truth, options.max_time_difference_s);
  if (!associated.ok()) return associated.status();
  const size_t n = associated->size();
  if (n < 3) {
    char tolerance[32];
    std::snprintf(tolerance, sizeof(tolerance), "%g s", options.max_time_difference_s);
    const bool by_time = association == AssociationMode::kTimestamp;
    return InvalidArgument(
        "only " + std::to_string(n) + " poses associate" +
        (by_time ? std::string(" within ") + tolerance : std::string()) +
        " (need at least 3): estimate has " + TimeSpan(estimate) + ", ground truth " +
        TimeSpan(ground_truth) +
        (by_time ? "; check that both use the same clock or raise eval.max_time_difference_s"
                 : ""));
  }

  PoseList gt_poses;
  std::vector<Eigen::Vector3d> est_points;
  std::vector<Eigen::Vector3d> gt_points;
  TrajectoryErrors errors;
  for (size_t i = 0; i < n; ++i) {
    gt_poses.push_back(associated->ground_truth[i].world_from_sensor);
    gt_points.push_back(gt_poses.back().translation());
    est_points.push_back(associated->estimate[i].world_from_sensor.translation());
    errors.times_s.push_back(associated->estimate[i].time_s);
  }
  errors.ground_truth_length_m = PathLength(gt_poses);
  if (!(errors.ground_truth_length_m > 1e-9)) {
    return InvalidArgument("the ground truth does not move over the " + std::to_string(n) +
                           " associated poses (path length " +
                           Metres(errors.ground_truth_length_m) +
                           "): length, end-point and RPE % errors are undefined");
  }

  StatusOr<Similarity3> transform = AlignUmeyama(est_points, gt_points, alignment);
  if (!transform.ok()) return transform.status();
  PoseList est_poses;
  for (const TimedPose& p : associated->estimate) {
    est_poses.push_back(transform->Apply(p.world_from_sensor));
  }

  errors.alignment = alignment;
  errors.ground_truth_from_estimate = *transform;
  errors.pairs = n;
  errors.unmatched_estimate = associated->unmatched_estimate;
  errors.unmatched_ground_truth = associated->unmatched_ground_truth;
  errors.ground_truth_positions = gt_points;
  for (const Eigen::Isometry3d& p : est_poses) errors.estimate_positions.push_back(p.translation());
  errors.ate_m = AbsoluteTranslationErrors(est_poses, gt_poses);
  errors.ate = SummarizeErrors(errors.ate_m);

  errors.rpe_delta_frames = options.rpe_delta_frames;
  errors.rpe_delta_m = options.rpe_delta_m;
  const std::vector<RelativeError> frame_pairs =
      RelativeErrorsOverFrames(est_poses, gt_poses, options.rpe_delta_frames);
  if (frame_pairs.empty()) {
    return InvalidArgument("RPE over " + std::to_string(options.rpe_delta_frames) +
                           " frames needs more associated poses than that, got " +
                           std::to_string(n) + " (lower eval.rpe_delta_frames)");
  }
  StatusOr<RelativeErrorSummary> rpe = SummarizeRelativeErrors(frame_pairs);
  if (!rpe.ok()) {
    return rpe.status().WithContext("RPE over " + std::to_string(options.rpe_delta_frames) +
                                    " frames");
  }
  errors.rpe = *rpe;
  if (options.rpe_delta_m > 0) {
    StatusOr<RelativeErrorSummary> over_distance = SummarizeRelativeErrors(
        RelativeErrorsOverDistance(est_poses, gt_poses, options.rpe_delta_m));
    if (over_distance.ok()) {
      errors.rpe_over_distance = *over_distance;
    } else {
      errors.notes.push_back("RPE % and deg/m left out: the ground-truth path (" +
                             Metres(errors.ground_truth_length_m) + ") is shorter than " +
                             "eval.rpe_delta_m = " + Metres(options.rpe_delta_m));
    }
  }

  errors.estimate_length_m = PathLength(est_poses);
  StatusOr<double> length_error = LengthErrorPct(est_poses, gt_poses);
  if (!length_error.ok()) return length_error.status();
  errors.length_error_pct = *length_error;
  StatusOr<double> endpoint_error = EndpointErrorPct(est_poses, gt_poses);
  if (!endpoint_error.ok()) return endpoint_error.status();
  errors.endpoint_error_pct = *endpoint_error;

  StatusOr<KittiErrors> kitti =
      ComputeKittiErrors(est_poses, gt_poses, segment_lengths, options.segment_step_frames);
  if (kitti.ok()) {
    errors.kitti = std::move(*kitti);
  } else {
    errors.notes.push_back("KITTI segment errors left out: " + kitti.status().message() +
                           " (set eval.segment_lengths_m)");
  }
  return errors;
}

std::vector<std::pair<std::string, double>> AccuracyFigures(const TrajectoryErrors& errors) {
  std::vector<std::pair<std::string, double>> figures = {
      {"ate_rmse_m", errors.ate.rmse},
      {"ate_mean_m", errors.ate.mean},
      {"ate_median_m", errors.ate.median},
      {"ate_max_m", errors.ate.max},
  };
  if (const RelativeErrorSummary* ratios = errors.RpeForRatios()) {
    figures.emplace_back("rpe_trans_pct", ratios->translation_pct);
    figures.emplace_back("rpe_rot_deg_per_m", ratios->rotation_deg_per_m);
  }
  figures.emplace_back("rpe_trans_m", errors.rpe.translation_m.rmse);
  figures.emplace_back("rpe_rot_deg", errors.rpe.rotation_deg.rmse);
  figures.emplace_back("length_error_pct", errors.length_error_pct);
  figures.emplace_back("endpoint_error_pct", errors.endpoint_error_pct);
  if (errors.kitti) {
    figures.emplace_back("kitti_t_err_pct", errors.kitti->translation_error_pct);
    figures.emplace_back("kitti_r_err_deg_per_100m", errors.kitti->rotation_error_deg_per_100m);
  }
  if (errors.alignment == AlignmentMode::kSim3) {
    figures.emplace_back("scale", errors.ground_truth_from_estimate.scale);
  }
  figures.emplace_back("pairs", static_cast<double>(errors.pairs));
  return figures;
}

}  // namespace sightline
