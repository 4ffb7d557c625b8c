// Multi-line RANSAC (seed 000, section 4.3.4, steps A-F), the reference wall-line extractor.
//
//   A  S = the scan points; N0 = |S|.
//   B  For one line, up to j_max hypotheses (fixed 250, or the adaptive count):
//      1 C = {}.  2 Pick two points of S whose distance lies within the pair limits (else draw
//      again).  3 The line through them.  4 C = points within err_max (5 cells) of it.
//      5 Skip unless |C| / N_i >= ratio_min (0.2).  6 Least-squares refit on C, keep the points
//      of C still within err_max (Q), sum their errors; skip unless |Q| / N_i >= ratio_min.
//      7 Keep the hypothesis with the lowest error as the best.  8 Stop early when
//      |Q| / N_i > ratio_max (0.5): that hypothesis is declared the line.
//   C  The line's end points, length and angle.
//   D  Remove its consensus set from S (N_i -= |Q|).
//   E  Stop when (N0 - N_i) / N0 > 0.8 or after i_max = 100 lines.
//   F  (The seed's text ends inside step E.) Stop when no hypothesis of a run passed step 6,
//      since the remaining points can hold no further line; else find the next line (B).
//
// Additions, each an option that can be set back to the seed's behaviour: a minimum number of
// points per line (min_line_points; 2 = seed), contiguity (max_gap_m; 0 = seed): the consensus
// set of step B6 is cut at gaps along the line and its longest piece kept, because in a real
// corridor the 5-cell band of a line through two objects (a box face and a door recess across
// the corridor, a person and a bin) collects 20 % of the points just as a wall does; the adaptive
// iteration count k = log(1 - p) / log(1 - w^2) (algorithms.md) beside the fixed count, and a final
// refinement of the chosen line (refine_sweep_deg; 0 = seed). The seed's single refit on the 5-cell
// consensus set tilts the line whenever the band holds two parallel surfaces: with 2 cm cells
// the band is 20 cm wide, and a wall with a door recessed 10 cm behind it gives lines 4-10 deg
// off. The refinement sweeps the direction in 0.1 deg steps, histograms the points' offsets in
// 1-cell bins for each direction, keeps the direction with the sharpest histogram (largest sum
// of squared counts: parallel surfaces are one sharp peak each at their true direction) and
// refits on the points of its fullest 2-bin window.
// The consensus set removed in step D is the seed's, unchanged.
#pragma once

#include <random>
#include <string>
#include <vector>

#include "core/mapping/line_extractor.h"
#include "core/options/option_table.h"

namespace sightline {

// Options of multi-line RANSAC. Keys "mapping.ransac.*".
struct MultiLineRansacOptions {
  double error_threshold_cells = 5;  // err_max_init: inlier distance in occupancy cells (seed 5
                                     // pixels); in metres it is this times the cell size.
  double min_pair_distance_m = 0.2;  // Step B2: the two seed points must be at least this far
  double max_pair_distance_m = 4.0;  // apart and at most this far [m].
  int max_pair_draws = 50;           // Draws per hypothesis before it counts as failed.
  double min_inlier_ratio = 0.2;     // ratio_min (steps B5, B6).
  double early_exit_ratio = 0.5;     // ratio_max (step B8).
  std::string iterations = "fixed";  // "fixed": j_max hypotheses; "adaptive": log(1-p)/log(1-w^2).
  int max_iterations = 250;          // j_max (also caps the adaptive count).
  double confidence = 0.99;          // p of the adaptive count.
  std::string best_by = "total_error";  // Step B7: "total_error" (seed: sum of errors) or
                                        // "mean_error".
  double stop_assigned_ratio = 0.8;     // ratio_scan_max (step E).
  int max_lines = 100;                  // i_max (step E).
  int min_line_points = 8;              // A line needs this many points (2 = seed).
  double max_gap_m = 0.5;               // Step B6: the re-tested consensus set is cut at gaps wider
                                        // than this along the line and its longest piece kept
                                        // (0 = as published: no cut) [m].
  double refine_sweep_deg = 6;          // Step C: the chosen line's dominant surface is re-found
                                        // by sweeping its direction this far either way, then
                                        // refitted (0 = seed: no refinement) [deg].
  double refine_threshold_cells = 1.0;  // Band of the refinement [cells].
  int seed = 1;                         // Random generator seed.

  bool IsValid(std::string* error) const;
  static OptionTable<MultiLineRansacOptions> Describe();
};

// The adaptive RANSAC hypothesis count for a 2-point model: the number k with
// 1 - (1 - w^2)^k >= confidence, i.e. ceil(log(1 - p) / log(1 - w^2)). 1 when w >= 1.
int AdaptiveIterationCount(double confidence, double inlier_ratio);

// Multi-line RANSAC (see the file comment).
//
//   MultiLineRansac ransac(options);
//   StatusOr<LineExtraction> lines = ransac.Extract(scan);
class MultiLineRansac : public LineExtractor {
 public:
  explicit MultiLineRansac(MultiLineRansacOptions options = {});

  const char* name() const override { return "multi_line_ransac"; }
  StatusOr<LineExtraction> Extract(const PolarScan& scan) override;
  // The same on bare points (base frame, metres), with the cell size that scales the threshold.
  StatusOr<LineExtraction> ExtractPoints(const std::vector<Eigen::Vector2d>& points,
                                         double cell_size_m);

  const MultiLineRansacOptions& options() const { return options_; }

 private:
  // Step C's refinement of the line (normal, offset) of best_set_.
  void RefineLine(const std::vector<Eigen::Vector2d>& points, double cell_size_m,
                  Eigen::Vector2d* normal, double* offset);

  MultiLineRansacOptions options_;
  std::mt19937 rng_;
  // Scratch buffers kept between calls.
  std::vector<Eigen::Vector2d> points_;
  std::vector<int> remaining_, consensus_, refit_, best_set_, current_set_;
  std::vector<int> histogram_;
};

}  // namespace sightline
