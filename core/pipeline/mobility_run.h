// The inside of MobilityPipeline (mobility_pipeline.h): what a run's files are written from.
// Not for other users.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "core/mobility/mobility_types.h"
#include "core/pipeline/mobility_pipeline.h"
#include "core/pipeline/statistics_log.h"

namespace sightline {

// Accuracy figures gathered over the frames of a simulated terrain.
struct MobilityTerrainAccuracy {
  double slope_error_max = 0;
  std::string worst;  // Where the largest slope error was, for the log.
  int slopes = 0;
  std::vector<double> flat_roughness;
};

// Every frame of a run since it started or was reset.
struct MobilityRunRecord {
  int64_t frames = 0;
  int failed = 0;                // Frames without a (full) map.
  std::vector<std::string> log;  // One line per frame.
  std::string segments_csv;      // The rows of segments.csv.
  // Per frame: its result when its files (cloud, images) are to be written, else null.
  std::vector<std::shared_ptr<const MobilityResult>> kept;
  MobilityTerrainAccuracy terrain;
  StatisticsLog stats;

  void Add(std::shared_ptr<const MobilityResult> r, bool keep_for_files);
};

// Writes the run's files into out_dir and returns its figures (mobility_outputs.cpp).
StatusOr<RunResult> FinishMobilityRun(const MobilityRunRecord& record,
                                      const MobilityRunOptions& run, const std::string& out_dir);

}  // namespace sightline
