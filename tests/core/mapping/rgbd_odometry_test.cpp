// RGB-D odometry (core/mapping/rgbd_odometry.h) against ground truth: the simulator's corridor
// (exact poses, Kinect noise), TUM fr1_desk (real Kinect, motion capture), and bad frames that
// must fail a step, be counted and leave the pose where it was.
#include "core/mapping/rgbd_odometry.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "core/io/dataset.h"
#include "core/sim/simulator.h"
#include "tests/core/mapping/corridor_run.h"
#include "tests/support/test_data.h"

namespace sightline {
namespace {

// A camera trajectory's errors: both anchored at their first pose (no best fit), the final and
// largest position error, the path length of the truth and of the estimate.
struct Drift {
  double path_m = 0, estimated_path_m = 0;
  double final_m = 0, max_m = 0;
};

Drift MeasureDrift(const std::vector<Eigen::Isometry3d>& estimate,
                   const std::vector<Eigen::Isometry3d>& truth) {
  Drift d;
  const Eigen::Isometry3d truth_from_estimate = truth.front() * estimate.front().inverse();
  for (size_t k = 0; k < truth.size(); ++k) {
    if (k > 0) {
      d.path_m += (truth[k].translation() - truth[k - 1].translation()).norm();
      d.estimated_path_m += (estimate[k].translation() - estimate[k - 1].translation()).norm();
    }
    const double e =
        ((truth_from_estimate * estimate[k]).translation() - truth[k].translation()).norm();
    d.max_m = std::max(d.max_m, e);
    d.final_m = e;
  }
  return d;
}

FrameStamp StampAt(int64_t sequence_id, double time_s) {
  FrameStamp stamp;
  stamp.sequence_id = sequence_id;
  stamp.sensor_time_s = time_s;
  return stamp;
}

TEST(RgbdOdometry, SimulatedCorridorStraightAndTurn) {
  // The mapping corridor's first 40 m: 30 m straight, a 90 deg left turn on a 0.6 m radius, 10 m
  // on; 320x240 Kinect noise; 1 m/s seen at 5 Hz: 0.2 m and up to 19 deg between frames (the
  // turn needs the feature guess: the pyramid alone converges to a wrong motion there).
  const sim::SimulationOptions simulation = testing::CorridorSimulation(40.0, 5.0, 1.0, 0.0);
  StatusOr<sim::Simulator> made = sim::Simulator::Create(simulation);
  ASSERT_TRUE(made.ok()) << made.status().ToString();
  RgbdOdometry odometry;
  ASSERT_TRUE(odometry.Configure(made->rgbd_camera()).ok());
  std::vector<Eigen::Isometry3d> estimate, truth;
  sim::SimulatedRgbd frame;
  for (int k = 0; k < made->frames(); ++k) {
    ASSERT_TRUE(made->RenderRgbd(k, &frame).ok());
    StatusOr<RgbdOdometryStep> step =
        odometry.Track(StampAt(k, made->TimeOf(k)), frame.depth_m, frame.color);
    ASSERT_TRUE(step.ok()) << step.status().ToString();
    EXPECT_TRUE(step->ok) << "frame " << k << ": " << step->failure;
    estimate.push_back(step->world_from_camera);
    truth.push_back(frame.world_from_camera);
  }
  const Drift d = MeasureDrift(estimate, truth);
  std::printf(
      "[ rgbd odometry ] corridor %.1f m (%zu frames): path %.3f m (%+.2f %%), final error "
      "%.3f m (%.2f %%), max %.3f m, %d failed step(s)\n",
      d.path_m, estimate.size(), d.estimated_path_m, 100 * (d.estimated_path_m / d.path_m - 1),
      d.final_m, 100 * d.final_m / d.path_m, d.max_m, odometry.failures());
  EXPECT_EQ(odometry.failures(), 0);
  // Distance is right to well under 1 %; the position error is mostly the heading's slow drift
  // (the mapping chain replaces the heading with the walls', see corridor_odometry_test.cpp).
  EXPECT_NEAR(d.estimated_path_m / d.path_m, 1.0, 0.01);
  EXPECT_LT(d.final_m, 0.05 * d.path_m);
}

// The first-to-last motion of the 9 fr1_desk frames (0.11 m, 9 deg in 0.27 s, hand-held)
// against the motion capture, per method. Measured here (docs/mapping.md): rgbd 29 mm and
// 1.9 deg, rgbd_icp 13 mm and 1.2 deg, icp 13 mm and 1.1 deg; the bounds leave room above that.
TEST(RgbdOdometry, TumFr1DeskAgainstMotionCapture) {
  SIGHTLINE_REQUIRE_DATA(path, "tum_fr1_desk");
  struct Case {
    const char* method;
    double max_position_error_m, max_rotation_error_deg;
  };
  for (const Case& c :
       {Case{"rgbd", 0.04, 2.5}, Case{"rgbd_icp", 0.02, 2.0}, Case{"icp", 0.025, 2.0}}) {
    SCOPED_TRACE(c.method);
    StatusOr<std::unique_ptr<Source>> source = OpenDataset(path, SourceKind::kRgbd);
    ASSERT_TRUE(source.ok()) << source.status().ToString();
    const Trajectory* gt = (*source)->ground_truth();
    ASSERT_TRUE(gt != nullptr && !gt->empty()) << path << " has no groundtruth.txt";
    RgbdOdometryOptions options;
    options.method = c.method;
    RgbdOdometry odometry(options);
    ASSERT_TRUE(odometry.Configure((*source)->info().rgbd->color).ok());
    std::vector<Eigen::Isometry3d> estimate, truth;
    while ((*source)->Grab().ok()) {
      StatusOr<Frame> frame = (*source)->Retrieve();
      ASSERT_TRUE(frame.ok());
      const RgbdFrame& rgbd = std::get<RgbdFrame>(*frame);
      StatusOr<RgbdOdometryStep> step = odometry.Track(rgbd.stamp, rgbd.depth_m, rgbd.color);
      ASSERT_TRUE(step.ok()) << step.status().ToString();
      EXPECT_TRUE(step->ok) << "frame " << rgbd.stamp.sequence_id << ": " << step->failure;
      const auto i = gt->Nearest(rgbd.stamp.sensor_time_s, 0.02);
      ASSERT_TRUE(i.has_value()) << "no ground truth at t = " << rgbd.stamp.sensor_time_s;
      estimate.push_back(step->world_from_camera);
      truth.push_back(gt->poses()[*i].world_from_sensor);
    }
    ASSERT_EQ(estimate.size(), 9u);
    const Drift d = MeasureDrift(estimate, truth);
    const Eigen::Isometry3d true_motion = truth.front().inverse() * truth.back();
    const Eigen::Isometry3d motion = estimate.front().inverse() * estimate.back();
    const double rotation_error_deg =
        RadToDeg(Eigen::AngleAxisd(motion.linear().transpose() * true_motion.linear()).angle());
    std::printf(
        "[ rgbd odometry ] tum_fr1_desk %-8s path %.3f m (estimated %.3f m), final error %.4f m "
        "(%.1f %% of the path), max %.4f m, rotation error %.2f deg\n",
        c.method, d.path_m, d.estimated_path_m, d.final_m, 100 * d.final_m / d.path_m, d.max_m,
        rotation_error_deg);
    EXPECT_EQ(odometry.failures(), 0);
    EXPECT_LT(d.max_m, c.max_position_error_m);
    EXPECT_LT(rotation_error_deg, c.max_rotation_error_deg);
  }
}

// A corridor frame pair to spoil: frame 0 tracked, then bad frames, then frame 1 again.
class RgbdOdometryBadInput : public ::testing::Test {
 protected:
  void SetUp() override {
    StatusOr<sim::Simulator> made =
        sim::Simulator::Create(testing::CorridorSimulation(2.0, 5.0, 1.0, 0.0));
    ASSERT_TRUE(made.ok()) << made.status().ToString();
    camera_ = made->rgbd_camera();
    ASSERT_TRUE(made->RenderRgbd(0, &first_).ok());
    ASSERT_TRUE(made->RenderRgbd(1, &second_).ok());
    ASSERT_TRUE(odometry_.Configure(camera_).ok());
    StatusOr<RgbdOdometryStep> step =
        odometry_.Track(StampAt(0, 0.0), first_.depth_m, first_.color);
    ASSERT_TRUE(step.ok() && step->ok && step->first);
  }

  // Tracks a bad frame at `time_s`: a failed step that keeps the pose.
  void ExpectFailedStep(const cv::Mat& depth, const cv::Mat& color, double time_s,
                        const std::string& why_contains) {
    const int failures = odometry_.failures();
    StatusOr<RgbdOdometryStep> step = odometry_.Track(StampAt(9, time_s), depth, color);
    ASSERT_TRUE(step.ok()) << step.status().ToString();
    EXPECT_FALSE(step->ok);
    EXPECT_NE(step->failure.find(why_contains), std::string::npos) << step->failure;
    EXPECT_EQ(odometry_.failures(), failures + 1);
    EXPECT_TRUE(step->world_from_camera.isApprox(Eigen::Isometry3d::Identity()));
  }

  // After the bad frames, the next good frame is tracked from frame 0 (0.2 m forward).
  void ExpectRecovery(double time_s) {
    StatusOr<RgbdOdometryStep> step =
        odometry_.Track(StampAt(10, time_s), second_.depth_m, second_.color);
    ASSERT_TRUE(step.ok()) << step.status().ToString();
    ASSERT_TRUE(step->ok) << step->failure;
    const Eigen::Isometry3d true_motion =
        first_.world_from_camera.inverse() * second_.world_from_camera;
    EXPECT_NEAR((step->world_from_camera.translation() - true_motion.translation()).norm(), 0,
                0.02);
  }

  PinholeCamera camera_;
  sim::SimulatedRgbd first_, second_;
  RgbdOdometry odometry_;
};

TEST_F(RgbdOdometryBadInput, NanZeroAndSparseDepthBlackAndMissingImagesFailSteps) {
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const cv::Mat all_nan(first_.depth_m.size(), CV_32FC1, cv::Scalar(nan));
  const cv::Mat all_zero(first_.depth_m.size(), CV_32FC1, cv::Scalar(0));
  cv::Mat sparse(first_.depth_m.size(), CV_32FC1, cv::Scalar(nan));
  second_.depth_m(cv::Rect(0, 0, 20, 20)).copyTo(sparse(cv::Rect(0, 0, 20, 20)));  // 0.5 %.
  const cv::Mat black(first_.color.size(), CV_8UC3, cv::Scalar(0, 0, 0));
  ExpectFailedStep(all_nan, second_.color, 0.04, "depth pixels in range");
  ExpectFailedStep(all_zero, second_.color, 0.08, "depth pixels in range");
  ExpectFailedStep(sparse, second_.color, 0.12, "depth pixels in range");
  ExpectFailedStep(second_.depth_m, black, 0.16, "blank colour image");
  ExpectFailedStep(second_.depth_m, cv::Mat(), 0.17, "no colour image");
  ExpectFailedStep(cv::Mat(), second_.color, 0.18, "no depth image");
  EXPECT_EQ(odometry_.failures(), 6);
  ExpectRecovery(0.2);
}

TEST_F(RgbdOdometryBadInput, TimeGoingBackOrAGapFailsAStep) {
  ExpectFailedStep(second_.depth_m, second_.color, 0.0, "not after the last tracked frame");
  ExpectFailedStep(second_.depth_m, second_.color, 5.0, "since the last tracked frame");
  // The gap restarted tracking at the held pose on that frame: the next one aligns with it.
  StatusOr<RgbdOdometryStep> step =
      odometry_.Track(StampAt(11, 5.2), second_.depth_m, second_.color);
  ASSERT_TRUE(step.ok() && step->ok) << (step.ok() ? step->failure : step.status().ToString());
  EXPECT_LT(step->world_from_camera.translation().norm(), 0.01);  // The same image: no motion.
}

TEST_F(RgbdOdometryBadInput, WrongImageTypesAreErrorsNotSteps) {
  cv::Mat depth_mm;
  first_.depth_m.convertTo(depth_mm, CV_16UC1, 1000);
  EXPECT_EQ(odometry_.Track(StampAt(2, 0.2), depth_mm, first_.color).status().code(),
            StatusCode::kInvalidArgument);
  EXPECT_EQ(
      odometry_.Track(StampAt(2, 0.2), first_.depth_m, cv::Mat(4, 4, CV_32FC3)).status().code(),
      StatusCode::kInvalidArgument);
  RgbdOdometry unconfigured;
  EXPECT_EQ(unconfigured.Track(StampAt(0, 0), first_.depth_m, first_.color).status().code(),
            StatusCode::kFailedPrecondition);
  RgbdOdometryOptions bad;
  bad.method = "sift";
  std::string error;
  EXPECT_FALSE(bad.IsValid(&error));
  EXPECT_NE(error.find("mapping.pose.rgbd.method"), std::string::npos) << error;
}

}  // namespace
}  // namespace sightline
