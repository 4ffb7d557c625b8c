// sightline_pipeline_stereo, the run loop and the stereo-vo pipeline without the other pipelines,
// the sensor drivers, ROS or PCL (what sightline-cli-stereo links): stereo-vo runs on recorded
// datasets with the full option set, and a live source says which program opens it.
#include <gtest/gtest.h>

#include <memory>
#include <string>

#include "core/pipeline/pipeline_registry.h"
#include "tests/support/test_data.h"

namespace sightline {

namespace {

PipelineRegistry StereoOnly() {
  PipelineRegistry registry = StereoPipelines();
  EXPECT_EQ(registry.pipelines().size(), 1u);
  EXPECT_NE(registry.Find("stereo-vo"), nullptr);
  return registry;
}

double Figure(const std::vector<std::pair<std::string, double>>& figures, const std::string& key) {
  for (const auto& [name, value] : figures) {
    if (name == key) return value;
  }
  ADD_FAILURE() << key << " missing";
  return -1;
}

TEST(PipelineStereo, RunsStereoVoOnKittiWithinTheGroundTruthsTolerance) {
  SIGHTLINE_REQUIRE_DATA(kitti, "kitti_clip1");
  RunRequest request;
  request.pipeline = "stereo-vo";
  request.dataset_path = kitti;
  request.out_dir = testing::TempDir("pipeline_stereo_kitti");
  StatusOr<RunReport> report = RunPipeline(StereoOnly(), request);
  ASSERT_TRUE(report.ok()) << report.status().ToString();
  EXPECT_EQ(report->metrics.frames, 51);
  EXPECT_EQ(report->result.dataset_format, "KITTI odometry");
  // 60 m of driving: a few centimetres of drift after alignment (the full library's figure).
  const double ate = Figure(report->metrics.accuracy, "ate_rmse_m");
  EXPECT_GT(ate, 0.0);
  EXPECT_LT(ate, 0.1);
  EXPECT_NEAR(Figure(report->metrics.accuracy, "estimated_length_m"), 59.8, 1.0);
  // The options a run lists are the full program's: the drivers' tables are declared too.
  for (const std::string key :
       {"sensors.openni2.width", "sensors.aravis.stereo.calibration_file", "sensors.v4l2.fourcc",
        "sensors.replay.fps", "io.rosbag.tf_max_gap_s", "stereo.subsample"}) {
    EXPECT_TRUE(report->metrics.options.Has(key)) << key;
  }
}

TEST(PipelineStereo, LiveSourcesAndBagsSayWhichProgramOpensThem) {
  for (const std::string path :
       {"aravis://left,right", "sim://panel?seed=1", "/tmp/drive.BAG", "/tmp/room.oni"}) {
    RunRequest request;
    request.pipeline = "stereo-vo";
    request.dataset_path = path;
    request.out_dir = testing::TempDir("pipeline_stereo_live");
    StatusOr<RunReport> report = RunPipeline(StereoOnly(), request);
    ASSERT_FALSE(report.ok()) << path;
    EXPECT_EQ(report.status().code(), StatusCode::kUnavailable) << path;
    EXPECT_EQ(report.status().message().rfind(path + ": ", 0), 0u) << report.status().message();
    EXPECT_NE(report.status().message().find("sightline-cli-full"), std::string::npos)
        << report.status().message();
  }
}

TEST(PipelineStereo, AMissingDatasetNamesItsPath) {
  RunRequest request;
  request.pipeline = "stereo-vo";
  request.dataset_path = testing::TempDir("pipeline_stereo_missing") + "/absent";
  request.out_dir = testing::TempDir("pipeline_stereo_missing_out");
  StatusOr<RunReport> report = RunPipeline(StereoOnly(), request);
  ASSERT_FALSE(report.ok());
  EXPECT_NE(report.status().message().find(request.dataset_path), std::string::npos)
      << report.status().message();
}

}  // namespace
}  // namespace sightline
