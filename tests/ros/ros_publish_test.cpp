// The messages sightline-node publishes, built from real pipeline results (no master): the grid
// matches the map the run wrote, the scan its polar scan, the odometry its pose.
#include "core/ros/ros_publish.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

#include "core/pipeline/pipeline_registry.h"
#include "core/pipeline/stereo_vo_result.h"
#include "tests/ros/ros_test_util.h"

namespace sightline {
namespace {

// Runs `pipeline` through the headless loop and keeps every result.
std::vector<std::shared_ptr<const PipelineResult>> RunAndKeep(const std::string& pipeline,
                                                              const std::string& dataset,
                                                              const std::string& out,
                                                              std::vector<std::string> sets = {}) {
  std::vector<std::shared_ptr<const PipelineResult>> results;
  RunRequest request;
  request.pipeline = pipeline;
  request.dataset_path = dataset;
  request.out_dir = out;
  request.overrides = std::move(sets);
  request.on_result = [&](const std::shared_ptr<const PipelineResult>& r, int64_t) {
    results.push_back(r);
  };
  const StatusOr<RunReport> report = RunPipeline(BuiltinPipelines(), request);
  EXPECT_TRUE(report.ok()) << report.status().ToString();
  return results;
}

int8_t MapServerValue(uint8_t v, double occupied, double free) {
  const double p = (255.0 - v) / 255.0;
  return p > occupied ? 100 : (p < free ? 0 : -1);
}

TEST(RosPublish, GridFromMapImageFlipsRowsAndKeepsOrigin) {
  // Row 0 is the top (largest y): occupied, free; row 1: unknown, occupied.
  cv::Mat gray = (cv::Mat_<uint8_t>(2, 2) << 0, 254, 205, 0);
  const nav_msgs::OccupancyGrid grid =
      OccupancyGridFromMapImage(gray, 0.05, Eigen::Vector2d(-1.5, 2.25), 0.65, 0.196, 12.5, "map");
  EXPECT_EQ(grid.header.frame_id, "map");
  EXPECT_EQ(grid.header.stamp.sec, 12u);
  EXPECT_EQ(grid.header.stamp.nsec, 500000000u);
  EXPECT_FLOAT_EQ(grid.info.resolution, 0.05f);
  EXPECT_EQ(grid.info.width, 2u);
  EXPECT_EQ(grid.info.height, 2u);
  EXPECT_DOUBLE_EQ(grid.info.origin.position.x, -1.5);
  EXPECT_DOUBLE_EQ(grid.info.origin.position.y, 2.25);
  EXPECT_DOUBLE_EQ(grid.info.origin.orientation.w, 1);
  // Grid row 0 is the bottom image row.
  const std::vector<int8_t> expected = {-1, 100, 100, 0};
  EXPECT_EQ(grid.data, expected);
}

TEST(RosPublish, MappingGridAndScanMatchTheRun) {
  const std::string rec = testing::CorridorRgbd();
  ASSERT_FALSE(rec.empty());
  const std::string out = testing::TempDir("ros_publish_mapping");
  const auto results = RunAndKeep("mapping", rec, out, {"mapping.stitch.render_every_n=1"});
  ASSERT_EQ(results.size(), 30u);
  const auto* last = dynamic_cast<const MappingResult*>(results.back().get());
  ASSERT_NE(last, nullptr);
  ASSERT_TRUE(last->mapping);
  const auto grid = MappingGridMessage(*last, RosFrames());
  ASSERT_TRUE(grid.has_value());
  // The last frame's map is the map the run wrote (map_server files).
  const testing::MapServerMap files = testing::ReadMapServerMap(out);
  ASSERT_FALSE(files.gray.empty());
  ASSERT_EQ(grid->info.width, static_cast<uint32_t>(files.gray.cols));
  ASSERT_EQ(grid->info.height, static_cast<uint32_t>(files.gray.rows));
  EXPECT_NEAR(grid->info.resolution, files.resolution, 1e-6);
  EXPECT_NEAR(grid->info.origin.position.x, files.origin.x(), 1e-5);
  EXPECT_NEAR(grid->info.origin.position.y, files.origin.y(), 1e-5);
  int mismatches = 0, occupied = 0, free = 0;
  for (int row = 0; row < files.gray.rows; ++row) {
    for (int col = 0; col < files.gray.cols; ++col) {
      const int8_t want = MapServerValue(files.gray.at<uint8_t>(row, col), files.occupied_thresh,
                                         files.free_thresh);
      const int8_t got = grid->data[(files.gray.rows - 1 - row) * files.gray.cols + col];
      mismatches += want != got;
      occupied += got == 100;
      free += got == 0;
    }
  }
  EXPECT_EQ(mismatches, 0);
  EXPECT_GT(occupied, 50);  // Walls were seen ...
  EXPECT_GT(free, 500);     // ... and floor.
  EXPECT_DOUBLE_EQ(grid->header.stamp.toSec(),
                   RosTimeFromSeconds(last->stamp.sensor_time_s).toSec());

  const auto scan = MappingScanMessage(*last, RosFrames());
  ASSERT_TRUE(scan.has_value());
  EXPECT_EQ(scan->header.frame_id, "base_link");
  const PolarScan& polar = last->mapping->scan;
  ASSERT_GT(polar.points.size(), 50u);
  int finite = 0;
  for (float r : scan->ranges) finite += std::isfinite(r);
  EXPECT_EQ(finite, static_cast<int>(polar.points.size()));
  for (const ScanPoint& p : polar.points) {
    ASSERT_LT(p.ray, static_cast<int>(scan->ranges.size()));
    EXPECT_NEAR(scan->ranges[p.ray], p.range_m, 1e-5);
    EXPECT_NEAR(scan->angle_min + p.ray * scan->angle_increment, p.bearing_rad, 1e-5);
    EXPECT_LE(scan->ranges[p.ray], scan->range_max);
  }
  // tf: map -> odom -> base_link -> camera composes to the camera pose of the frame.
  const auto tf = MappingTransforms(*last, RosFrames());
  ASSERT_EQ(tf.size(), 3u);
  EXPECT_EQ(tf[1].header.frame_id, "odom");
  EXPECT_EQ(tf[1].child_frame_id, "base_link");
  EXPECT_NEAR(tf[1].transform.translation.x, last->mapping->pose.x, 1e-9);
  EXPECT_NEAR(tf[1].transform.translation.y, last->mapping->pose.y, 1e-9);
  const auto& q = tf[1].transform.rotation;
  EXPECT_NEAR(2 * std::atan2(q.z, q.w), WrapAngle(last->mapping->pose.heading_rad), 1e-9);
}

TEST(RosPublish, OdometryEqualsTheStereoPose) {
  const std::string rec = testing::CorridorStereo();
  ASSERT_FALSE(rec.empty());
  const auto results = RunAndKeep("stereo-vo", rec, testing::TempDir("ros_publish_stereo"));
  ASSERT_EQ(results.size(), 30u);
  int checked = 0;
  for (const auto& base : results) {
    const auto* r = dynamic_cast<const StereoVoResult*>(base.get());
    ASSERT_NE(r, nullptr);
    if (!r->odometry) continue;
    const Eigen::Isometry3d& pose = r->odometry->world_from_camera;
    const nav_msgs::Odometry odom = OdometryMessage(pose, r->stamp.sensor_time_s, "odom", "camera");
    const auto& p = odom.pose.pose.position;
    EXPECT_NEAR((Eigen::Vector3d(p.x, p.y, p.z) - pose.translation()).norm(), 0, 1e-12);
    const auto& o = odom.pose.pose.orientation;
    const Eigen::Matrix3d rotation = Eigen::Quaterniond(o.w, o.x, o.y, o.z).toRotationMatrix();
    EXPECT_NEAR((rotation - pose.rotation()).norm(), 0, 1e-9);
    EXPECT_NEAR(odom.header.stamp.toSec(), r->stamp.sensor_time_s, 1e-6);
    ++checked;
  }
  EXPECT_EQ(checked, 30);
  // The run moved (the corridor drive at 1 m/s for 3 s): the test compares real poses.
  const auto* last = dynamic_cast<const StereoVoResult*>(results.back().get());
  EXPECT_GT(last->odometry->world_from_camera.translation().norm(), 0.5);
}

TEST(RosPublish, MobilityCloudAndGridCarryTheScores) {
  MobilityResult m;
  m.stamp.sensor_time_s = 3.25;
  m.points = {{0.1f, 0.2f, 1.0f}, {0.3f, 0.4f, 2.0f}, {0.5f, 0.6f, 3.0f}};
  m.segment = {0, 1, -1};
  m.segments.resize(2);
  m.segments[0].score_rule = 1.0;
  m.segments[0].score_gpr = 0.9;
  m.segments[1].score_rule = 0.25;
  m.segments[1].score_gpr = 0.5;
  const sensor_msgs::PointCloud2 cloud = MobilityCloudMessage(m, RosFrames());
  ASSERT_EQ(cloud.width, 3u);
  ASSERT_EQ(cloud.fields.size(), 6u);
  EXPECT_EQ(cloud.fields[3].name, "score_rule");
  EXPECT_EQ(cloud.fields[5].name, "segment");
  for (size_t i = 0; i < 3; ++i) {
    float v[5];
    int32_t segment = 0;
    std::memcpy(v, &cloud.data[i * cloud.point_step], sizeof(v));
    std::memcpy(&segment, &cloud.data[i * cloud.point_step + 20], sizeof(segment));
    EXPECT_FLOAT_EQ(v[2], m.points[i].z());
    EXPECT_EQ(segment, m.segment[i]);
    if (m.segment[i] < 0) {
      EXPECT_TRUE(std::isnan(v[3]) && std::isnan(v[4]));
    } else {
      EXPECT_FLOAT_EQ(v[3], m.segments[m.segment[i]].score_rule);
      EXPECT_FLOAT_EQ(v[4], m.segments[m.segment[i]].score_gpr);
    }
  }
  // 2 rows (x) x 3 columns (y): row 0 farthest, column 0 leftmost.
  m.map.cell_m = 0.5;
  m.map.x_max_m = 1.0;
  m.map.y_max_m = 0.75;
  const float nan = std::numeric_limits<float>::quiet_NaN();
  m.map.score = (cv::Mat_<float>(2, 3) << 1.0f, 0.5f, nan, 0.0f, 0.25f, 1.0f);
  const nav_msgs::OccupancyGrid grid = MobilityGridMessage(m, RosFrames());
  EXPECT_EQ(grid.header.frame_id, "mobility_ground");
  EXPECT_EQ(grid.info.width, 2u);   // Along x.
  EXPECT_EQ(grid.info.height, 3u);  // Along y.
  EXPECT_DOUBLE_EQ(grid.info.origin.position.x, 0.0);
  EXPECT_DOUBLE_EQ(grid.info.origin.position.y, -0.75);
  // Cell (i, j): x = i (0 nearest), y = j (0 rightmost). Nearest row (r = 1): y right to left
  // is columns 2, 1, 0 -> scores 1.0, 0.25, 0.0 -> costs 0, 75, 100.
  EXPECT_EQ(grid.data[0 * 2 + 0], 0);
  EXPECT_EQ(grid.data[1 * 2 + 0], 75);
  EXPECT_EQ(grid.data[2 * 2 + 0], 100);
  // Farthest row (r = 0): columns 2, 1, 0 -> NaN, 0.5, 1.0 -> -1, 50, 0.
  EXPECT_EQ(grid.data[0 * 2 + 1], -1);
  EXPECT_EQ(grid.data[1 * 2 + 1], 50);
  EXPECT_EQ(grid.data[2 * 2 + 1], 0);
}

TEST(RosPublish, DiagnosticsSplitTimingFromCounts) {
  PipelineResult result;
  result.stamp.sensor_time_s = 1.5;
  result.stamp.sequence_id = 7;
  result.stats = {{"mapping/lines_ms", 2.5}, {"mapping/lines", 4}};
  result.status = InvalidArgument("no walls");
  const auto array = DiagnosticsMessage("mapping", MappingStatistics(), result);
  ASSERT_EQ(array.status.size(), 2u);
  EXPECT_EQ(array.status[0].name, "sightline/mapping");
  EXPECT_EQ(array.status[0].level, diagnostic_msgs::DiagnosticStatus::WARN);
  EXPECT_NE(array.status[0].message.find("no walls"), std::string::npos);
  ASSERT_EQ(array.status[0].values.size(), 2u);  // frame, mapping/lines.
  EXPECT_EQ(array.status[0].values[1].key, "mapping/lines");
  EXPECT_EQ(array.status[0].values[1].value, "4");
  ASSERT_EQ(array.status[1].values.size(), 1u);
  EXPECT_EQ(array.status[1].values[0].key, "mapping/lines_ms");
  EXPECT_EQ(array.status[1].values[0].value, "2.5");
}

}  // namespace
}  // namespace sightline

namespace sightline {
namespace {

TEST(RosPublish, ButtonTargetOrientationTurnsXOntoTheApproach) {
  ArmTarget target;
  target.stamp_s = 4.5;
  target.position_m = {0.8, -0.1, 0.3};
  target.approach = Eigen::Vector3d(0.2, 0.9, -0.1).normalized();
  const geometry_msgs::PoseStamped pose = ButtonTargetMessage(target);
  EXPECT_EQ(pose.header.frame_id, "arm_base");
  EXPECT_DOUBLE_EQ(pose.header.stamp.toSec(), 4.5);
  EXPECT_DOUBLE_EQ(pose.pose.position.y, -0.1);
  const auto& o = pose.pose.orientation;
  const Eigen::Vector3d x = Eigen::Quaterniond(o.w, o.x, o.y, o.z) * Eigen::Vector3d::UnitX();
  EXPECT_NEAR((x - target.approach).norm(), 0, 1e-9);
}

}  // namespace
}  // namespace sightline

namespace sightline {
namespace {

// The value of `key` in `status`, or "(absent)".
std::string ValueOf(const diagnostic_msgs::DiagnosticStatus& status, const std::string& key) {
  for (const auto& kv : status.values) {
    if (kv.key == key) return kv.value;
  }
  return "(absent)";
}

// The frame that handled a tap says how, naming the tapped picture by its stamp; other frames
// carry no answer (a remote panel must not take a later frame's silence for "no button").
TEST(RosPublish, ButtonGateCarriesTheTapAnswerOnTheFrameThatTookIt) {
  ButtonFrameResult result;
  result.stamp.sensor_time_s = 1700000013.5;
  EXPECT_EQ(ValueOf(ButtonGateStatus(result), "tap"), "(absent)");
  EXPECT_EQ(ValueOf(ButtonGateStatus(result), "tap_stamp"), "(absent)");
  result.tap_answered = true;
  result.tap_stamp_s = 1700000012.345678;
  EXPECT_EQ(ValueOf(ButtonGateStatus(result), "tap"), "found");
  const std::string stamp = ValueOf(ButtonGateStatus(result), "tap_stamp");
  EXPECT_NEAR(std::stod(stamp), 1700000012.345678, 1e-6) << stamp;
  EXPECT_EQ(ValueOf(ButtonGateStatus(result), "candidate"), "(absent)");  // None found.
  result.candidate_outline = {{10, 20}, {30, 21}, {-2, 40}};
  EXPECT_EQ(ValueOf(ButtonGateStatus(result), "candidate"), "10,20 30,21 -2,40");
  result.tap_status = NotFound("no compact outline within 35 px");
  EXPECT_EQ(ValueOf(ButtonGateStatus(result), "tap"), "no_button");
  EXPECT_EQ(ValueOf(ButtonGateStatus(result), "candidate"), "(absent)");
  const std::pair<TapRefusal, const char*> refusals[] = {{TapRefusal::kTooOld, "too_old"},
                                                         {TapRefusal::kNoPicture, "no_picture"},
                                                         {TapRefusal::kStopped, "stopped"}};
  for (const auto& [refusal, key] : refusals) {
    result.tap_status = FailedPrecondition("tap on frame 7 refused");
    result.tap_refused = refusal;
    EXPECT_EQ(ValueOf(ButtonGateStatus(result), "tap"), key);
    // The key reads back as the refusal (the remote panel words it as the local one does).
    ASSERT_TRUE(TapRefusalOfKey(key).has_value()) << key;
    EXPECT_EQ(*TapRefusalOfKey(key), refusal);
  }
  EXPECT_FALSE(TapRefusalOfKey("refused_by_a_newer_node").has_value());
}

// A frame that tracks the button says where, for a remote panel's ring; others do not.
TEST(RosPublish, ButtonGateRingsTheTrackedButtonOnly) {
  ButtonFrameResult result;
  result.picker.state = PickerState::kTracking;
  result.picker.track.found = true;
  result.picker.track.center = {321.25, 200.5};
  result.picker.track.radius_px = 9.46;
  EXPECT_EQ(ValueOf(ButtonGateStatus(result), "ring"), "321.2,200.5,9.5");
  result.picker.track.found = false;  // Lost.
  EXPECT_EQ(ValueOf(ButtonGateStatus(result), "ring"), "(absent)");
  result.picker.track.found = true;
  for (PickerState s : {PickerState::kIdle, PickerState::kConfirm, PickerState::kStopped}) {
    result.picker.state = s;
    EXPECT_EQ(ValueOf(ButtonGateStatus(result), "ring"), "(absent)") << PickerStateKey(s);
  }
}

}  // namespace
}  // namespace sightline
