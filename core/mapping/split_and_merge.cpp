#include "core/mapping/split_and_merge.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/mapping/option_check.h"
#include "core/mapping/pose2d.h"

namespace sightline {

using mapping_internal::Invalid;

bool SplitAndMergeOptions::IsValid(std::string* error) const {
  if (!(error_threshold_cells > 0)) {
    return Invalid(error, "mapping.split_merge.error_threshold_cells must be positive");
  }
  if (!(max_gap_m > 0)) return Invalid(error, "mapping.split_merge.max_gap_m must be positive");
  if (min_line_points < 2)
    return Invalid(error, "mapping.split_merge.min_line_points must be >= 2");
  if (!(min_length_m >= 0)) return Invalid(error, "mapping.split_merge.min_length_m must be >= 0");
  if (!(merge_angle_deg >= 0 && merge_angle_deg < 90)) {
    return Invalid(error, "mapping.split_merge.merge_angle_deg must lie in [0, 90)");
  }
  return true;
}

OptionTable<SplitAndMergeOptions> SplitAndMergeOptions::Describe() {
  using O = SplitAndMergeOptions;
  return OptionTable<O>("mapping.split_merge")
      .Double("error_threshold_cells", &O::error_threshold_cells, "cells", 0.1, 100, 0.5,
              "Split a piece while a point lies farther than this from its chord; merge pieces "
              "that fit one line within it (cells, like RANSAC's err_max).")
      .Double("max_gap_m", &O::max_gap_m, "m", 0.01, 10, 0.05,
              "Consecutive scan points farther apart than this start a new run.")
      .Int("min_line_points", &O::min_line_points, "points", 2, 10000, 1,
           "Lines with fewer points are dropped.")
      .Double("min_length_m", &O::min_length_m, "m", 0, 10, 0.05, "Shorter lines are dropped.")
      .Double("merge_angle_deg", &O::merge_angle_deg, "deg", 0, 45, 0.5,
              "Collinear lines (angles this close, one fit within the threshold) are merged.");
}

namespace {

// Largest distance of points[indices] to the total least-squares line through them.
double MaxFitError(const std::vector<Eigen::Vector2d>& points, const std::vector<int>& indices) {
  Eigen::Vector2d normal;
  double offset = 0;
  if (!FitLineTotalLeastSquares(points, indices, &normal, &offset)) return 0;
  double worst = 0;
  for (int i : indices) worst = std::max(worst, std::abs(normal.dot(points[i]) - offset));
  return worst;
}

std::vector<int> Range(int begin, int end) {
  std::vector<int> r;
  for (int i = begin; i < end; ++i) r.push_back(i);
  return r;
}

}  // namespace

SplitAndMerge::SplitAndMerge(SplitAndMergeOptions options) : options_(std::move(options)) {}

StatusOr<LineExtraction> SplitAndMerge::Extract(const PolarScan& scan) {
  std::vector<Eigen::Vector2d> points(scan.points.size());
  for (size_t i = 0; i < scan.points.size(); ++i) points[i] = scan.points[i].xy;
  return ExtractPoints(points, scan.cell_size_m);
}

void SplitAndMerge::Split(const std::vector<Eigen::Vector2d>& points, int begin, int end,
                          double threshold, int* splits) {
  // Iterative end-point fit with an explicit stack.
  std::vector<std::pair<int, int>> stack = {{begin, end}};
  while (!stack.empty()) {
    const auto [b, e] = stack.back();
    stack.pop_back();
    if (e - b <= 2) {
      pieces_.emplace_back(b, e);
      continue;
    }
    const Eigen::Vector2d chord = points[e - 1] - points[b];
    const double length = chord.norm();
    double worst = -1;
    int worst_index = -1;
    for (int i = b + 1; i < e - 1; ++i) {
      const Eigen::Vector2d q = points[i] - points[b];
      const double dist =
          length > 1e-12 ? std::abs(chord.x() * q.y() - chord.y() * q.x()) / length : q.norm();
      if (dist > worst) {
        worst = dist;
        worst_index = i;
      }
    }
    if (worst <= threshold) {
      pieces_.emplace_back(b, e);
      continue;
    }
    ++*splits;
    // Depth-first, left piece first (pushed last).
    stack.emplace_back(worst_index, e);
    stack.emplace_back(b, worst_index);
  }
}

StatusOr<LineExtraction> SplitAndMerge::ExtractPoints(const std::vector<Eigen::Vector2d>& points,
                                                      double cell_size_m) {
  std::string error;
  if (!options_.IsValid(&error)) return InvalidArgument(error);
  if (!(cell_size_m > 0)) return InvalidArgument("split-and-merge: cell size must be positive");
  const double threshold = options_.error_threshold_cells * cell_size_m;
  const int n = static_cast<int>(points.size());
  LineExtraction result;
  result.points = n;
  result.point_line.assign(n, -1);

  // Runs separated by gaps, each split recursively.
  pieces_.clear();
  int splits = 0;
  int run_begin = 0;
  for (int i = 1; i <= n; ++i) {
    if (i == n || (points[i] - points[i - 1]).norm() > options_.max_gap_m) {
      if (i - run_begin >= 2) Split(points, run_begin, i, threshold, &splits);
      run_begin = i;
    }
  }
  std::sort(pieces_.begin(), pieces_.end());
  // Merge neighbouring pieces that fit one line.
  bool merged = true;
  while (merged) {
    merged = false;
    for (size_t k = 0; k + 1 < pieces_.size(); ++k) {
      if (pieces_[k].second != pieces_[k + 1].first) continue;  // Different runs.
      if (MaxFitError(points, Range(pieces_[k].first, pieces_[k + 1].second)) <= threshold) {
        pieces_[k].second = pieces_[k + 1].second;
        pieces_.erase(pieces_.begin() + k + 1);
        merged = true;
        break;
      }
    }
  }
  // Lines from pieces, then merge collinear lines (a wall interrupted by a door or a person).
  std::vector<std::vector<int>> sets;
  for (const auto& [b, e] : pieces_) {
    if (e - b >= 2) sets.push_back(Range(b, e));
  }
  const double merge_angle = DegToRad(options_.merge_angle_deg);
  auto angle_of = [&](const std::vector<int>& set) {
    Eigen::Vector2d normal;
    double offset = 0;
    FitLineTotalLeastSquares(points, set, &normal, &offset);
    return std::atan2(normal.y(), normal.x());
  };
  merged = true;
  while (merged) {
    merged = false;
    for (size_t a = 0; a < sets.size() && !merged; ++a) {
      if (static_cast<int>(sets[a].size()) < options_.min_line_points) continue;
      for (size_t b = a + 1; b < sets.size() && !merged; ++b) {
        if (static_cast<int>(sets[b].size()) < options_.min_line_points) continue;
        if (std::abs(WrapHalfTurn(angle_of(sets[a]) - angle_of(sets[b]))) > merge_angle) continue;
        std::vector<int> both = sets[a];
        both.insert(both.end(), sets[b].begin(), sets[b].end());
        if (MaxFitError(points, both) > threshold) continue;
        sets[a] = std::move(both);
        sets.erase(sets.begin() + b);
        merged = true;
      }
    }
  }
  for (const std::vector<int>& set : sets) {
    if (static_cast<int>(set.size()) < options_.min_line_points) continue;
    Eigen::Vector2d normal;
    double offset = 0;
    if (!FitLineTotalLeastSquares(points, set, &normal, &offset)) continue;
    WallSegment line = MakeWallSegment(normal, offset, points, set);
    if (line.length_m < options_.min_length_m) continue;
    const int index = static_cast<int>(result.lines.size());
    for (int i : set) result.point_line[i] = index;
    result.assigned += static_cast<int>(set.size());
    result.lines.push_back(line);
  }
  result.iterations = splits;
  char text[96];
  std::snprintf(text, sizeof(text), "%d splits, %zu pieces, %zu lines kept", splits, pieces_.size(),
                result.lines.size());
  result.stop_reason = text;
  return result;
}

}  // namespace sightline
