// Messages shared by every pipeline's publishers: clouds, grids and diagnostics (transforms and
// odometry: ros_geometry.h).
#include <cmath>
#include <cstring>

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

sensor_msgs::PointCloud2 PointCloudMessage(const std::vector<Eigen::Vector3d>& points,
                                           double stamp_s, const std::string& frame_id) {
  sensor_msgs::PointCloud2 out;
  out.header.stamp = RosTimeFromSeconds(stamp_s);
  out.header.frame_id = frame_id;
  out.height = 1;
  out.width = static_cast<uint32_t>(points.size());
  out.fields = {Field("x", 0, sensor_msgs::PointField::FLOAT32),
                Field("y", 4, sensor_msgs::PointField::FLOAT32),
                Field("z", 8, sensor_msgs::PointField::FLOAT32)};
  out.is_bigendian = false;
  out.point_step = 12;
  out.row_step = out.point_step * out.width;
  out.is_dense = true;
  out.data.resize(out.row_step);
  for (size_t i = 0; i < points.size(); ++i) {
    const float xyz[3] = {static_cast<float>(points[i].x()), static_cast<float>(points[i].y()),
                          static_cast<float>(points[i].z())};
    std::memcpy(&out.data[i * 12], xyz, sizeof(xyz));
  }
  return out;
}

nav_msgs::OccupancyGrid OccupancyGridFromMapImage(const cv::Mat& gray, double resolution_m,
                                                  const Eigen::Vector2d& origin,
                                                  double occupied_thresh, double free_thresh,
                                                  double stamp_s, const std::string& frame_id) {
  nav_msgs::OccupancyGrid out;
  out.header.stamp = RosTimeFromSeconds(stamp_s);
  out.header.frame_id = frame_id;
  out.info.map_load_time = out.header.stamp;
  out.info.resolution = static_cast<float>(resolution_m);
  out.info.width = static_cast<uint32_t>(gray.cols);
  out.info.height = static_cast<uint32_t>(gray.rows);
  out.info.origin.position.x = origin.x();
  out.info.origin.position.y = origin.y();
  out.info.origin.orientation.w = 1;
  out.data.assign(static_cast<size_t>(gray.cols) * gray.rows, -1);
  for (int row = 0; row < gray.rows; ++row) {
    const uint8_t* in = gray.ptr<uint8_t>(row);
    // Grid row j holds world y = origin.y + j * resolution: the image's rows bottom-up.
    int8_t* cell = &out.data[static_cast<size_t>(gray.rows - 1 - row) * gray.cols];
    for (int col = 0; col < gray.cols; ++col) {
      const double p = (255.0 - in[col]) / 255.0;
      cell[col] = p > occupied_thresh ? 100 : (p < free_thresh ? 0 : -1);
    }
  }
  return out;
}

namespace {

diagnostic_msgs::KeyValue KeyValue(const std::string& key, double value) {
  diagnostic_msgs::KeyValue out;
  out.key = key;
  char text[64];
  std::snprintf(text, sizeof(text), "%.9g", value);
  out.value = text;
  return out;
}

}  // namespace

diagnostic_msgs::DiagnosticArray DiagnosticsMessage(const std::string& pipeline,
                                                    const StatisticTable& table,
                                                    const PipelineResult& result) {
  diagnostic_msgs::DiagnosticArray out;
  out.header.stamp = RosTimeFromSeconds(result.stamp.sensor_time_s);
  diagnostic_msgs::DiagnosticStatus stats;
  stats.name = "sightline/" + pipeline;
  stats.hardware_id = "sightline";
  stats.level = result.status.ok() ? diagnostic_msgs::DiagnosticStatus::OK
                                   : diagnostic_msgs::DiagnosticStatus::WARN;
  stats.message = result.status.ok() ? "ok" : result.status.ToString();
  diagnostic_msgs::DiagnosticStatus timing = stats;
  timing.name += "/timing";
  timing.level = diagnostic_msgs::DiagnosticStatus::OK;
  timing.message = "per-stage time of this frame [ms]";
  stats.values.push_back(KeyValue("frame", static_cast<double>(result.stamp.sequence_id)));
  for (const auto& [key, value] : result.stats) {
    const StatisticInfo* info = FindStatistic(table, key);
    if (info != nullptr && info->unit == "ms") {
      timing.values.push_back(KeyValue(key, value));
    } else {
      stats.values.push_back(KeyValue(key, value));
    }
  }
  out.status = {stats, timing};
  return out;
}

}  // namespace sightline
