// The stereo odometry over a live Aravis stereo pair on real GigE Vision: a left and a right fake
// camera served by textured_fake_stereo_camera (one process, two serials, two loopback addresses
// of a private network namespace, as aravis_gv_test) stream Mono8 stereo pairs of the simulated
// corridor, and log which scene frame and true pose every buffer carried. The odometry runs
// through the product's path for aravis://L,R (OpenSource, RunStereoOdometry) with a stereo
// calibration written from the simulated rig, and is scored against that served ground truth.
// Skipped with the reason when no private network namespace can be made.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <opencv2/core.hpp>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "core/common/trajectory.h"
#include "core/pipeline/stereo_vo_pipeline.h"
#include "core/sensors/aravis_source.h"
#include "core/sensors/driver_registry.h"
#include "core/sim/sensor_options.h"
#include "tests/core/sensors/child_process.h"
#include "tests/core/sensors/fake_gige_camera.h"
#include "tests/support/test_data.h"

namespace sightline {
namespace {

using ::sightline::testing::ChildProcess;

constexpr char kLeftAddress[] = "127.0.0.1";
constexpr char kRightAddress[] = "127.0.0.2";  // An alias of lo inside the namespace.
constexpr double kPairToleranceMs = 15;
// The first frames after acquisition starts are left out of the checks: a fake camera's first
// frame comes off the frame grid, and on a loaded machine the source's first pair can then join
// images of two different instants (the gate holds the pose through it, as it should). Seen once
// in about fifteen runs beside a CPU-heavy test.
constexpr size_t kWarmupFrames = 3;
constexpr int kDriveFrames = 100;  // 4 s of driving at 0.5 m/s, 25 Hz.
// Per tracked frame of the corridor (752x480): measured 800-870 stereo matches and 690-830
// inliers, static or driving; the ramp of arv-fake-gv-camera-0.8 gives none.
constexpr int kMinStereoMatches = 500;
constexpr int kMinInliers = 400;

::testing::Environment* const kEnvironment = ::testing::AddGlobalTestEnvironment(
    ::sightline::testing::NewPrivateNetworkEnvironment({kRightAddress}));

using ::sightline::testing::FakeCameraDeviceId;
using ::sightline::testing::WaitFakeCameraDiscoverable;

// The simulated rig both the camera program and the calibration file use (the simulator's
// EuRoC-like default: 752x480, f 458 px, baseline 0.11 m, rectified).
sim::StereoSensorOptions Rig() { return sim::StereoSensorOptions(); }

// An OpenCV stereo YAML (the layout `sightline-cli calibrate stereo` writes) for `rig`.
std::string WriteCalibration(const std::string& name, const StereoRig& rig) {
  const std::string path =
      (std::filesystem::temp_directory_path() / ("sightline_" + name + ".yaml")).string();
  cv::FileStorage fs(path, cv::FileStorage::WRITE);
  auto k = [](const PinholeCamera& c) -> cv::Mat {
    return (cv::Mat_<double>(3, 3) << c.fx, 0, c.cx, 0, c.fy, c.cy, 0, 0, 1);
  };
  const Eigen::Vector3d t = rig.right_from_left.translation();
  cv::Mat r(3, 3, CV_64F);
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) r.at<double>(i, j) = rig.right_from_left.linear()(i, j);
  }
  fs << "image_width" << rig.left.width << "image_height" << rig.left.height;
  fs << "M1" << k(rig.left) << "D1" << cv::Mat::zeros(1, 5, CV_64F);
  fs << "M2" << k(rig.right) << "D2" << cv::Mat::zeros(1, 5, CV_64F);
  fs << "R" << r << "T" << (cv::Mat_<double>(3, 1) << t.x(), t.y(), t.z());
  return path;
}

// The largest distance and angle of any pose from the first.
void MaxMotion(const Trajectory& t, double* metres, double* degrees) {
  *metres = *degrees = 0;
  const Eigen::Isometry3d first_inverse = t.poses().front().world_from_sensor.inverse();
  for (const TimedPose& p : t.poses()) {
    const Eigen::Isometry3d rel = first_inverse * p.world_from_sensor;
    *metres = std::max(*metres, rel.translation().norm());
    *degrees = std::max(*degrees, Eigen::AngleAxisd(rel.rotation()).angle() * 180 / M_PI);
  }
}

// Both cameras run at 25 Hz on frame starts aligned to the period; their timestamps differ by a
// few milliseconds.
OptionSet SensorOptions() {
  OptionSet options;
  EXPECT_TRUE(DeclareSensorOptions(&options).ok());
  EXPECT_TRUE(options
                  .ApplyOverride("sensors.aravis.stereo.pair_tolerance_ms=" +
                                 std::to_string(kPairToleranceMs))
                  .ok());
  return options;
}

// One buffer the camera program served (served.csv).
struct ServedFrame {
  int64_t stamp_ns = 0;
  int frame = 0;
};

// served.csv by side (0 = left, 1 = right), in time order.
void ReadServed(const std::string& path, std::vector<ServedFrame> served[2]) {
  std::ifstream in(path);
  std::string line;
  std::getline(in, line);  // Header.
  while (std::getline(in, line)) {
    std::istringstream fields(line);
    std::string side, stamp, frame;
    if (!std::getline(fields, side, ',') || !std::getline(fields, stamp, ',') ||
        !std::getline(fields, frame)) {
      continue;  // A line cut off when the program was killed.
    }
    served[side == "left" ? 0 : 1].push_back({std::stoll(stamp), std::stoi(frame)});
  }
}

// The served frame nearest to `time_s`, if within `tolerance_s`.
const ServedFrame* NearestServed(const std::vector<ServedFrame>& served, double time_s,
                                 double tolerance_s) {
  const ServedFrame* best = nullptr;
  double best_dt = tolerance_s;
  for (const ServedFrame& s : served) {
    const double dt = std::abs(static_cast<double>(s.stamp_ns) * 1e-9 - time_s);
    if (dt <= best_dt) {
      best = &s;
      best_dt = dt;
    }
  }
  return best;
}

class AravisStereoVo : public ::testing::Test {
 protected:
  // Starts the camera program with this motion ("robot" or "static") and that many rendered
  // scene frames, and waits until both cameras are discoverable.
  void StartCameras(const std::string& motion, int frames) {
    log_dir_ = ::sightline::testing::TempDir("aravis_stereo_vo_" + motion);
    const sim::StereoSensorOptions rig = Rig();
    StatusOr<std::unique_ptr<ChildProcess>> started =
        ChildProcess::Start({SIGHTLINE_TEXTURED_FAKE_STEREO_CAMERA,
                             "--left-address",
                             kLeftAddress,
                             "--right-address",
                             kRightAddress,
                             "--left-serial",
                             "VOL",
                             "--right-serial",
                             "VOR",
                             "--motion",
                             motion,
                             "--frames",
                             std::to_string(frames),
                             "--rate",
                             "25",
                             "--width",
                             std::to_string(rig.width),
                             "--height",
                             std::to_string(rig.height),
                             "--focal",
                             std::to_string(rig.focal_px),
                             "--baseline",
                             std::to_string(rig.baseline_m),
                             "--log",
                             log_dir_});
    ASSERT_TRUE(started.ok()) << started.status().ToString();
    cameras_ = std::move(*started);
    // The program renders its frames (about 60 ms a pair) before it serves.
    ASSERT_TRUE(WaitFakeCameraDiscoverable("VOL", std::chrono::seconds(30)));
    ASSERT_TRUE(WaitFakeCameraDiscoverable("VOR", std::chrono::seconds(15)));
  }

  // Stops the program, so that its logs are complete, and reads them.
  void StopCameras(Trajectory* ground_truth, std::vector<ServedFrame> served[2]) {
    cameras_->Kill();
    StatusOr<Trajectory> read = ReadTumTrajectory(log_dir_ + "/served_groundtruth.txt");
    ASSERT_TRUE(read.ok()) << read.status().ToString();
    *ground_truth = *read;
    ReadServed(log_dir_ + "/served.csv", served);
  }

  // Every estimated frame from `first` on is a left frame the program served, and the right frame
  // it was paired with (the only one within the pair tolerance) showed the same scene frame.
  static void ExpectConsistentPairs(const StereoVoRun& run,
                                    const std::vector<ServedFrame> served[2], size_t first) {
    const std::vector<TimedPose>& poses = run.estimate.poses();
    for (size_t i = first; i < poses.size(); ++i) {
      const TimedPose& p = poses[i];
      const ServedFrame* left = NearestServed(served[0], p.time_s, 1e-5);
      ASSERT_NE(left, nullptr) << "no left frame served at " << p.time_s;
      const ServedFrame* right = NearestServed(served[1], p.time_s, kPairToleranceMs * 1e-3);
      ASSERT_NE(right, nullptr) << "no right frame served near " << p.time_s;
      EXPECT_EQ(left->frame, right->frame) << "at " << p.time_s;
    }
  }

  // Every frame after `first`: tracked with many stereo matches and inliers, not gated.
  static void ExpectTracked(const StereoVoRun& run, int min_matches, int min_inliers,
                            size_t first) {
    std::vector<int> matches, inliers;
    for (size_t i = first + 1; i < run.frames.size(); ++i) {
      matches.push_back(run.frames[i].stereo_matches);
      inliers.push_back(run.frames[i].inliers);
    }
    std::sort(matches.begin(), matches.end());
    std::sort(inliers.begin(), inliers.end());
    if (!matches.empty()) {
      std::cout << "per frame: stereo matches min " << matches.front() << " median "
                << matches[matches.size() / 2] << ", inliers min " << inliers.front() << " median "
                << inliers[inliers.size() / 2] << "\n";
    }
    for (size_t i = first + 1; i < run.frames.size(); ++i) {
      const FrameStats& s = run.frames[i];
      SCOPED_TRACE("frame " + std::to_string(i) + ": " + s.status);
      EXPECT_FALSE(s.gated);
      EXPECT_EQ(s.status, "ok");
      EXPECT_GE(s.stereo_matches, min_matches);
      EXPECT_GE(s.inliers, min_inliers);
    }
  }

  const std::string pair_ =
      "aravis://" + FakeCameraDeviceId("VOL") + "," + FakeCameraDeviceId("VOR");
  std::string log_dir_;
  std::unique_ptr<ChildProcess> cameras_;
};

TEST_F(AravisStereoVo, LivePairTracksTheServedCorridorDrive) {
  SIGHTLINE_REQUIRE_PRIVATE_NETWORK();
  StartCameras("robot", kDriveFrames);
  if (HasFatalFailure()) return;
  const std::string calibration = WriteCalibration("live_drive", Rig().Rig());
  const OptionSet sensors = SensorOptions();
  StereoVoRunOptions run;
  run.max_frames = 60;
  StatusOr<StereoVoRun> result = RunStereoOdometry(pair_ + "?calibration_file=" + calibration, {},
                                                   run, nullptr, {}, nullptr, &sensors);
  ASSERT_TRUE(result.ok()) << result.status().ToString();
  ASSERT_EQ(result->frames.size(), 60u);
  Trajectory truth;
  std::vector<ServedFrame> served[2];
  StopCameras(&truth, served);
  if (HasFatalFailure()) return;
  ExpectConsistentPairs(*result, served, kWarmupFrames);
  ExpectTracked(*result, kMinStereoMatches, kMinInliers, kWarmupFrames);
  const ServedFrame* first =
      NearestServed(served[0], result->estimate.poses()[kWarmupFrames].time_s, 1e-5);
  const ServedFrame* last = NearestServed(served[0], result->estimate.poses().back().time_s, 1e-5);
  ASSERT_TRUE(first != nullptr && last != nullptr);
  std::cout << "the run saw scene frames " << first->frame << " to " << last->frame << "\n";

  // The estimate against the true poses of the served left frames, both relative to the first
  // frame after the warm-up (no alignment).
  const std::vector<TimedPose> estimate(result->estimate.poses().begin() + kWarmupFrames,
                                        result->estimate.poses().end());
  std::vector<Eigen::Isometry3d> true_poses;
  for (const TimedPose& p : estimate) {
    const std::optional<size_t> i = truth.Nearest(p.time_s, 1e-5);
    ASSERT_TRUE(i.has_value()) << "no ground truth at " << p.time_s;
    true_poses.push_back(truth.poses()[*i].world_from_sensor);
  }
  double true_length = 0, position_error = 0, angle_error = 0;
  for (size_t i = 0; i < estimate.size(); ++i) {
    if (i > 0) {
      true_length += (true_poses[i].translation() - true_poses[i - 1].translation()).norm();
    }
    const Eigen::Isometry3d true_rel = true_poses.front().inverse() * true_poses[i];
    const Eigen::Isometry3d estimated_rel =
        estimate.front().world_from_sensor.inverse() * estimate[i].world_from_sensor;
    const Eigen::Isometry3d error = true_rel.inverse() * estimated_rel;
    position_error = std::max(position_error, error.translation().norm());
    angle_error = std::max(angle_error, Eigen::AngleAxisd(error.rotation()).angle() * 180 / M_PI);
  }
  double estimated_length = 0;
  for (size_t i = 1; i < estimate.size(); ++i) {
    estimated_length += (estimate[i].world_from_sensor.translation() -
                         estimate[i - 1].world_from_sensor.translation())
                            .norm();
  }
  std::cout << "served path " << true_length << " m, estimated " << estimated_length
            << " m; largest position error " << position_error << " m, angle error " << angle_error
            << " deg\n";
  ASSERT_GT(true_length, 0.5) << "the rig must have driven during the run";
  // Measured: length within 0.2 %, position error 1.7-2.7 mm over 1.1-1.3 m (0.2 %). A
  // disparity offset invented from drifting tracks made it 0.6 % and 7-10 mm.
  EXPECT_NEAR(estimated_length, true_length, 0.005 * true_length);
  EXPECT_LT(position_error, 0.005 * true_length);
  EXPECT_LT(angle_error, 0.5);
}

TEST_F(AravisStereoVo, LiveStaticPairGivesNoFalseMotion) {
  SIGHTLINE_REQUIRE_PRIVATE_NETWORK();
  StartCameras("static", 10);
  if (HasFatalFailure()) return;
  const std::string calibration = WriteCalibration("live_static", Rig().Rig());
  const OptionSet sensors = SensorOptions();

  // The source attaches the URI's calibration to its SourceInfo.
  StatusOr<std::unique_ptr<Source>> source =
      OpenSource(pair_ + "?calibration_file=" + calibration, sensors);
  ASSERT_TRUE(source.ok()) << source.status().ToString();
  ASSERT_TRUE((*source)->info().stereo.has_value());
  EXPECT_NEAR((*source)->info().stereo->BaselineM(), Rig().baseline_m, 1e-9);
  EXPECT_EQ((*source)->info().stereo->left.width, Rig().width);
  source->reset();

  StereoVoRunOptions run;
  run.max_frames = 25;
  std::vector<StereoVoRun> runs;
  for (const bool by_uri : {true, false}) {
    SCOPED_TRACE(by_uri ? "aravis://L,R?calibration_file=FILE" : "stereo.calibration_file");
    StereoVoRunOptions options = run;
    if (!by_uri) options.calibration_file = calibration;
    const std::string uri = by_uri ? pair_ + "?calibration_file=" + calibration : pair_;
    StatusOr<StereoVoRun> result =
        RunStereoOdometry(uri, {}, options, nullptr, {}, nullptr, &sensors);
    ASSERT_TRUE(result.ok()) << result.status().ToString();
    EXPECT_EQ(result->dataset_format, "Aravis stereo pair");
    ASSERT_EQ(result->frames.size(), static_cast<size_t>(run.max_frames));
    ExpectTracked(*result, kMinStereoMatches, kMinInliers, kWarmupFrames);
    double metres = 0, degrees = 0;
    MaxMotion(result->estimate, &metres, &degrees);
    std::cout << "static rig: largest estimated motion " << metres << " m, " << degrees << " deg\n";
    EXPECT_LT(metres, 0.001) << "a static rig must give no motion";
    EXPECT_LT(degrees, 0.1);
    runs.push_back(std::move(*result));
  }
  Trajectory truth;
  std::vector<ServedFrame> served[2];
  StopCameras(&truth, served);
  if (HasFatalFailure()) return;
  for (const StereoVoRun& r : runs) ExpectConsistentPairs(r, served, kWarmupFrames);
}

TEST_F(AravisStereoVo, WithoutCalibrationTheErrorNamesTheOption) {
  SIGHTLINE_REQUIRE_PRIVATE_NETWORK();
  StartCameras("static", 1);
  if (HasFatalFailure()) return;
  const OptionSet sensors = SensorOptions();
  StereoVoRunOptions run;
  run.max_frames = 20;
  StatusOr<StereoVoRun> result = RunStereoOdometry(pair_, {}, run, nullptr, {}, nullptr, &sensors);
  ASSERT_FALSE(result.ok());
  EXPECT_EQ(result.status().code(), StatusCode::kFailedPrecondition);
  EXPECT_NE(result.status().message().find("no stereo calibration"), std::string::npos)
      << result.status().message();
  EXPECT_NE(result.status().message().find("stereo.calibration_file=FILE"), std::string::npos)
      << result.status().message();
  EXPECT_NE(result.status().message().find("?calibration_file=FILE"), std::string::npos)
      << result.status().message();

  // A calibration for another image size is refused, naming both sizes.
  sim::StereoSensorOptions other = Rig();
  other.width = 640;
  run.calibration_file = WriteCalibration("wrong_size", other.Rig());
  result = RunStereoOdometry(pair_, {}, run, nullptr, {}, nullptr, &sensors);
  ASSERT_FALSE(result.ok());
  EXPECT_EQ(result.status().code(), StatusCode::kInvalidArgument);
  EXPECT_NE(result.status().message().find("640x480"), std::string::npos)
      << result.status().message();
  EXPECT_NE(result.status().message().find("752x480"), std::string::npos)
      << result.status().message();

  // So is a missing file given in the URI.
  StatusOr<std::unique_ptr<Source>> source =
      OpenSource(pair_ + "?calibration_file=/nonexistent/rig.yaml", sensors);
  ASSERT_FALSE(source.ok());
  EXPECT_NE(source.status().message().find("sensors.aravis.stereo.calibration_file"),
            std::string::npos)
      << source.status().message();
}

}  // namespace
}  // namespace sightline
