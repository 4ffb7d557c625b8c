// The mobility pipeline's messages: the scored cloud and the top-view score grid.
#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>

#include "core/ros/ros_publish.h"

namespace sightline {

namespace {

sensor_msgs::PointField Field(const std::string& name, uint32_t offset, uint8_t datatype) {
  sensor_msgs::PointField field;
  field.name = name;
  field.offset = offset;
  field.datatype = datatype;
  field.count = 1;
  return field;
}

}  // namespace

sensor_msgs::PointCloud2 MobilityCloudMessage(const MobilityResult& result,
                                              const RosFrames& frames) {
  using sensor_msgs::PointField;
  sensor_msgs::PointCloud2 out;
  out.header.stamp = RosTimeFromSeconds(result.stamp.sensor_time_s);
  out.header.frame_id = frames.camera;
  out.height = 1;
  out.width = static_cast<uint32_t>(result.points.size());
  out.fields = {
      Field("x", 0, PointField::FLOAT32),          Field("y", 4, PointField::FLOAT32),
      Field("z", 8, PointField::FLOAT32),          Field("score_rule", 12, PointField::FLOAT32),
      Field("score_gpr", 16, PointField::FLOAT32), Field("segment", 20, PointField::INT32)};
  out.is_bigendian = false;
  out.point_step = 24;
  out.row_step = out.point_step * out.width;
  out.is_dense = false;  // Unsegmented points have NaN scores.
  out.data.resize(out.row_step);
  const float nan = std::numeric_limits<float>::quiet_NaN();
  for (size_t i = 0; i < result.points.size(); ++i) {
    const int s = i < result.segment.size() ? result.segment[i] : -1;
    const bool scored = s >= 0 && s < static_cast<int>(result.segments.size());
    const float values[5] = {result.points[i].x(), result.points[i].y(), result.points[i].z(),
                             scored ? static_cast<float>(result.segments[s].score_rule) : nan,
                             scored ? static_cast<float>(result.segments[s].score_gpr) : nan};
    const int32_t segment = scored ? s : -1;
    std::memcpy(&out.data[i * 24], values, sizeof(values));
    std::memcpy(&out.data[i * 24 + 20], &segment, sizeof(segment));
  }
  return out;
}

nav_msgs::OccupancyGrid MobilityGridMessage(const MobilityResult& result, const RosFrames& frames) {
  const TopViewMap& map = result.map;
  nav_msgs::OccupancyGrid out;
  out.header.stamp = RosTimeFromSeconds(result.stamp.sensor_time_s);
  out.header.frame_id = frames.ground;
  out.info.map_load_time = out.header.stamp;
  out.info.resolution = static_cast<float>(map.cell_m);
  // Grid column i walks x forward (the map's rows bottom-up), grid row j walks y left (the
  // map's columns right to left).
  const int rows = map.score.rows, cols = map.score.cols;
  out.info.width = static_cast<uint32_t>(rows);
  out.info.height = static_cast<uint32_t>(cols);
  out.info.origin.position.x = map.x_max_m - rows * map.cell_m;
  out.info.origin.position.y = map.y_max_m - cols * map.cell_m;
  out.info.origin.orientation.w = 1;
  out.data.assign(static_cast<size_t>(rows) * cols, -1);
  if (map.score.type() != CV_32FC1) return out;
  for (int r = 0; r < rows; ++r) {
    const float* score = map.score.ptr<float>(r);
    for (int c = 0; c < cols; ++c) {
      if (std::isnan(score[c])) continue;
      const int i = rows - 1 - r, j = cols - 1 - c;
      const double cost = 100.0 * (1.0 - std::clamp(static_cast<double>(score[c]), 0.0, 1.0));
      out.data[static_cast<size_t>(j) * rows + i] = static_cast<int8_t>(std::lround(cost));
    }
  }
  return out;
}

}  // namespace sightline
