// Reads a trajectory file in TUM or KITTI format, or whichever of the two a file holds.
#pragma once

#include <string>

#include "core/common/status.h"
#include "core/common/trajectory.h"

namespace sightline {

// The text formats of trajectory files.
enum class TrajectoryFormat {
  kAuto,   // Decided per file by the first data line: 8 numbers TUM, 12 numbers KITTI.
  kTum,    // "timestamp tx ty tz qx qy qz qw".
  kKitti,  // 12 numbers (top 3x4 of world_from_camera); times are index * 0.1 s (10 Hz).
};

// "auto", "tum", "kitti".
const char* TrajectoryFormatName(TrajectoryFormat format);
// Parses "auto", "tum" or "kitti"; the error lists the choices.
StatusOr<TrajectoryFormat> ParseTrajectoryFormat(const std::string& text);

// The format of the file's first data line. Fails, naming the file and line, for other counts.
StatusOr<TrajectoryFormat> DetectTrajectoryFormat(const std::string& path);

// Reads `path` in `format` (kAuto detects it). KITTI files get synthetic 10 Hz timestamps, so two
// KITTI files associate by time as they would by index.
StatusOr<Trajectory> ReadTrajectoryFile(const std::string& path,
                                        TrajectoryFormat format = TrajectoryFormat::kAuto);

}  // namespace sightline
