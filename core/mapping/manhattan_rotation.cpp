#include "core/mapping/manhattan_rotation.h"

#include <cmath>
#include <cstdio>

#include "core/mapping/option_check.h"
#include "core/mapping/pose2d.h"

namespace sightline {

using mapping_internal::Invalid;

bool ManhattanRotationOptions::IsValid(std::string* error) const {
  if (!(min_line_length_m >= 0))
    return Invalid(error, "mapping.rotation.min_line_length_m must be >= 0");
  if (min_line_inliers < 2) return Invalid(error, "mapping.rotation.min_line_inliers must be >= 2");
  if (!(vote_gate_deg > 0 && vote_gate_deg <= 45)) {
    return Invalid(error, "mapping.rotation.vote_gate_deg must lie in (0, 45]");
  }
  if (!(trim_deg > 0)) return Invalid(error, "mapping.rotation.trim_deg must be positive");
  if (!(rms_scale_m > 0)) return Invalid(error, "mapping.rotation.rms_scale_m must be positive");
  if (!(min_vote_weight_m >= 0)) {
    return Invalid(error, "mapping.rotation.min_vote_weight_m must be >= 0");
  }
  if (!(gate_min_deg > 0)) return Invalid(error, "mapping.rotation.gate_min_deg must be positive");
  if (!(drift_deg_per_m >= 0))
    return Invalid(error, "mapping.rotation.drift_deg_per_m must be >= 0");
  if (!(turn_error >= 0 && turn_error <= 1)) {
    return Invalid(error, "mapping.rotation.turn_error must lie in [0, 1]");
  }
  if (!(max_reference_conflict >= 0)) {
    return Invalid(error, "mapping.rotation.max_reference_conflict must be >= 0");
  }
  if (!(min_reference_length_m >= 0)) {
    return Invalid(error, "mapping.rotation.min_reference_length_m must be >= 0");
  }
  if (!(min_concentration >= 0 && min_concentration <= 1)) {
    return Invalid(error, "mapping.rotation.min_concentration must lie in [0, 1]");
  }
  if (!(max_correction_deg > 0 && max_correction_deg <= 45)) {
    return Invalid(error, "mapping.rotation.max_correction_deg must lie in (0, 45]");
  }
  if (!(correction_gain > 0 && correction_gain <= 1)) {
    return Invalid(error, "mapping.rotation.correction_gain must lie in (0, 1]");
  }
  if (!(class_tolerance_deg > 0 && class_tolerance_deg < 45)) {
    return Invalid(error, "mapping.rotation.class_tolerance_deg must lie in (0, 45)");
  }
  if (!(reset_rotation_deg > 0))
    return Invalid(error, "mapping.rotation.reset_rotation_deg must be positive");
  if (!(reset_translation_m > 0)) {
    return Invalid(error, "mapping.rotation.reset_translation_m must be positive");
  }
  if (reset_disagreement_frames < 1) {
    return Invalid(error, "mapping.rotation.reset_disagreement_frames must be >= 1");
  }
  if (reset_cooldown_frames < 0)
    return Invalid(error, "mapping.rotation.reset_cooldown_frames must be >= 0");
  return true;
}

OptionTable<ManhattanRotationOptions> ManhattanRotationOptions::Describe() {
  using O = ManhattanRotationOptions;
  return OptionTable<O>("mapping.rotation")
      .Bool("enabled", &O::enabled,
            "Correct the heading with the walls' Manhattan directions; off = dead reckoning only.")
      .Double("min_line_length_m", &O::min_line_length_m, "m", 0, 20, 0.05,
              "Wall lines shorter than this do not vote for the direction.")
      .Int("min_line_inliers", &O::min_line_inliers, "points", 2, 10000, 1,
           "Wall lines with fewer scan points do not vote.")
      .Double("vote_gate_deg", &O::vote_gate_deg, "deg", 0.1, 45, 0.5,
              "Without a reference: lines within this of the best-supported direction (modulo "
              "90 deg) vote.")
      .Double("trim_deg", &O::trim_deg, "deg", 0.01, 45, 0.1,
              "Voting lines within this of their length-weighted median are averaged; others "
              "(a wall merged with a recessed door, a box) are dropped.")
      .Double("rms_scale_m", &O::rms_scale_m, "m", 0.001, 1, 0.005,
              "Lines vote with weight length / (1 + (rms / rms_scale_m)^2): scattered consensus "
              "sets (a wall merged with a door recess) count less.")
      .Double("min_vote_weight_m", &O::min_vote_weight_m, "m", 0, 50, 0.05,
              "A frame's walls count only when their summed vote weight (length x fit quality) "
              "reaches this.")
      .Double("gate_min_deg", &O::gate_min_deg, "deg", 0.01, 45, 0.1,
              "Tracking gate right after a correction: lines farther than this from the "
              "expected direction neither vote nor correct.")
      .Double("drift_deg_per_m", &O::drift_deg_per_m, "deg/m", 0, 90, 0.1,
              "The gate widens by this per metre driven since the last correction (expected "
              "heading drift of the pose source).")
      .Double("turn_error", &O::turn_error, "", 0, 1, 0.01,
              "... and by this fraction of the angle turned since the last correction.")
      .Double("min_reference_length_m", &O::min_reference_length_m, "m", 0, 50, 0.1,
              "Voting wall length a frame needs before it may set the reference direction.")
      .Double("max_reference_conflict", &O::max_reference_conflict, "", 0, 100, 0.05,
              "A frame sets the reference only when the wall length in a second direction a few "
              "degrees off (inside the gate, outside the trim) is at most this fraction of the "
              "main direction's.")
      .Double("min_concentration", &O::min_concentration, "", 0, 1, 0.05,
              "Agreement of the voting lines modulo 90 deg (1 = perfect); below it the frame's "
              "walls are not used.")
      .Double("max_correction_deg", &O::max_correction_deg, "deg", 0.1, 45, 0.5,
              "The tracking gate never exceeds this: larger corrections are not applied.")
      .Double("correction_gain", &O::correction_gain, "", 0.01, 1, 0.05,
              "Fraction of the correction applied per frame (1 = take the walls' heading).")
      .Double("class_tolerance_deg", &O::class_tolerance_deg, "deg", 0.5, 44, 0.5,
              "A line this close to a Manhattan axis is classed as parallel (0) or "
              "perpendicular (1) to the reference.")
      .Double("reset_rotation_deg", &O::reset_rotation_deg, "deg", 1, 360, 1,
              "Reset rule: a pose-source turn larger than this between two frames resets the "
              "reference.")
      .Double("reset_translation_m", &O::reset_translation_m, "m", 0.01, 100, 0.05,
              "Reset rule: a pose-source move larger than this between two frames resets the "
              "reference.")
      .Int("reset_disagreement_frames", &O::reset_disagreement_frames, "frames", 1, 100000, 1,
           "Reset rule: this many consecutive frames whose walls disagree by more than "
           "max_correction_deg reset the reference.")
      .Int("reset_cooldown_frames", &O::reset_cooldown_frames, "frames", 0, 100000, 1,
           "No second reset within this many frames of the last one.");
}

ManhattanMeasurement MeasureManhattanAngle(const std::vector<WallSegment>& lines,
                                           const ManhattanRotationOptions& options,
                                           std::optional<double> expected_rad,
                                           std::optional<double> gate_rad) {
  ManhattanMeasurement m;
  auto eligible = [&](const WallSegment& line) {
    return line.length_m >= options.min_line_length_m && line.inliers >= options.min_line_inliers;
  };
  double gate = gate_rad.value_or(DegToRad(options.vote_gate_deg));
  const bool tracking = expected_rad.has_value();
  if (!expected_rad) {
    // The direction with the most wall length within the gate (modulo 90 deg).
    gate = DegToRad(options.vote_gate_deg);
    double best_support = 0;
    for (const WallSegment& candidate : lines) {
      if (!eligible(candidate)) continue;
      double support = 0;
      for (const WallSegment& line : lines) {
        if (eligible(line) &&
            std::abs(WrapQuarterTurn(line.angle_rad - candidate.angle_rad)) <= gate) {
          support += line.length_m;
        }
      }
      if (support > best_support) {
        best_support = support;
        expected_rad = candidate.angle_rad;
      }
    }
    if (!expected_rad) return m;
  }
  // Voters: deviation from the expected direction, length, and the weight of the median: the
  // length, and when tracking also the agreement with the prediction (a Gaussian of half the
  // gate), so that of two clusters of lines the one the prediction explains wins.
  struct Vote {
    double deviation, length, weight;
  };
  std::vector<Vote> votes;
  const double sigma = 0.5 * gate;
  for (const WallSegment& line : lines) {
    if (!eligible(line)) continue;
    const double deviation = WrapQuarterTurn(line.angle_rad - *expected_rad);
    if (std::abs(deviation) > gate) {
      ++m.rejected_lines;
      continue;
    }
    const double agreement =
        tracking ? std::exp(-0.5 * (deviation / sigma) * (deviation / sigma)) : 1.0;
    // A line whose consensus points scatter (a wall merged with a recessed door) is a few
    // tenths of a degree to degrees off: weight lines by their fit quality too.
    const double quality = 1.0 / (1.0 + (line.rms_error_m / options.rms_scale_m) *
                                            (line.rms_error_m / options.rms_scale_m));
    votes.push_back({deviation, line.length_m * quality, line.length_m * quality * agreement});
  }
  if (votes.empty()) return m;
  // Weighted median of the deviations.
  std::sort(votes.begin(), votes.end(),
            [](const Vote& a, const Vote& b) { return a.deviation < b.deviation; });
  double total = 0;
  for (const Vote& v : votes) total += v.weight;
  double median = votes.back().deviation, running = 0;
  for (const Vote& v : votes) {
    running += v.weight;
    if (running >= 0.5 * total) {
      median = v.deviation;
      break;
    }
  }
  // 4-theta mean (weights = length) of the voters near the median.
  const double trim = DegToRad(options.trim_deg);
  double sum_sin = 0, sum_cos = 0;
  for (const Vote& v : votes) {
    const double deviation = v.deviation, w = v.length;
    if (std::abs(deviation - median) > trim) {
      ++m.rejected_lines;
      // Only a direction a few degrees off is a conflict; farther ones are other structures.
      if (std::abs(deviation - median) <= 0.5 * DegToRad(options.vote_gate_deg)) {
        m.trimmed_weight_m += w;
      }
      continue;
    }
    const double angle = *expected_rad + deviation;
    sum_sin += w * std::sin(4 * angle);
    sum_cos += w * std::cos(4 * angle);
    m.weight_m += w;
    ++m.voting_lines;
  }
  if (m.voting_lines == 0 || m.weight_m <= 0) return m;
  m.concentration = std::hypot(sum_sin, sum_cos) / m.weight_m;
  m.angle_rad = WrapQuarterTurn(0.25 * std::atan2(sum_sin, sum_cos));
  m.valid = m.concentration >= options.min_concentration && m.weight_m >= options.min_vote_weight_m;
  return m;
}

ManhattanRotation::ManhattanRotation(ManhattanRotationOptions options)
    : options_(std::move(options)) {}

void ManhattanRotation::Restart(double heading_rad) {
  heading_rad_ = WrapAngle(heading_rad);
  has_reference_ = false;
  reference_rad_ = 0;
  frame_ = 0;
  last_reset_frame_ = -1000000;
  disagreeing_frames_ = 0;
  resets_ = 0;
  distance_since_correction_m_ = 0;
  turn_since_correction_rad_ = 0;
}

RotationEstimate ManhattanRotation::Update(const std::vector<WallSegment>& lines,
                                           const OdometryIncrement& step) {
  const int frame = frame_++;
  const bool cooldown_over = frame - last_reset_frame_ >= options_.reset_cooldown_frames;
  RotationEstimate e;
  const double predicted = WrapAngle(heading_rad_ + (step.valid ? step.heading_change_rad : 0));
  e.predicted_heading_rad = predicted;
  double heading = predicted;
  char text[200];

  auto fire_reset = [&](const std::string& reason) {
    e.reset = true;
    e.reset_reason = reason;
    has_reference_ = false;
    disagreeing_frames_ = 0;
    last_reset_frame_ = frame;
    ++resets_;
  };
  // Large jumps of the pose source.
  if (step.valid && cooldown_over) {
    const double turn_deg = RadToDeg(std::abs(step.heading_change_rad));
    const double move_m = step.translation_in_previous_base.norm();
    if (turn_deg > options_.reset_rotation_deg) {
      std::snprintf(text, sizeof(text), "pose source turned %.1f deg in one frame (limit %.1f)",
                    turn_deg, options_.reset_rotation_deg);
      fire_reset(text);
    } else if (move_m > options_.reset_translation_m) {
      std::snprintf(text, sizeof(text), "pose source moved %.2f m in one frame (limit %.2f)",
                    move_m, options_.reset_translation_m);
      fire_reset(text);
    }
  }

  // The error dead reckoning may have accumulated since the last correction.
  if (step.valid) {
    distance_since_correction_m_ += step.translation_in_previous_base.norm();
    turn_since_correction_rad_ += std::abs(step.heading_change_rad);
  }
  const double gate = std::min(
      DegToRad(options_.max_correction_deg),
      DegToRad(options_.gate_min_deg + options_.drift_deg_per_m * distance_since_correction_m_) +
          options_.turn_error * turn_since_correction_rad_);
  e.gate_rad = gate;
  // With a reference, the walls should appear at reference - predicted heading (modulo 90).
  e.measurement = MeasureManhattanAngle(
      lines, options_,
      has_reference_ ? std::optional<double>(WrapQuarterTurn(reference_rad_ - predicted))
                     : std::nullopt,
      gate);
  // Walls the gate rejected, measured on their own: do they agree among themselves?
  ManhattanMeasurement other;
  if (has_reference_ && !e.measurement.valid && e.measurement.rejected_lines > 0) {
    other = MeasureManhattanAngle(lines, options_);
  }
  const bool disagree = other.valid && other.weight_m >= options_.min_reference_length_m;

  if (!options_.enabled) {
    e.status = "dead reckoning (Manhattan correction off)";
  } else if (disagree) {
    // Long walls at a direction the reference does not explain.
    e.gated = true;
    e.raw_correction_rad = WrapQuarterTurn(reference_rad_ - other.angle_rad - predicted);
    ++disagreeing_frames_;
    std::snprintf(text, sizeof(text), "walls disagree with the reference by %.1f deg",
                  RadToDeg(e.raw_correction_rad));
    e.status = text;
    if (disagreeing_frames_ >= options_.reset_disagreement_frames && cooldown_over) {
      std::snprintf(text, sizeof(text),
                    "walls disagreed with the reference by more than %.1f deg in %d frames",
                    options_.vote_gate_deg, options_.reset_disagreement_frames);
      fire_reset(text);
      reference_rad_ = WrapQuarterTurn(other.angle_rad + predicted);
      has_reference_ = true;
      distance_since_correction_m_ = 0;
      turn_since_correction_rad_ = 0;
      e.status = "reference re-set";
    }
  } else if (!e.measurement.valid) {
    if (e.measurement.voting_lines == 0 && e.measurement.rejected_lines > 0) {
      e.status = "no wall along the Manhattan directions: dead reckoning";
    } else if (e.measurement.voting_lines == 0) {
      e.status = "no walls: dead reckoning";
    } else {
      std::snprintf(text, sizeof(text), "walls disagree (concentration %.2f): dead reckoning",
                    e.measurement.concentration);
      e.status = text;
    }
  } else if (!has_reference_ && e.measurement.weight_m < options_.min_reference_length_m) {
    e.status = "too little wall to set the reference: dead reckoning";
  } else if (!has_reference_ && e.measurement.trimmed_weight_m >
                                    options_.max_reference_conflict * e.measurement.weight_m) {
    e.status = "walls in two directions a few degrees apart: reference not set yet";
  } else if (!has_reference_) {
    reference_rad_ = WrapQuarterTurn(e.measurement.angle_rad + predicted);
    has_reference_ = true;
    distance_since_correction_m_ = 0;
    turn_since_correction_rad_ = 0;
    e.status = "reference set";
  } else {
    const double raw = WrapQuarterTurn(reference_rad_ - e.measurement.angle_rad - predicted);
    e.raw_correction_rad = raw;
    if (std::abs(raw) <= gate) {
      heading = predicted + options_.correction_gain * raw;
      e.corrected = true;
      disagreeing_frames_ = 0;
      distance_since_correction_m_ = 0;
      turn_since_correction_rad_ = 0;
      e.status = "corrected";
    } else {
      e.gated = true;
      std::snprintf(text, sizeof(text), "gated: walls say %.1f deg, limit %.1f", RadToDeg(raw),
                    RadToDeg(gate));
      e.status = text;
    }
  }
  heading_rad_ = WrapAngle(heading);
  e.heading_rad = heading_rad_;
  e.correction_rad = WrapAngle(heading_rad_ - predicted);
  e.reference_set = has_reference_;
  e.reference_angle_rad = reference_rad_;
  return e;
}

void ManhattanRotation::Classify(const RotationEstimate& estimate,
                                 std::vector<WallSegment>* lines) const {
  const double tolerance = DegToRad(options_.class_tolerance_deg);
  const bool have_axis = estimate.reference_set || estimate.measurement.voting_lines > 0;
  for (WallSegment& line : *lines) {
    line.direction_class = -1;
    if (!have_axis) continue;
    const double delta =
        estimate.reference_set
            ? WrapHalfTurn(line.angle_rad + estimate.heading_rad - estimate.reference_angle_rad)
            : WrapHalfTurn(line.angle_rad - estimate.measurement.angle_rad);
    if (std::abs(delta) <= tolerance) {
      line.direction_class = 0;
    } else if (std::abs(delta) >= std::numbers::pi / 2 - tolerance) {
      line.direction_class = 1;
    }
  }
}

}  // namespace sightline
