#include "core/eval/trajectory_file.h"

#include "core/common/text_file.h"

namespace sightline {

const char* TrajectoryFormatName(TrajectoryFormat format) {
  switch (format) {
    case TrajectoryFormat::kAuto:
      return "auto";
    case TrajectoryFormat::kTum:
      return "tum";
    case TrajectoryFormat::kKitti:
      return "kitti";
  }
  return "?";
}

StatusOr<TrajectoryFormat> ParseTrajectoryFormat(const std::string& text) {
  for (TrajectoryFormat f :
       {TrajectoryFormat::kAuto, TrajectoryFormat::kTum, TrajectoryFormat::kKitti}) {
    if (text == TrajectoryFormatName(f)) return f;
  }
  return InvalidArgument("unknown trajectory format '" + text + "' (expected tum, kitti or auto)");
}

StatusOr<TrajectoryFormat> DetectTrajectoryFormat(const std::string& path) {
  StatusOr<std::vector<DataLine>> lines = ReadDataLines(path);
  if (!lines.ok()) return lines.status();
  if (lines->empty()) return ParseError(path + ": no poses (the file has no data lines)");
  const DataLine& first = lines->front();
  const size_t fields = SplitFields(first.text).size();
  if (fields == 8) return TrajectoryFormat::kTum;
  if (fields == 12) return TrajectoryFormat::kKitti;
  return ParseError(path + " line " + std::to_string(first.number) + ": " + std::to_string(fields) +
                    " fields is neither TUM (8: t tx ty tz qx qy qz qw) nor KITTI (12: 3x4 pose)");
}

StatusOr<Trajectory> ReadTrajectoryFile(const std::string& path, TrajectoryFormat format) {
  if (format == TrajectoryFormat::kAuto) {
    StatusOr<TrajectoryFormat> detected = DetectTrajectoryFormat(path);
    if (!detected.ok()) return detected.status();
    format = *detected;
  }
  return format == TrajectoryFormat::kKitti ? ReadKittiTrajectory(path) : ReadTumTrajectory(path);
}

}  // namespace sightline
