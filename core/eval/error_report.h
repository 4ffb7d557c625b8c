// People- and machine-readable forms of TrajectoryErrors: the table `sightline-cli eval` prints
// and the JSON object of its --json output (the keys of the metrics.json `accuracy` block).
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "core/eval/evaluation.h"

namespace sightline {

// Unit and meaning of an accuracy figure (keys of AccuracyFigures and metrics.json's
// `accuracy`), e.g. {"m", "absolute trajectory error, RMSE"}; empty for a key it does not know.
struct AccuracyFigureInfo {
  std::string unit;
  std::string meaning;
};
AccuracyFigureInfo DescribeAccuracyFigure(const std::string& key);

// A plain-text report: pairing and alignment, one row per accuracy figure with unit and meaning,
// the KITTI errors per segment length, and notes on figures that are absent.
std::string FormatErrorTable(const TrajectoryErrors& errors);

// {"ate_rmse_m": 0.012, ..., "pairs": 50} as written into metrics.json's `accuracy` block.
std::string AccuracyToJson(const std::vector<std::pair<std::string, double>>& figures,
                           bool pretty = true);

}  // namespace sightline
