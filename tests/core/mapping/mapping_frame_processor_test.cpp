#include "core/mapping/mapping_frame_processor.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "core/mapping/pose2d.h"
#include "core/sim/simulator.h"
#include "tests/core/mapping/corridor_run.h"
#include "tests/core/mapping/synthetic_scene.h"

namespace sightline {
namespace {

using testing::FloorPlaneOf;
using testing::KinectCamera;
using testing::RenderDepth;
using testing::SyntheticView;
using testing::SyntheticWall;

class MappingFrameProcessorTest : public ::testing::Test {
 protected:
  void SetUp() override {
    camera_ = KinectCamera(320, 240);
    ASSERT_TRUE(processor_.Configure(FloorPlaneOf(SyntheticView()), camera_).ok());
  }
  // A frame of the robot at `x` in a straight corridor along world x.
  MappingInput CorridorFrame(int index, double x, double heading_deg = 0) const {
    SyntheticView view;
    view.position = Eigen::Vector2d(x, 0);
    view.heading_rad = DegToRad(heading_deg);
    MappingInput input;
    input.stamp.sequence_id = index;
    input.stamp.sensor_time_s = 0.2 * index;
    input.depth_m =
        RenderDepth(camera_, view, testing::Corridor(-5, 60, 2.0), true, 8.0, 0.001, index);
    input.odometry = Pose2d{x, 0, DegToRad(heading_deg)};
    input.people = std::vector<PersonBox>();
    return input;
  }
  PinholeCamera camera_;
  MappingFrameProcessor processor_;
};

TEST_F(MappingFrameProcessorTest, CorridorFrameGivesWallsAlongTheCorridor) {
  TimingStats timing;
  StatusOr<std::shared_ptr<const MappingFrameResult>> r =
      processor_.Process(CorridorFrame(0, 0), &timing);
  ASSERT_TRUE(r.ok()) << r.status().ToString();
  const MappingFrameResult& result = **r;
  EXPECT_EQ(result.status, "ok");
  ASSERT_GE(result.lines.lines.size(), 2u);
  for (const WallSegment& line : result.lines.lines) {
    if (line.length_m < 1.0) continue;
    EXPECT_LT(std::abs(RadToDeg(line.angle_rad)), 0.5);  // Both side walls run along x.
    EXPECT_EQ(line.direction_class, 0);
  }
  EXPECT_EQ(result.rotation.status, "reference set");
  EXPECT_GT(result.scan.points.size(), 100u);
  EXPECT_EQ(result.occupancy.width(), 400);
  for (const char* stage : {"occupancy", "scan", "lines", "rotation", "stitch"}) {
    EXPECT_EQ(timing.Summary(stage).count, 1u) << stage;
  }
  EXPECT_GE(result.times.total_ms, result.times.lines_ms);
  EXPECT_FALSE(processor_.map().empty());
  // The camera is 0.8 m above the base, looking forward.
  EXPECT_NEAR(result.world_from_camera.translation().z(), 0.8, 1e-9);
}

TEST_F(MappingFrameProcessorTest, HeadingDriftIsCorrectedAlongTheCorridor) {
  // Odometry reports a heading drifting 0.5 deg per frame; the walls keep the estimate at 0.
  for (int k = 0; k < 20; ++k) {
    MappingInput input = CorridorFrame(k, 0.2 * k);
    input.odometry->heading_rad = DegToRad(0.5 * k);
    StatusOr<std::shared_ptr<const MappingFrameResult>> r = processor_.Process(input);
    ASSERT_TRUE(r.ok());
    EXPECT_LT(std::abs(RadToDeg((*r)->pose.heading_rad)), 0.3) << "frame " << k;
  }
  EXPECT_EQ(processor_.trajectory().size(), 20u);
  EXPECT_TRUE(processor_.reset_log().empty());
}

TEST_F(MappingFrameProcessorTest, DegenerateInputGivesAClearStatusAndNoResetStorm) {
  const cv::Mat nan_depth(240, 320, CV_32FC1, cv::Scalar(std::nanf("")));
  SyntheticView up;
  up.pitch_down_rad = DegToRad(-25);  // Looking up at a wall: no floor in view.
  const cv::Mat no_floor = RenderDepth(camera_, up, {{{1.2, -3}, {1.2, 3}, 3.0}}, true);
  // A person right in front of the camera, filling the view.
  const cv::Mat person_depth =
      RenderDepth(camera_, SyntheticView(), {{{0.7, -2}, {0.7, 2}, 2.0}}, true);
  PersonBox everywhere;
  everywhere.box = cv::Rect2d(0, 0, 320, 240);
  everywhere.image_size = cv::Size(320, 240);
  // A single wall across the view, 2.5 m ahead.
  const cv::Mat single_wall =
      RenderDepth(camera_, SyntheticView(), {{{2.5, -4}, {2.5, 4}, 2.0}}, true);

  struct Case {
    cv::Mat depth;
    bool person;
    const char* status;
  };
  const Case cases[] = {{cv::Mat(), false, "no depth"},
                        {nan_depth, false, "no valid depth"},
                        {no_floor, false, "no floor visible"},
                        {person_depth, true, "view blocked by people"},
                        {single_wall, false, "ok"}};
  int frame = 0;
  for (int round = 0; round < 40; ++round) {
    for (const Case& c : cases) {
      MappingInput input;
      input.stamp.sequence_id = frame;
      input.depth_m = c.depth;
      input.odometry = Pose2d{0.01 * frame, 0, 0};
      input.people = c.person ? std::vector<PersonBox>{everywhere} : std::vector<PersonBox>();
      StatusOr<std::shared_ptr<const MappingFrameResult>> r = processor_.Process(input);
      ASSERT_TRUE(r.ok()) << c.status << ": " << r.status().ToString();
      EXPECT_EQ((*r)->status, c.status) << "frame " << frame;
      // The wall seen without floor may still give lines; the others cannot.
      if (std::string(c.status) != "ok" && std::string(c.status) != "no floor visible") {
        EXPECT_TRUE((*r)->lines.lines.empty()) << c.status;
      }
      EXPECT_FALSE((*r)->reset);
      ++frame;
    }
  }
  EXPECT_TRUE(processor_.reset_log().empty());
  // The single wall alone kept the heading at 0.
  EXPECT_LT(std::abs(RadToDeg(processor_.trajectory().back().heading_rad)), 0.3);
}

TEST_F(MappingFrameProcessorTest, WrongDepthTypeIsAnError) {
  MappingInput input;
  input.depth_m = cv::Mat(240, 320, CV_16UC1, cv::Scalar(1000));
  EXPECT_EQ(processor_.Process(input).status().code(), StatusCode::kInvalidArgument);
  MappingFrameProcessor unconfigured;
  EXPECT_EQ(unconfigured.Process(MappingInput()).status().code(), StatusCode::kFailedPrecondition);
}

TEST_F(MappingFrameProcessorTest, ResultsStayValidAfterLaterFrames) {
  // The GUI keeps results while the worker goes on: a result must not change afterwards.
  StatusOr<std::shared_ptr<const MappingFrameResult>> first =
      processor_.Process(CorridorFrame(0, 0));
  ASSERT_TRUE(first.ok());
  const cv::Mat copy = (*first)->occupancy.cells.clone();
  for (int k = 1; k < 5; ++k) ASSERT_TRUE(processor_.Process(CorridorFrame(k, 0.3 * k)).ok());
  EXPECT_EQ(cv::norm(copy, (*first)->occupancy.cells, cv::NORM_L1), 0.0);
}

TEST_F(MappingFrameProcessorTest, MapImageEveryNFrames) {
  MappingOptions options;
  options.stitch.render_every_n = 3;
  MappingFrameProcessor processor(options);
  ASSERT_TRUE(processor.Configure(FloorPlaneOf(SyntheticView()), camera_).ok());
  for (int k = 0; k < 7; ++k) {
    StatusOr<std::shared_ptr<const MappingFrameResult>> r =
        processor.Process(CorridorFrame(k, 0.2 * k));
    ASSERT_TRUE(r.ok());
    EXPECT_EQ((*r)->map_image != nullptr, k % 3 == 0) << k;
    if ((*r)->map_image) {
      EXPECT_EQ((*r)->map_image->type(), CV_8UC3);
      EXPECT_DOUBLE_EQ((*r)->map_resolution_m, 0.05);
      ASSERT_NE((*r)->trajectory, nullptr);
      EXPECT_EQ((*r)->trajectory->size(), static_cast<size_t>(k + 1));
    }
  }
}

// The simulator's corridor (colour and depth, 1 m/s at 5 Hz) through the chain with the pose
// from RGB-D odometry; `spoil(k, &input)` may break frames.
class MappingPoseSourceTest : public ::testing::Test {
 protected:
  void SetUp() override {
    StatusOr<sim::Simulator> made =
        sim::Simulator::Create(testing::CorridorSimulation(3.0, 5.0, 1.0, 2.0));
    ASSERT_TRUE(made.ok()) << made.status().ToString();
    simulator_ = std::make_unique<sim::Simulator>(std::move(*made));
    sim::SimulatedRgbd frame;
    ASSERT_TRUE(simulator_->RenderRgbd(0, &frame).ok());
    std::vector<Eigen::Vector3f> points;
    AppendDepthPoints(frame.depth_m, simulator_->rgbd_camera(), 6.0, 1, &points);
    StatusOr<FloorFitResult> floor = FloorPlaneEstimator().Fit(points);
    ASSERT_TRUE(floor.ok()) << floor.status().ToString();
    floor_ = floor->plane;
  }
  MappingInput Frame(int k, bool with_odometry = true) const {
    sim::SimulatedRgbd frame;
    EXPECT_TRUE(simulator_->RenderRgbd(k, &frame).ok());
    MappingInput input;
    input.stamp.sequence_id = k;
    input.stamp.sensor_time_s = simulator_->TimeOf(k);
    input.depth_m = frame.depth_m;
    input.color = frame.color;
    input.people = std::vector<PersonBox>();
    if (with_odometry) input.odometry = Pose2d{0.2 * k, 0, 0};  // Wheel odometry.
    return input;
  }
  std::unique_ptr<sim::Simulator> simulator_;
  FloorPlane floor_;
};

TEST_F(MappingPoseSourceTest, FailedOdometryStepsHoldThePoseAndSkipTheMap) {
  MappingOptions options;
  options.pose_source = "rgbd";
  MappingFrameProcessor processor(options);
  ASSERT_TRUE(processor.Configure(floor_, simulator_->rgbd_camera()).ok());
  TimingStats timing;
  const float nan = std::numeric_limits<float>::quiet_NaN();
  for (int k = 0; k < simulator_->frames(); ++k) {
    MappingInput input = Frame(k);
    if (k == 4) input.color.setTo(cv::Scalar(0, 0, 0));  // A black frame.
    if (k == 5) input.depth_m.setTo(cv::Scalar(0));      // No depth at all.
    if (k == 6) {                                        // A few valid pixels only.
      cv::Mat sparse(input.depth_m.size(), CV_32FC1, cv::Scalar(nan));
      input.depth_m(cv::Rect(150, 200, 10, 10)).copyTo(sparse(cv::Rect(150, 200, 10, 10)));
      input.depth_m = sparse;
    }
    const int map_frames = processor.map().frames();
    StatusOr<std::shared_ptr<const MappingFrameResult>> r = processor.Process(input, &timing);
    ASSERT_TRUE(r.ok()) << r.status().ToString();
    const MappingFrameResult& result = **r;
    EXPECT_EQ(result.pose_source, "rgbd");
    if (k >= 4 && k <= 6) {
      EXPECT_FALSE(result.odometry_failure.empty()) << "frame " << k;
      EXPECT_EQ(result.status, k == 5 ? "no valid depth" : "odometry failed") << "frame " << k;
      EXPECT_EQ(processor.map().frames(), map_frames) << "frame " << k << " was stitched";
      EXPECT_NEAR(result.pose.x, processor.trajectory()[3].x, 1e-9) << "frame " << k;
    } else {
      EXPECT_TRUE(result.odometry_failure.empty())
          << "frame " << k << ": " << result.odometry_failure;
      EXPECT_EQ(processor.map().frames(), map_frames + 1) << "frame " << k;
      // The odometry's x is the distance driven along the corridor (0.2 m per frame).
      EXPECT_NEAR(result.pose.x, 0.2 * k, 0.03) << "frame " << k;
    }
  }
  EXPECT_EQ(processor.active_pose_source(), "rgbd");
  EXPECT_EQ(processor.odometry_failures(), 3);
  ASSERT_EQ(processor.odometry_log().size(), 3u);
  EXPECT_NE(processor.odometry_log()[0].find("frame 4"), std::string::npos);
  EXPECT_NE(processor.odometry_log()[0].find("blank colour image"), std::string::npos)
      << processor.odometry_log()[0];
  EXPECT_EQ(timing.Summary("odometry").count, static_cast<size_t>(simulator_->frames()));
}

TEST_F(MappingPoseSourceTest, AutoPicksTheRecordingsOdometryElseRgbdElseNone) {
  struct Case {
    std::string wanted;
    bool odometry, color;
    const char* active;
  };
  for (const Case& c : {Case{"auto", true, true, "recording"}, Case{"auto", false, true, "rgbd"},
                        Case{"auto", false, false, "none"}, Case{"rgbd", true, true, "rgbd"},
                        Case{"none", true, true, "none"}}) {
    MappingOptions options;
    options.pose_source = c.wanted;
    MappingFrameProcessor processor(options);
    ASSERT_TRUE(processor.Configure(floor_, simulator_->rgbd_camera()).ok());
    EXPECT_EQ(processor.active_pose_source(), "");
    for (int k = 0; k < 3; ++k) {
      MappingInput input = Frame(k, c.odometry);
      if (!c.color) input.color = cv::Mat();
      ASSERT_TRUE(processor.Process(input).ok());
    }
    EXPECT_EQ(processor.active_pose_source(), c.active) << c.wanted;
    // Only "none" stands still; both pose sources see the 0.4 m driven.
    const double expected_x = std::string(c.active) == "none" ? 0.0 : 0.4;
    EXPECT_NEAR(processor.trajectory().back().x, expected_x, 0.03) << c.wanted;
  }
}

TEST(MappingOptions, KeysAndValidation) {
  const auto specs = MappingOptions::Describe().Specs();
  auto has = [&](const std::string& key) {
    for (const auto& s : specs) {
      if (s.key == key) return true;
    }
    return false;
  };
  for (const char* key :
       {"mapping.extractor", "mapping.floor.epsilon_m", "mapping.occupancy.cell_size_m",
        "mapping.scan.resolution_deg", "mapping.ransac.max_iterations",
        "mapping.ransac.error_threshold_cells", "mapping.split_merge.max_gap_m",
        "mapping.rotation.enabled", "mapping.stitch.resolution_m", "mapping.people.source",
        "mapping.pose.source", "mapping.pose.rgbd.method", "mapping.pose.rgbd.max_gap_s"}) {
    EXPECT_TRUE(has(key)) << key;
  }
  MappingOptions bad;
  bad.extractor = "hough";
  std::string error;
  EXPECT_FALSE(bad.IsValid(&error));
  EXPECT_NE(error.find("mapping.extractor"), std::string::npos);
  bad = MappingOptions();
  bad.pose_source = "gps";
  EXPECT_FALSE(bad.IsValid(&error));
  EXPECT_NE(error.find("mapping.pose.source"), std::string::npos);
  EXPECT_TRUE(MappingOptions().IsValid(&error)) << error;
}

}  // namespace
}  // namespace sightline
