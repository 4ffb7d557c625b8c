// The mapping pipeline's messages: global map, scan, wall lines and the robot's frames.
#include <algorithm>
#include <cmath>
#include <limits>

#include "core/ros/ros_publish.h"

namespace sightline {

std::optional<nav_msgs::OccupancyGrid> MappingGridMessage(const MappingResult& result,
                                                          const RosFrames& frames) {
  if (!result.mapping || !result.mapping->map_gray || result.mapping->map_gray->empty()) {
    return std::nullopt;
  }
  const MappingFrameResult& m = *result.mapping;
  return OccupancyGridFromMapImage(*m.map_gray, m.map_resolution_m, m.map_origin,
                                   m.map_occupied_threshold, m.map_free_threshold,
                                   result.stamp.sensor_time_s, frames.map);
}

std::optional<sensor_msgs::LaserScan> MappingScanMessage(const MappingResult& result,
                                                         const RosFrames& frames) {
  if (!result.mapping) return std::nullopt;
  const MappingFrameResult& m = *result.mapping;
  const PolarScan& scan = m.scan;
  sensor_msgs::LaserScan out;
  out.header.stamp = RosTimeFromSeconds(result.stamp.sensor_time_s);
  out.header.frame_id = frames.base;
  out.angle_min = static_cast<float>(scan.fov_min_rad);
  out.angle_max = static_cast<float>(scan.fov_max_rad);
  out.angle_increment = static_cast<float>(scan.resolution_rad);
  out.range_min = 0;
  // The farthest cell centre of the occupancy image from the robot.
  const double depth = m.occupancy.height() * m.occupancy.cell_size_m;
  const double half_width = 0.5 * m.occupancy.width() * m.occupancy.cell_size_m;
  out.range_max = static_cast<float>(std::hypot(depth, half_width));
  int rays = 0;
  if (scan.resolution_rad > 0) {
    rays =
        static_cast<int>(std::lround((scan.fov_max_rad - scan.fov_min_rad) / scan.resolution_rad)) +
        1;
  }
  out.ranges.assign(static_cast<size_t>(std::max(rays, 0)), std::numeric_limits<float>::infinity());
  for (const ScanPoint& point : scan.points) {
    if (point.ray >= 0 && point.ray < rays)
      out.ranges[point.ray] = static_cast<float>(point.range_m);
  }
  return out;
}

visualization_msgs::MarkerArray MappingWallMarkers(const MappingResult& result,
                                                   const RosFrames& frames) {
  visualization_msgs::MarkerArray out;
  visualization_msgs::Marker clear;
  clear.header.frame_id = frames.base;
  clear.header.stamp = RosTimeFromSeconds(result.stamp.sensor_time_s);
  clear.action = visualization_msgs::Marker::DELETEALL;
  out.markers.push_back(clear);
  if (!result.mapping) return out;
  visualization_msgs::Marker lines = clear;
  lines.action = visualization_msgs::Marker::ADD;
  lines.ns = "walls";
  lines.id = 0;
  lines.type = visualization_msgs::Marker::LINE_LIST;
  lines.pose.orientation.w = 1;
  lines.scale.x = 0.03;
  lines.color.a = 1;
  for (const WallSegment& wall : result.mapping->lines.lines) {
    std_msgs::ColorRGBA colour;
    colour.a = 1;
    colour.r = wall.direction_class == 0 ? 1.0f : 0.2f;
    colour.g = wall.direction_class == 1 ? 1.0f : 0.2f;
    colour.b = wall.direction_class < 0 ? 1.0f : 0.2f;
    for (const Eigen::Vector2d& end : {wall.start, wall.end}) {
      geometry_msgs::Point p;
      p.x = end.x();
      p.y = end.y();
      lines.points.push_back(p);
      lines.colors.push_back(colour);
    }
  }
  if (!lines.points.empty()) out.markers.push_back(lines);
  return out;
}

std::vector<geometry_msgs::TransformStamped> MappingTransforms(const MappingResult& result,
                                                               const RosFrames& frames) {
  if (!result.mapping) return {};
  const double t = result.stamp.sensor_time_s;
  return {TransformMessage(Eigen::Isometry3d::Identity(), t, frames.map, frames.odom),
          TransformMessage(result.mapping->pose.ToIsometry(), t, frames.odom, frames.base),
          TransformMessage(result.base_from_camera, t, frames.base, frames.camera)};
}

}  // namespace sightline
