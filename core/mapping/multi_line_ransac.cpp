#include "core/mapping/multi_line_ransac.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "core/mapping/option_check.h"
#include "core/mapping/pose2d.h"

namespace sightline {

using mapping_internal::Invalid;

bool MultiLineRansacOptions::IsValid(std::string* error) const {
  if (!(error_threshold_cells > 0)) {
    return Invalid(error, "mapping.ransac.error_threshold_cells must be positive");
  }
  if (!(min_pair_distance_m >= 0 && max_pair_distance_m > min_pair_distance_m)) {
    return Invalid(error,
                   "mapping.ransac.min_pair_distance_m must be >= 0 and below "
                   "max_pair_distance_m");
  }
  if (max_pair_draws < 1) return Invalid(error, "mapping.ransac.max_pair_draws must be >= 1");
  if (!(min_inlier_ratio > 0 && min_inlier_ratio <= 1)) {
    return Invalid(error, "mapping.ransac.min_inlier_ratio must lie in (0, 1]");
  }
  if (!(early_exit_ratio > 0 && early_exit_ratio <= 1)) {
    return Invalid(error, "mapping.ransac.early_exit_ratio must lie in (0, 1]");
  }
  if (iterations != "fixed" && iterations != "adaptive") {
    return Invalid(error, "mapping.ransac.iterations must be fixed or adaptive");
  }
  if (max_iterations < 1) return Invalid(error, "mapping.ransac.max_iterations must be >= 1");
  if (!(confidence > 0 && confidence < 1)) {
    return Invalid(error, "mapping.ransac.confidence must lie in (0, 1)");
  }
  if (best_by != "total_error" && best_by != "mean_error") {
    return Invalid(error, "mapping.ransac.best_by must be total_error or mean_error");
  }
  if (!(stop_assigned_ratio > 0 && stop_assigned_ratio <= 1)) {
    return Invalid(error, "mapping.ransac.stop_assigned_ratio must lie in (0, 1]");
  }
  if (max_lines < 1) return Invalid(error, "mapping.ransac.max_lines must be >= 1");
  if (min_line_points < 2) return Invalid(error, "mapping.ransac.min_line_points must be >= 2");
  if (!(max_gap_m >= 0)) return Invalid(error, "mapping.ransac.max_gap_m must be >= 0");
  if (!(refine_sweep_deg >= 0 && refine_sweep_deg <= 45)) {
    return Invalid(error, "mapping.ransac.refine_sweep_deg must lie in [0, 45]");
  }
  if (!(refine_threshold_cells > 0)) {
    return Invalid(error, "mapping.ransac.refine_threshold_cells must be positive");
  }
  return true;
}

OptionTable<MultiLineRansacOptions> MultiLineRansacOptions::Describe() {
  using O = MultiLineRansacOptions;
  return OptionTable<O>("mapping.ransac")
      .Double("error_threshold_cells", &O::error_threshold_cells, "cells", 0.1, 100, 0.5,
              "err_max: inlier distance in occupancy cells (published: 5 pixels); metres = cells x "
              "mapping.occupancy.cell_size_m.")
      .Double("min_pair_distance_m", &O::min_pair_distance_m, "m", 0, 50, 0.05,
              "Step B2: the two sampled points must be at least this far apart (no short lines).")
      .Double("max_pair_distance_m", &O::max_pair_distance_m, "m", 0.01, 100, 0.1,
              "Step B2: ... and at most this far apart (no lines across the room).")
      .Int("max_pair_draws", &O::max_pair_draws, "", 1, 10000, 5,
           "Draws per hypothesis to find a pair within the distance limits.")
      .Double("min_inlier_ratio", &O::min_inlier_ratio, "", 0.01, 1, 0.01,
              "ratio_min (steps B5, B6): a line needs this fraction of the remaining points.")
      .Double("early_exit_ratio", &O::early_exit_ratio, "", 0.01, 1, 0.01,
              "ratio_max (step B8): a hypothesis with more inliers than this ends the search.")
      .Choice("iterations", &O::iterations, {"fixed", "adaptive"},
              "Hypotheses per line: fixed (max_iterations, seed) or adaptive "
              "log(1-p)/log(1-w^2) with w the best inlier ratio so far.")
      .Int("max_iterations", &O::max_iterations, "", 1, 100000, 10,
           "j_max: hypotheses per line (published: 250); also caps the adaptive count.")
      .Double("confidence", &O::confidence, "", 0.5, 0.999999, 0.001,
              "p of the adaptive count: probability of drawing one all-inlier pair.")
      .Choice(
          "best_by", &O::best_by, {"total_error", "mean_error"},
          "Step B7: keep the hypothesis with the lowest summed error (as published) or mean error.")
      .Double("stop_assigned_ratio", &O::stop_assigned_ratio, "", 0.01, 1, 0.01,
              "ratio_scan_max (step E): stop once this fraction of the points lies on lines.")
      .Int("max_lines", &O::max_lines, "", 1, 10000, 1, "i_max (step E): at most this many lines.")
      .Int("min_line_points", &O::min_line_points, "points", 2, 10000, 1,
           "A line needs at least this many points (2 = as published; more rejects clutter).")
      .Double("max_gap_m", &O::max_gap_m, "m", 0, 100, 0.05,
              "Step B6: cut the consensus set at gaps wider than this along the line and keep "
              "the longest piece, so that lines are contiguous walls (0 = as published: no cut).")
      .Double("refine_sweep_deg", &O::refine_sweep_deg, "deg", 0, 45, 0.5,
              "Step C: re-find the chosen line's dominant surface by sweeping its direction this "
              "far either way, then refit on it (0 = as published: the line of step B6 as is).")
      .Double("refine_threshold_cells", &O::refine_threshold_cells, "cells", 0.1, 100, 0.5,
              "Band of the refinement (offset histogram bin and refit band): narrower than "
              "err_max, so that a door recessed behind the wall face does not tilt the line.")
      .Int("seed", &O::seed, "", 0, 2147483647, 1,
           "Random generator seed; each scan starts from it, so results are reproducible.");
}

int AdaptiveIterationCount(double confidence, double inlier_ratio) {
  if (inlier_ratio >= 1) return 1;
  if (inlier_ratio <= 0) return std::numeric_limits<int>::max();
  const double sample_good = inlier_ratio * inlier_ratio;
  const double k = std::log(1 - confidence) / std::log(1 - sample_good);
  if (!(k < 1e9)) return std::numeric_limits<int>::max();
  return std::max(1, static_cast<int>(std::ceil(k - 1e-9)));
}

namespace {

// Sorts `indices` along the line with unit normal `normal`, cuts at gaps wider than `max_gap`
// and keeps the piece with the most points.
void KeepLongestRun(const std::vector<Eigen::Vector2d>& points, const Eigen::Vector2d& normal,
                    double max_gap, std::vector<int>* indices) {
  if (indices->size() < 2) return;
  const Eigen::Vector2d direction(-normal.y(), normal.x());
  std::sort(indices->begin(), indices->end(),
            [&](int a, int b) { return direction.dot(points[a]) < direction.dot(points[b]); });
  size_t best_begin = 0, best_end = 1, begin = 0;
  for (size_t i = 1; i <= indices->size(); ++i) {
    const bool cut = i == indices->size() ||
                     direction.dot(points[(*indices)[i]] - points[(*indices)[i - 1]]) > max_gap;
    if (!cut) continue;
    if (i - begin > best_end - best_begin) {
      best_begin = begin;
      best_end = i;
    }
    begin = i;
  }
  if (best_begin > 0)
    std::copy(indices->begin() + best_begin, indices->begin() + best_end, indices->begin());
  indices->resize(best_end - best_begin);
}

}  // namespace

MultiLineRansac::MultiLineRansac(MultiLineRansacOptions options) : options_(std::move(options)) {}

StatusOr<LineExtraction> MultiLineRansac::Extract(const PolarScan& scan) {
  points_.resize(scan.points.size());
  for (size_t i = 0; i < scan.points.size(); ++i) points_[i] = scan.points[i].xy;
  std::vector<Eigen::Vector2d> points;
  points.swap(points_);
  StatusOr<LineExtraction> result = ExtractPoints(points, scan.cell_size_m);
  points_.swap(points);
  return result;
}

void MultiLineRansac::RefineLine(const std::vector<Eigen::Vector2d>& points, double cell_size_m,
                                 Eigen::Vector2d* normal, double* offset) {
  const MultiLineRansacOptions& o = options_;
  const double band = o.refine_threshold_cells * cell_size_m;
  // Sweep the direction around the seed's line; for each, histogram the points' offsets in
  // bins of one band. Parallel surfaces (a wall and a door recessed behind it) each give one
  // sharp peak at their true direction and smear out at any other, so the direction whose
  // histogram is sharpest (largest sum of squared counts) is theirs. Counting the points in
  // one window instead would favour a diagonal touching both surfaces.
  const double base = std::atan2(normal->y(), normal->x());
  const double step = DegToRad(0.1);
  const int steps = static_cast<int>(std::lround(DegToRad(o.refine_sweep_deg) / step));
  int64_t best_score = -1;
  double best_angle = base, best_center = *offset;
  for (int k = 0; k <= 2 * steps; ++k) {
    // 0, +1, -1, +2, -2, ...: ties go to the direction nearer the seed's line.
    const int offset_steps = (k % 2 == 1) ? (k + 1) / 2 : -(k / 2);
    const double angle = base + offset_steps * step;
    const Eigen::Vector2d n(std::cos(angle), std::sin(angle));
    double lo = std::numeric_limits<double>::max();
    for (int idx : best_set_) lo = std::min(lo, n.dot(points[idx]));
    histogram_.assign(
        static_cast<size_t>(4 * o.error_threshold_cells / o.refine_threshold_cells) + 8, 0);
    for (int idx : best_set_) {
      const size_t bin =
          std::min(histogram_.size() - 1, static_cast<size_t>((n.dot(points[idx]) - lo) / band));
      ++histogram_[bin];
    }
    int64_t score = 0;
    int window = -1;
    size_t window_bin = 0;
    for (size_t bin = 0; bin < histogram_.size(); ++bin) {
      score += static_cast<int64_t>(histogram_[bin]) * histogram_[bin];
      if (bin + 1 < histogram_.size() && histogram_[bin] + histogram_[bin + 1] > window) {
        window = histogram_[bin] + histogram_[bin + 1];
        window_bin = bin;
      }
    }
    if (score > best_score) {
      best_score = score;
      best_angle = angle;
      best_center = lo + (window_bin + 1) * band;
    }
  }
  Eigen::Vector2d n(std::cos(best_angle), std::sin(best_angle));
  double d = best_center;
  // Refit on the points within the band of that surface, then twice within 3/4 of it, so that
  // the jamb between a wall and a recessed door (points across the band) barely pulls the fit.
  for (int round = 0; round < 3; ++round) {
    const double window = round == 0 ? band : 0.75 * band;
    current_set_.clear();
    for (int idx : best_set_) {
      if (std::abs(n.dot(points[idx]) - d) < window) current_set_.push_back(idx);
    }
    if (static_cast<int>(current_set_.size()) < std::max(2, o.min_line_points / 2) ||
        !FitLineTotalLeastSquares(points, current_set_, &n, &d)) {
      return;
    }
  }
  *normal = n;
  *offset = d;
}

StatusOr<LineExtraction> MultiLineRansac::ExtractPoints(const std::vector<Eigen::Vector2d>& points,
                                                        double cell_size_m) {
  std::string error;
  if (!options_.IsValid(&error)) return InvalidArgument(error);
  if (!(cell_size_m > 0)) return InvalidArgument("multi-line RANSAC: cell size must be positive");
  const MultiLineRansacOptions& o = options_;
  const double threshold = o.error_threshold_cells * cell_size_m;
  const double min_pair_sq = o.min_pair_distance_m * o.min_pair_distance_m;
  const double max_pair_sq = o.max_pair_distance_m * o.max_pair_distance_m;
  const bool adaptive = o.iterations == "adaptive";
  const bool by_total = o.best_by == "total_error";

  LineExtraction result;
  const int n0 = static_cast<int>(points.size());
  result.points = n0;
  result.point_line.assign(n0, -1);
  rng_.seed(static_cast<uint32_t>(o.seed));
  // Step A.
  remaining_.resize(n0);
  for (int i = 0; i < n0; ++i) remaining_[i] = i;

  while (true) {
    const int ni = static_cast<int>(remaining_.size());
    if (static_cast<int>(result.lines.size()) >= o.max_lines) {
      result.stop_reason = "reached max_lines (step E)";
      break;
    }
    if (ni < std::max(2, o.min_line_points)) {
      result.stop_reason = "too few points left for a line";
      break;
    }
    // Step B.
    std::uniform_int_distribution<int> pick(0, ni - 1);
    bool found = false;
    double best_score = 0;
    Eigen::Vector2d best_normal = Eigen::Vector2d::UnitX();
    double best_offset = 0;
    best_set_.clear();
    int j_max = o.max_iterations;
    if (adaptive) j_max = std::min(j_max, AdaptiveIterationCount(o.confidence, o.min_inlier_ratio));
    double w_best = o.min_inlier_ratio;
    for (int j = 0; j < j_max; ++j) {
      ++result.iterations;
      // B1, B2: a pair of points within the distance limits.
      int a = -1, b = -1;
      for (int draw = 0; draw < o.max_pair_draws; ++draw) {
        const int ia = pick(rng_), ib = pick(rng_);
        if (ia == ib) continue;
        const double dist_sq = (points[remaining_[ia]] - points[remaining_[ib]]).squaredNorm();
        if (dist_sq < min_pair_sq || dist_sq > max_pair_sq) continue;
        a = remaining_[ia];
        b = remaining_[ib];
        break;
      }
      if (a < 0) continue;
      // B3: the line through the pair.
      const Eigen::Vector2d direction = (points[b] - points[a]).normalized();
      const Eigen::Vector2d normal(-direction.y(), direction.x());
      const double offset = normal.dot(points[a]);
      // B4: consensus set.
      consensus_.clear();
      for (int idx : remaining_) {
        if (std::abs(normal.dot(points[idx]) - offset) < threshold) consensus_.push_back(idx);
      }
      // B5: inlier ratio.
      if (consensus_.size() < o.min_inlier_ratio * ni) continue;
      // B6: least-squares refit and re-test on the consensus set.
      Eigen::Vector2d refit_normal;
      double refit_offset = 0;
      if (!FitLineTotalLeastSquares(points, consensus_, &refit_normal, &refit_offset)) continue;
      refit_.clear();
      for (int idx : consensus_) {
        if (std::abs(refit_normal.dot(points[idx]) - refit_offset) < threshold) {
          refit_.push_back(idx);
        }
      }
      if (o.max_gap_m > 0) KeepLongestRun(points, refit_normal, o.max_gap_m, &refit_);
      double total_error = 0;
      for (int idx : refit_) total_error += std::abs(refit_normal.dot(points[idx]) - refit_offset);
      const double ratio = static_cast<double>(refit_.size()) / ni;
      if (ratio < o.min_inlier_ratio || static_cast<int>(refit_.size()) < o.min_line_points) {
        continue;
      }
      // B7: best error so far.
      const double score = by_total ? total_error : total_error / refit_.size();
      const bool early_exit = ratio > o.early_exit_ratio;
      if (!found || score < best_score || early_exit) {
        found = true;
        best_score = score;
        best_normal = refit_normal;
        best_offset = refit_offset;
        best_set_.swap(refit_);
      }
      // B8: early exit; the current hypothesis is declared the line.
      if (early_exit) break;
      if (adaptive && ratio > w_best) {
        w_best = ratio;
        j_max = std::min(o.max_iterations, AdaptiveIterationCount(o.confidence, w_best));
      }
    }
    if (!found) {
      result.stop_reason = "no hypothesis passed the inlier tests (step F)";
      break;
    }
    // C: the line's properties, after the optional refinement: the dominant surface inside the
    // consensus set, found with 2-point hypotheses in a narrower band, then refitted.
    if (o.refine_sweep_deg > 0 && best_set_.size() >= 2) {
      RefineLine(points, cell_size_m, &best_normal, &best_offset);
    }
    const int line_index = static_cast<int>(result.lines.size());
    result.lines.push_back(MakeWallSegment(best_normal, best_offset, points, best_set_));
    // D: remove the consensus set.
    for (int idx : best_set_) result.point_line[idx] = line_index;
    result.assigned += static_cast<int>(best_set_.size());
    remaining_.erase(std::remove_if(remaining_.begin(), remaining_.end(),
                                    [&](int idx) { return result.point_line[idx] >= 0; }),
                     remaining_.end());
    // E: enough points assigned.
    if (result.assigned > o.stop_assigned_ratio * n0) {
      char text[96];
      std::snprintf(text, sizeof(text), "%.0f %% of the points lie on lines (step E)",
                    100.0 * result.assigned / n0);
      result.stop_reason = text;
      break;
    }
  }
  return result;
}

}  // namespace sightline
