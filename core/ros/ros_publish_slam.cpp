// The SLAM pipelines' map messages (mono-slam's and the button's map snapshot).
#include "core/ros/ros_publish.h"

namespace sightline {

sensor_msgs::PointCloud2 MapPointsMessage(const MapSnapshot& map, double stamp_s,
                                          const std::string& frame_id) {
  std::vector<Eigen::Vector3d> points;
  points.reserve(map.points.size());
  for (const MapSnapshot::Point& p : map.points) points.push_back(p.position);
  return PointCloudMessage(points, stamp_s, frame_id);
}

visualization_msgs::MarkerArray PoseArrowMarkers(const std::vector<IdentifiedPose>& poses,
                                                 double stamp_s, const std::string& frame_id) {
  visualization_msgs::MarkerArray out;
  visualization_msgs::Marker marker;
  marker.header.frame_id = frame_id;
  marker.header.stamp = RosTimeFromSeconds(stamp_s);
  marker.action = visualization_msgs::Marker::DELETEALL;
  out.markers.push_back(marker);
  marker.action = visualization_msgs::Marker::ADD;
  marker.ns = "keyframes";
  marker.type = visualization_msgs::Marker::ARROW;
  marker.scale.x = 0.01;  // Shaft and head diameters; the arrow spans the two points.
  marker.scale.y = 0.02;
  marker.color.r = 0.2f;
  marker.color.g = 0.6f;
  marker.color.b = 1.0f;
  marker.color.a = 1;
  marker.pose.orientation.w = 1;
  for (const IdentifiedPose& pose : poses) {
    marker.id = static_cast<int>(pose.id);
    const Eigen::Vector3d from = pose.frame_from_camera.translation();
    const Eigen::Vector3d to = pose.frame_from_camera * Eigen::Vector3d(0, 0, 0.1);
    marker.points.resize(2);
    marker.points[0].x = from.x();
    marker.points[0].y = from.y();
    marker.points[0].z = from.z();
    marker.points[1].x = to.x();
    marker.points[1].y = to.y();
    marker.points[1].z = to.z();
    out.markers.push_back(marker);
  }
  return out;
}

visualization_msgs::MarkerArray KeyframeMarkers(const MapSnapshot& map, double stamp_s,
                                                const std::string& frame_id) {
  std::vector<IdentifiedPose> poses;
  poses.reserve(map.keyframes.size());
  for (const MapSnapshot::Frame& keyframe : map.keyframes) {
    poses.push_back({keyframe.id, keyframe.map_from_camera});
  }
  return PoseArrowMarkers(poses, stamp_s, frame_id);
}

sensor_msgs::PointCloud2 StereoPointsMessage(const StereoOdometryResult& odometry,
                                             const RectifiedStereoCamera& camera,
                                             const std::string& frame_id) {
  std::vector<Eigen::Vector3d> points;
  points.reserve(odometry.features.size());
  for (const TrackedFeature& f : odometry.features) {
    const double disparity = f.left.x - f.right.x;
    if (f.role != FeatureRole::kInlier || !(disparity > 0) || !(camera.f > 0)) continue;
    points.push_back(odometry.world_from_camera *
                     camera.Triangulate(f.left.x, f.left.y, disparity));
  }
  return PointCloudMessage(points, odometry.stamp.sensor_time_s, frame_id);
}

}  // namespace sightline
