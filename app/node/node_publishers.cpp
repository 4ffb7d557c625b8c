// The topics of each pipeline (README "ROS node" lists them).
#include "app/node/node_publishers.h"

#include <diagnostic_msgs/DiagnosticArray.h>
#include <tf2_ros/transform_broadcaster.h>

#include <cmath>

#include "core/pipeline/mobility_result.h"
#include "core/pipeline/mono_slam_result.h"
#include "core/pipeline/stereo_vo_result.h"

namespace sightline::node {

namespace {

// Diagnostics for every pipeline; the pipeline's own topics in PublishTyped.
class BasePublisher : public ResultPublisher {
 public:
  BasePublisher(const std::string& pipeline, const StatisticTable& table, ros::NodeHandle& nh,
                const RosFrames& frames)
      : pipeline_(pipeline), table_(table), frames_(frames) {
    diagnostics_ = nh.advertise<diagnostic_msgs::DiagnosticArray>("diagnostics", 10);
  }
  void Publish(const PipelineResult& result) override {
    diagnostics_.publish(DiagnosticsMessage(pipeline_, table_, result));
    PublishTyped(result);
  }

 protected:
  virtual void PublishTyped(const PipelineResult& result) {}
  const RosFrames& frames() const { return frames_; }
  tf2_ros::TransformBroadcaster& tf() { return tf_; }

 private:
  std::string pipeline_;
  StatisticTable table_;
  RosFrames frames_;
  ros::Publisher diagnostics_;
  tf2_ros::TransformBroadcaster tf_;
};

class MappingPublisher : public BasePublisher {
 public:
  MappingPublisher(const StatisticTable& table, ros::NodeHandle& nh, const RosFrames& frames)
      : BasePublisher("mapping", table, nh, frames) {
    map_ = nh.advertise<nav_msgs::OccupancyGrid>("map", 1, /*latch=*/true);
    scan_ = nh.advertise<sensor_msgs::LaserScan>("scan", 10);
    walls_ = nh.advertise<visualization_msgs::MarkerArray>("walls", 10);
    odom_ = nh.advertise<nav_msgs::Odometry>("odom", 10);
  }

 protected:
  void PublishTyped(const PipelineResult& base) override {
    const auto* result = dynamic_cast<const MappingResult*>(&base);
    if (result == nullptr || !result->mapping) return;
    tf().sendTransform(MappingTransforms(*result, frames()));
    if (auto grid = MappingGridMessage(*result, frames())) map_.publish(*grid);
    if (auto scan = MappingScanMessage(*result, frames())) scan_.publish(*scan);
    walls_.publish(MappingWallMarkers(*result, frames()));
    // The estimate as odometry too (base in odom), for subscribers without tf.
    odom_.publish(OdometryMessage(result->mapping->pose.ToIsometry(), result->stamp.sensor_time_s,
                                  frames().odom, frames().base));
  }

 private:
  ros::Publisher map_, scan_, walls_, odom_;
};

// stereo-vo: odometry + tf, the frame's triangulated inliers, and a keyframe arrow every
// kKeyframeStepM travelled or kKeyframeTurnRad turned (for viewers; the estimator has none).
class StereoVoPublisher : public BasePublisher {
 public:
  static constexpr double kKeyframeStepM = 0.5;
  static constexpr double kKeyframeTurnRad = 15 * M_PI / 180;

  StereoVoPublisher(const StatisticTable& table, ros::NodeHandle& nh, const RosFrames& frames)
      : BasePublisher("stereo-vo", table, nh, frames) {
    odom_ = nh.advertise<nav_msgs::Odometry>("odom", 10);
    points_ = nh.advertise<sensor_msgs::PointCloud2>("map_points", 2);
    keyframes_ = nh.advertise<visualization_msgs::MarkerArray>("keyframes", 1, /*latch=*/true);
  }

 protected:
  void PublishTyped(const PipelineResult& base) override {
    const auto* result = dynamic_cast<const StereoVoResult*>(&base);
    if (result == nullptr || !result->odometry) return;
    const double t = result->stamp.sensor_time_s;
    const Eigen::Isometry3d& pose = result->odometry->world_from_camera;
    odom_.publish(OdometryMessage(pose, t, frames().odom, frames().camera));
    tf().sendTransform(TransformMessage(pose, t, frames().odom, frames().camera));
    points_.publish(StereoPointsMessage(*result->odometry, result->camera, frames().odom));
    const bool first = keyframes_so_far_.empty();
    const Eigen::Isometry3d step =
        first ? Eigen::Isometry3d::Identity()
              : keyframes_so_far_.back().frame_from_camera.inverse() * pose;
    if (first || step.translation().norm() >= kKeyframeStepM ||
        Eigen::AngleAxisd(step.rotation()).angle() >= kKeyframeTurnRad) {
      keyframes_so_far_.push_back({result->stamp.sequence_id, pose});
      keyframes_.publish(PoseArrowMarkers(keyframes_so_far_, t, frames().odom));
    }
  }

 private:
  ros::Publisher odom_, points_, keyframes_;
  std::vector<IdentifiedPose> keyframes_so_far_;
};

// mono-slam; the button pipeline's SLAM part too (its result derives from mono-slam's).
class MonoSlamPublisher : public BasePublisher {
 public:
  MonoSlamPublisher(const std::string& pipeline, const StatisticTable& table, ros::NodeHandle& nh,
                    const RosFrames& frames)
      : BasePublisher(pipeline, table, nh, frames) {
    odom_ = nh.advertise<nav_msgs::Odometry>("odom", 10);
    points_ = nh.advertise<sensor_msgs::PointCloud2>("map_points", 1, /*latch=*/true);
    keyframes_ = nh.advertise<visualization_msgs::MarkerArray>("keyframes", 1, /*latch=*/true);
  }

 protected:
  void PublishTyped(const PipelineResult& base) override {
    const auto* result = dynamic_cast<const MonoSlamFrameResult*>(&base);
    if (result == nullptr || !result->slam) return;
    const MonoSlamResult& slam = *result->slam;
    const double t = result->stamp.sensor_time_s;
    if (slam.tracked) {
      odom_.publish(OdometryMessage(slam.map_from_camera, t, frames().map, frames().camera));
      tf().sendTransform(TransformMessage(slam.map_from_camera, t, frames().map, frames().camera));
    }
    // The map snapshot is shared until it changes: publish it when it did.
    if (slam.map && slam.map != last_map_) {
      last_map_ = slam.map;
      points_.publish(MapPointsMessage(*slam.map, t, frames().map));
      keyframes_.publish(KeyframeMarkers(*slam.map, t, frames().map));
    }
  }

 private:
  ros::Publisher odom_, points_, keyframes_;
  std::shared_ptr<const MapSnapshot> last_map_;
};

class MobilityPublisher : public BasePublisher {
 public:
  MobilityPublisher(const StatisticTable& table, ros::NodeHandle& nh, const RosFrames& frames)
      : BasePublisher("mobility", table, nh, frames) {
    cloud_ = nh.advertise<sensor_msgs::PointCloud2>("mobility_cloud", 2);
    grid_ = nh.advertise<nav_msgs::OccupancyGrid>("mobility_grid", 2);
  }

 protected:
  void PublishTyped(const PipelineResult& base) override {
    const auto* result = dynamic_cast<const MobilityFrameResult*>(&base);
    if (result == nullptr || !result->mobility) return;
    const MobilityResult& mobility = *result->mobility;
    tf().sendTransform(TransformMessage(mobility.map.ground_from_camera,
                                        result->stamp.sensor_time_s, frames().ground,
                                        frames().camera));
    cloud_.publish(MobilityCloudMessage(mobility, frames()));
    grid_.publish(MobilityGridMessage(mobility, frames()));
  }

 private:
  ros::Publisher cloud_, grid_;
};

}  // namespace

std::unique_ptr<ResultPublisher> MakeSlamPublisher(const std::string& pipeline,
                                                   const StatisticTable& table, ros::NodeHandle& nh,
                                                   const RosFrames& frames) {
  return std::make_unique<MonoSlamPublisher>(pipeline, table, nh, frames);
}

std::unique_ptr<ResultPublisher> MakeResultPublisher(const std::string& pipeline,
                                                     const StatisticTable& table,
                                                     ros::NodeHandle& nh, const RosFrames& frames) {
  if (pipeline == "mapping") return std::make_unique<MappingPublisher>(table, nh, frames);
  if (pipeline == "stereo-vo") return std::make_unique<StereoVoPublisher>(table, nh, frames);
  if (pipeline == "mono-slam") return MakeSlamPublisher(pipeline, table, nh, frames);
  if (pipeline == "mobility") return std::make_unique<MobilityPublisher>(table, nh, frames);
  return std::make_unique<BasePublisher>(pipeline, table, nh, frames);
}

}  // namespace sightline::node
