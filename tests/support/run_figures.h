// The figures of a headless run that do not depend on the host's speed (accuracy, counts but
// the wall time and frame rate, the frame count), for comparing two runs of one pipeline.
// Header-only: the test targets that include it link the pipelines themselves.
#pragma once

#include <map>
#include <string>

#include "core/pipeline/pipeline_registry.h"

namespace sightline::testing {

inline std::map<std::string, double> RunFigures(const RunReport& report) {
  std::map<std::string, double> figures;
  for (const auto& [key, value] : report.result.accuracy) figures["accuracy/" + key] = value;
  for (const auto& [key, value] : report.result.counts) {
    if (key != "wall_time_s" && key != "frames_per_second") figures["counts/" + key] = value;
  }
  figures["frames"] = double(report.result.frames);
  return figures;
}

}  // namespace sightline::testing
