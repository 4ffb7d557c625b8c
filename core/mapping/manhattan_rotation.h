// Manhattan rotation (seed 000): the robot's heading from the directions of the walls it sees,
// relative to the wall directions of a reference frame, with dead reckoning for the rest.
//
// Wall directions repeat every 90 deg. One frame's dominant direction is the weighted circular
// mean of 4 theta (algorithms.md):
//     m = 1/4 atan2(sum w_i sin 4 theta_i, sum w_i cos 4 theta_i),
// which has no +-45 deg wrap problem (weights: line length, lowered for lines whose points
// scatter). The first frame with enough, unambiguous wall fixes the reference direction
// alpha_ref (in the world frame). In every later frame the pose source predicts the heading
// psi_pred; the walls say psi = alpha_ref - m modulo 90 deg, and the candidate nearest psi_pred
// is taken. So the heading does not drift while walls are in view, one wall is enough, and a
// frame without walls falls back to dead reckoning.
//
// Robustness (a corridor has boxes, bins and doors recessed behind the wall faces, which give
// lines a few degrees off): lines vote only inside a tracking gate around the predicted wall
// direction that widens with the distance and angle driven since the last correction (the error
// dead reckoning can have accumulated); of the voters, a weighted median (weights favouring the
// prediction) picks the direction and only lines within trim_deg of it are averaged.
//
// Reset (seed: "reset the map when large rotations or translations were detected"): the reference
// is dropped and re-set from the current frame when the pose source jumps by more than
// reset_rotation_deg or reset_translation_m between two frames, or when long walls outside the
// gate agree among themselves on another direction in reset_disagreement_frames consecutive
// frames (the building is no longer aligned with the reference). Frames without walls never
// trigger a reset, and resets are at least reset_cooldown_frames apart, so degenerate input
// cannot cause a reset storm. After a reset the heading continues from dead reckoning.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "core/mapping/dead_reckoning.h"
#include "core/mapping/line_extractor.h"
#include "core/mapping/mapping_types.h"
#include "core/options/option_table.h"

namespace sightline {

// Options of the Manhattan rotation. Keys "mapping.rotation.*".
struct ManhattanRotationOptions {
  bool enabled = true;                   // False: dead reckoning only (for comparison).
  double min_line_length_m = 0.4;        // Shorter lines do not vote [m].
  int min_line_inliers = 10;             // Lines with fewer scan points do not vote.
  double vote_gate_deg = 10;             // Without a reference: lines within this of the
                                         // best-supported direction (modulo 90 deg) vote [deg].
  double trim_deg = 1.5;                 // Lines within this of the voters' weighted median are
                                         // averaged (4 theta); the rest are dropped [deg].
  double rms_scale_m = 0.02;             // Lines vote with weight length / (1 + (rms / scale)^2)
                                         // (rms: the line's fit error) [m].
  double min_vote_weight_m = 0.0;        // A frame's walls count only with this much summed vote
                                         // weight [m].
  double gate_min_deg = 2.0;             // With a reference, lines vote and corrections apply only
  double drift_deg_per_m = 2.0;          // within gate_min_deg + drift_deg_per_m x distance +
  double turn_error = 0.05;              // turn_error x |turn| since the last correction [deg]:
                                         // the error dead reckoning can have accumulated.
  double min_concentration = 0.7;        // |sum w e^(i 4 theta)| / sum w below this: the walls
                                         // disagree and the frame is not used.
  double min_reference_length_m = 1.0;   // Voting wall length a frame needs to set the reference.
  double max_reference_conflict = 0.25;  // ... and at most this fraction of it may conflict
                                         // (lines in the gate but outside the trim).
  double max_correction_deg = 15;        // The tracking gate never exceeds this [deg].
  double correction_gain = 1.0;          // Fraction of the correction applied (1 = seed: absolute).
  double class_tolerance_deg = 10;       // A line within this of a Manhattan axis gets its class.
  double reset_rotation_deg = 45;        // Pose-source heading jump that resets [deg per frame].
  double reset_translation_m = 1.0;      // Pose-source position jump that resets [m per frame].
  int reset_disagreement_frames = 15;    // Consecutive gated frames that reset.
  int reset_cooldown_frames = 30;        // Frames after a reset during which no other fires.

  bool IsValid(std::string* error) const;
  static OptionTable<ManhattanRotationOptions> Describe();
};

// The dominant wall direction of a frame's lines, robustly: lines below the length / inlier
// limits do not vote, nor do lines farther than `gate_rad` (modulo 90 deg) from `expected_rad`
// (the direction the walls should have, from the reference and the predicted heading) or,
// without it, farther than vote_gate_deg from the direction with the most wall length. Of the
// voters, those within trim_deg of their weighted median are averaged with the 4-theta formula
// (weights = length / (1 + (rms / rms_scale_m)^2), so that lines whose points scatter, such as
// a wall merged with a recessed door, count less). The median's weights are these, times, when
// tracking, a Gaussian of the deviation from `expected_rad` with sigma = gate / 2. Boxes, bins and
// a wall merged with a recessed door give lines a few degrees off; the median and the trim keep
// them out. Invalid when no line votes, the concentration is below the limit or the vote weight is
// below min_vote_weight_m.
ManhattanMeasurement MeasureManhattanAngle(const std::vector<WallSegment>& lines,
                                           const ManhattanRotationOptions& options,
                                           std::optional<double> expected_rad = std::nullopt,
                                           std::optional<double> gate_rad = std::nullopt);

// Tracks the heading. Construct, then Update() once per frame in order.
//
//   ManhattanRotation rotation(options);
//   RotationEstimate r = rotation.Update(lines, odometry_step);
//   rotation.Classify(r, &lines);  // Manhattan direction class per line
class ManhattanRotation {
 public:
  explicit ManhattanRotation(ManhattanRotationOptions options = {});

  // Starts over at `heading_rad` without a reference.
  void Restart(double heading_rad = 0);
  // One frame: lines in the base frame and the pose source's motion since the last frame.
  RotationEstimate Update(const std::vector<WallSegment>& lines, const OdometryIncrement& step);
  // Sets each line's direction_class against the reference (or, before one exists, against the
  // frame's own dominant direction).
  void Classify(const RotationEstimate& estimate, std::vector<WallSegment>* lines) const;

  double heading_rad() const { return heading_rad_; }
  int resets() const { return resets_; }
  const ManhattanRotationOptions& options() const { return options_; }

 private:
  ManhattanRotationOptions options_;
  double heading_rad_ = 0;
  bool has_reference_ = false;
  double reference_rad_ = 0;
  int frame_ = 0;
  int last_reset_frame_ = -1000000;
  int disagreeing_frames_ = 0;
  int resets_ = 0;
  double distance_since_correction_m_ = 0;
  double turn_since_correction_rad_ = 0;
};

}  // namespace sightline
