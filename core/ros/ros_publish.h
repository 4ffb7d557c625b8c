// ROS 1 messages built from the pipelines' typed results: pure functions (no master, no node
// handle), so that sightline-node publishes them and tests check them against the results.
// Every message is stamped with the frame's sensor time (data time, as the pipelines decide).
// Only core/ros and the ROS front ends include this header (it pulls ROS's message headers; its
// translation units are C++17).
#pragma once

#include <diagnostic_msgs/DiagnosticArray.h>
#include <geometry_msgs/PoseStamped.h>
#include <geometry_msgs/TransformStamped.h>
#include <nav_msgs/OccupancyGrid.h>
#include <nav_msgs/Odometry.h>
#include <sensor_msgs/LaserScan.h>
#include <sensor_msgs/PointCloud2.h>
#include <visualization_msgs/MarkerArray.h>

#include <Eigen/Geometry>
#include <opencv2/core.hpp>
#include <optional>
#include <string>
#include <vector>

#include "core/button/arm_protocol.h"
#include "core/mobility/mobility_types.h"
#include "core/mono/slam_map.h"
#include "core/pipeline/button_result.h"
#include "core/pipeline/mapping_result.h"
#include "core/pipeline/pipeline.h"
#include "core/ros/ros_geometry.h"
#include "core/ros/ros_image.h"
#include "core/stereo/stereo_geometry.h"
#include "core/stereo/stereo_types.h"

namespace sightline {

// The tf frame names the node publishes (REP 105 names for the robot frames).
struct RosFrames {
  std::string map = "map";         // World frame of the mapping / SLAM estimate.
  std::string odom = "odom";       // Continuous odometry frame.
  std::string base = "base_link";  // Robot on the floor (mapping): x forward, y left, z up.
  std::string camera = "camera";   // The camera's optical frame: x right, y down, z forward.
  std::string ground = "mobility_ground";  // Mobility's ground frame: x forward, y left, z up.
};

// --- Common pieces (stamps: RosTimeFromSeconds, ros_image.h; poses: ros_geometry.h) ---

// Points as a PointCloud2 with float32 fields x y z (dense, little-endian).
sensor_msgs::PointCloud2 PointCloudMessage(const std::vector<Eigen::Vector3d>& points,
                                           double stamp_s, const std::string& frame_id);
// A map_server image (0 occupied ... 254 free, 205 unknown; row 0 the top, i.e. the largest y)
// as an OccupancyGrid with map_server's trinary rule: p = (255 - v) / 255; p > occupied_thresh
// -> 100, p < free_thresh -> 0, else -1. `origin` is the world position of the lower-left cell.
nav_msgs::OccupancyGrid OccupancyGridFromMapImage(const cv::Mat& gray, double resolution_m,
                                                  const Eigen::Vector2d& origin,
                                                  double occupied_thresh, double free_thresh,
                                                  double stamp_s, const std::string& frame_id);
// The frame's statistics as one DiagnosticStatus per pipeline ("sightline/<pipeline>": level OK,
// or WARN with the frame's status message) with one key per statistic ("mapping/lines_ms" ->
// "mapping/lines_ms [ms]") and one status "sightline/<pipeline>/timing" holding the "ms" ones.
diagnostic_msgs::DiagnosticArray DiagnosticsMessage(const std::string& pipeline,
                                                    const StatisticTable& table,
                                                    const PipelineResult& result);

// --- mapping ---

// The global map of this frame as an OccupancyGrid in frames.map; nullopt when the frame carries
// no map (mapping.stitch.render_every_n: the node sets it to 1 unless given).
std::optional<nav_msgs::OccupancyGrid> MappingGridMessage(const MappingResult& result,
                                                          const RosFrames& frames);
// The polar scan as a LaserScan in frames.base: one range per ray from fov_min (the rightmost
// ray) counter-clockwise; rays without a hit are +inf (REP 117). Nullopt without a mapping.
std::optional<sensor_msgs::LaserScan> MappingScanMessage(const MappingResult& result,
                                                         const RosFrames& frames);
// The wall lines as one LINE_LIST marker in frames.base (coloured by Manhattan direction class)
// after a DELETEALL marker.
visualization_msgs::MarkerArray MappingWallMarkers(const MappingResult& result,
                                                   const RosFrames& frames);
// map -> odom (identity: the estimate is the only pose), odom -> base (the estimate) and base
// -> camera (the floor calibration). Empty without a mapping.
std::vector<geometry_msgs::TransformStamped> MappingTransforms(const MappingResult& result,
                                                               const RosFrames& frames);

// --- stereo-vo and mono-slam ---

// The map points of a SLAM map snapshot in `frame_id`.
sensor_msgs::PointCloud2 MapPointsMessage(const MapSnapshot& map, double stamp_s,
                                          const std::string& frame_id);
// A camera pose with the id its marker takes.
struct IdentifiedPose {
  int64_t id = 0;
  Eigen::Isometry3d frame_from_camera = Eigen::Isometry3d::Identity();
};
// One ARROW marker per pose (its camera's z axis, 10 cm), after a DELETEALL marker, so that the
// array replaces what an earlier one showed.
visualization_msgs::MarkerArray PoseArrowMarkers(const std::vector<IdentifiedPose>& poses,
                                                 double stamp_s, const std::string& frame_id);
// The keyframes of a SLAM map snapshot as PoseArrowMarkers.
visualization_msgs::MarkerArray KeyframeMarkers(const MapSnapshot& map, double stamp_s,
                                                const std::string& frame_id);
// stereo-vo: the frame's inlier features triangulated with the rectified `camera` and placed
// by the frame's pose (world_from_camera) in `frame_id`; stamped with the frame's time.
sensor_msgs::PointCloud2 StereoPointsMessage(const StereoOdometryResult& odometry,
                                             const RectifiedStereoCamera& camera,
                                             const std::string& frame_id);

// --- mobility ---

// The scored cloud in frames.camera with float32 fields x y z score_rule score_gpr and int32
// segment (-1 unsegmented; the scores are NaN there).
sensor_msgs::PointCloud2 MobilityCloudMessage(const MobilityResult& result,
                                              const RosFrames& frames);
// The top-view score map as an OccupancyGrid in frames.ground: cost = round(100 * (1 - score)),
// -1 where unknown; grid x forward, y left.
nav_msgs::OccupancyGrid MobilityGridMessage(const MobilityResult& result, const RosFrames& frames);

// --- button ---

// A gated target as a pose in its frame (target.frame_id, the arm base): the button centre as
// position, and as orientation the rotation that turns the x axis onto the push direction
// (`approach`), stamped with the image's time.
geometry_msgs::PoseStamped ButtonTargetMessage(const ArmTarget& target);
// The safety gate's verdict of a button frame as a DiagnosticStatus "sightline/button/gate":
// OK when it let a target out, WARN otherwise; keys reason (GateReasonKey), state, stopped,
// held, target_published; message = the verdict's message. The frame that answered a tap adds
// `tap` (TapAnswerKey) and `tap_stamp` (the tapped picture's stamp, seconds, "%.9f"), and
// with a candidate `candidate`, its outline (OutlineText), so a remote panel asks about what the
// node found, not about the spot tapped. A frame that tracks the button adds `ring`: "x,y,r",
// its centre and radius in image pixels.
diagnostic_msgs::DiagnosticStatus ButtonGateStatus(const ButtonFrameResult& result);
// The answer to the tap a frame handled: "found" (a candidate, the picker asks), "no_button",
// or the refusal's TapRefusalKey ("no_picture", "too_old", "stopped").
std::string TapAnswerKey(const ButtonFrameResult& result);
// An outline in image pixels as text: "x,y x,y ..." (integers).
std::string OutlineText(const std::vector<cv::Point>& outline);

}  // namespace sightline
