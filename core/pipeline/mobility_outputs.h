// Files of the mobility pipeline: the scored cloud (PCD or PLY, ASCII) and segments.csv rows.
#pragma once

#include <string>

#include "core/common/status.h"
#include "core/mobility/mobility_types.h"

namespace sightline {

// Writes the scored cloud: x y z, rgb (the score colour, grey = unscored), score (NaN =
// unscored) and segment (-1 = none). format "pcd" or "ply".
Status WriteScoredCloud(const MobilityResult& result, const std::string& format,
                        const std::string& path);

// The header and the rows of segments.csv for one frame.
std::string SegmentsCsvHeader();
std::string SegmentsCsvRows(int64_t frame, const MobilityResult& result);

}  // namespace sightline
