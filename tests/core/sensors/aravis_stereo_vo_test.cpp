// The stereo odometry over a live Aravis stereo pair: two arv-fake-gv-camera-0.8 processes with
// different serials on the loopback of a private network namespace (as aravis_gv_test), with a
// stereo calibration given as a URI option or as stereo.calibration_file. The simulator shows a
// static ramp, so any estimated motion is false motion. Skipped with the reason when no private
// network namespace can be made.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <memory>
#include <string>

#include <opencv2/core.hpp>

#include "core/pipeline/stereo_vo_pipeline.h"
#include "core/sensors/aravis_source.h"
#include "core/sensors/driver_registry.h"
#include "tests/core/sensors/child_process.h"
#include "tests/core/sensors/fake_gige_camera.h"

namespace sightline {
namespace {

using ::sightline::testing::ChildProcess;
using Clock = std::chrono::steady_clock;

constexpr char kLeftAddress[] = "127.0.0.1";
constexpr char kRightAddress[] = "127.0.0.2";  // An alias of lo inside the namespace.
constexpr int kFrames = 20;

::testing::Environment* const kEnvironment = ::testing::AddGlobalTestEnvironment(
    ::sightline::testing::NewPrivateNetworkEnvironment({kRightAddress}));

using ::sightline::testing::FakeCameraDeviceId;
using ::sightline::testing::StartFakeCamera;
using ::sightline::testing::WaitFakeCameraDiscoverable;

// An OpenCV stereo YAML (the layout `sightline-cli calibrate stereo` writes) for two ideal
// width x height cameras 0.12 m apart.
std::string WriteCalibration(const std::string& name, int width, int height) {
  const std::string path =
      (std::filesystem::temp_directory_path() / ("sightline_" + name + ".yaml")).string();
  cv::FileStorage fs(path, cv::FileStorage::WRITE);
  const cv::Mat k = (cv::Mat_<double>(3, 3) << 420, 0, width / 2.0, 0, 420, height / 2.0, 0, 0, 1);
  const cv::Mat d = cv::Mat::zeros(1, 5, CV_64F);
  fs << "image_width" << width << "image_height" << height;
  fs << "M1" << k << "D1" << d << "M2" << k << "D2" << d;
  fs << "R" << cv::Mat::eye(3, 3, CV_64F) << "T" << (cv::Mat_<double>(3, 1) << -0.12, 0, 0);
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

// Both cameras free-run at the simulator's 25 Hz; its frame times jitter by up to 5 ms.
OptionSet SensorOptions() {
  OptionSet options;
  EXPECT_TRUE(DeclareSensorOptions(&options).ok());
  EXPECT_TRUE(options.ApplyOverride("sensors.aravis.stereo.pair_tolerance_ms=15").ok());
  return options;
}

class AravisStereoVo : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!::sightline::testing::PrivateNetworkStatus().ok()) return;
    left_ = StartFakeCamera(kLeftAddress, "VOL");
    right_ = StartFakeCamera(kRightAddress, "VOR");
    ASSERT_TRUE(left_ && right_);
    ASSERT_TRUE(WaitFakeCameraDiscoverable("VOL", std::chrono::seconds(15)));
    ASSERT_TRUE(WaitFakeCameraDiscoverable("VOR", std::chrono::seconds(15)));
  }

  const std::string pair_ = "aravis://" + FakeCameraDeviceId("VOL") + "," + FakeCameraDeviceId("VOR");
  std::unique_ptr<ChildProcess> left_, right_;
};

TEST_F(AravisStereoVo, LivePairWithCalibrationRunsWithoutFalseMotion) {
  SIGHTLINE_REQUIRE_PRIVATE_NETWORK();
  const std::string calibration = WriteCalibration("live_pair", 512, 512);
  const OptionSet sensors = SensorOptions();

  // The source attaches the URI's calibration to its SourceInfo.
  StatusOr<std::unique_ptr<Source>> source =
      OpenSource(pair_ + "?calibration_file=" + calibration, sensors);
  ASSERT_TRUE(source.ok()) << source.status().ToString();
  ASSERT_TRUE((*source)->info().stereo.has_value());
  EXPECT_NEAR((*source)->info().stereo->BaselineM(), 0.12, 1e-9);
  EXPECT_EQ((*source)->info().stereo->left.width, 512);
  source->reset();

  StereoVoRunOptions run;
  run.max_frames = kFrames;
  for (const bool by_uri : {true, false}) {
    SCOPED_TRACE(by_uri ? "aravis://L,R?calibration_file=FILE" : "stereo.calibration_file");
    StereoVoRunOptions options = run;
    if (!by_uri) options.calibration_file = calibration;
    const std::string uri = by_uri ? pair_ + "?calibration_file=" + calibration : pair_;
    StatusOr<StereoVoRun> result =
        RunStereoOdometry(uri, {}, options, nullptr, {}, nullptr, &sensors);
    ASSERT_TRUE(result.ok()) << result.status().ToString();
    EXPECT_EQ(result->dataset_format, "Aravis stereo pair");
    ASSERT_EQ(result->frames.size(), static_cast<size_t>(kFrames));
    EXPECT_EQ(result->estimate.size(), static_cast<size_t>(kFrames));
    double metres = 0, degrees = 0;
    MaxMotion(result->estimate, &metres, &degrees);
    EXPECT_LT(metres, 0.003) << "a static pattern must give no motion";
    EXPECT_LT(degrees, 0.2);
  }
}

TEST_F(AravisStereoVo, WithoutCalibrationTheErrorNamesTheOption) {
  SIGHTLINE_REQUIRE_PRIVATE_NETWORK();
  const OptionSet sensors = SensorOptions();
  StereoVoRunOptions run;
  run.max_frames = kFrames;
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
  run.calibration_file = WriteCalibration("wrong_size", 640, 480);
  result = RunStereoOdometry(pair_, {}, run, nullptr, {}, nullptr, &sensors);
  ASSERT_FALSE(result.ok());
  EXPECT_EQ(result.status().code(), StatusCode::kInvalidArgument);
  EXPECT_NE(result.status().message().find("640x480"), std::string::npos)
      << result.status().message();
  EXPECT_NE(result.status().message().find("512x512"), std::string::npos)
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
