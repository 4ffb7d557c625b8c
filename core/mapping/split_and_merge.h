// Split-and-merge line extraction (Pavlidis and Horowitz 1974; compared on laser scans by Nguyen
// et al. 2007, who found it faster than and as correct as RANSAC): a second extractor behind the
// same interface as multi-line RANSAC, to compare.
//
// The scan's points (ordered by bearing) are cut into runs at gaps, each run is split
// recursively at the point farthest from the chord until every piece lies within the threshold,
// neighbouring pieces that fit one line are merged, then any two collinear lines are merged.
#pragma once

#include <vector>

#include "core/mapping/line_extractor.h"
#include "core/options/option_table.h"

namespace sightline {

// Options of split-and-merge. Keys "mapping.split_merge.*".
struct SplitAndMergeOptions {
  double error_threshold_cells = 5;  // Split and merge threshold, in occupancy cells (like
                                     // RANSAC's err_max).
  double max_gap_m = 0.3;            // Consecutive points farther apart start a new run [m].
  int min_line_points = 8;           // Lines with fewer points are dropped.
  double min_length_m = 0.2;         // Shorter lines are dropped [m].
  double merge_angle_deg = 3;        // Lines this close in angle may merge (with offsets within
                                     // the threshold) [deg].

  bool IsValid(std::string* error) const;
  static OptionTable<SplitAndMergeOptions> Describe();
};

// Split-and-merge (see the file comment).
class SplitAndMerge : public LineExtractor {
 public:
  explicit SplitAndMerge(SplitAndMergeOptions options = {});

  const char* name() const override { return "split_and_merge"; }
  StatusOr<LineExtraction> Extract(const PolarScan& scan) override;
  // The same on bare points ordered along the scan (base frame, metres).
  StatusOr<LineExtraction> ExtractPoints(const std::vector<Eigen::Vector2d>& points,
                                         double cell_size_m);

  const SplitAndMergeOptions& options() const { return options_; }

 private:
  void Split(const std::vector<Eigen::Vector2d>& points, int begin, int end, double threshold,
             int* splits);

  SplitAndMergeOptions options_;
  std::vector<std::pair<int, int>> pieces_;  // Scratch: [begin, end) ranges.
};

}  // namespace sightline
