// The mapping, mobility and inspect pipelines as objects run headless through the registry
// (RunPipeline -> RunHeadless), on simulated recordings with ground truth: their files and
// figures. Also: mobility honours mobility.run.floor_file, and mapping's floor calibration.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/io/dataset.h"
#include "core/io/floor_file.h"
#include "core/pipeline/mapping_pipeline.h"
#include "core/pipeline/mobility_pipeline.h"
#include "core/pipeline/pipeline_registry.h"
#include "core/sim/simulate.h"
#include "tests/support/test_data.h"

namespace sightline {
namespace {

using testing::ReadAll;

double Figure(const std::vector<std::pair<std::string, double>>& figures, const std::string& key) {
  for (const auto& [name, value] : figures) {
    if (name == key) return value;
  }
  ADD_FAILURE() << key << " missing";
  return std::nan("");
}

int DataLines(const std::string& path) {
  std::ifstream in(path);
  int n = 0;
  for (std::string line; std::getline(in, line);) n += !line.empty() && line[0] != '#';
  return n;
}

// A 30-frame corridor drive (6 m at 1 m/s, 5 Hz) at 320x240, odometry drifting 2 deg/m.
class PipelineObjects : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    corridor_ = new std::string(testing::TempDir("pipeline_objects") + "/corridor");
    sim::SimulationOptions options = sim::SimulationOptions::ForScene("corridor");
    options.frames = 30;
    options.sensors = "rgbd";
    options.rate_hz = 5;
    options.rgbd.resolution = "320x240";
    options.motion.speed_mps = 1;
    options.odometry.heading_drift_deg_per_m = 2;
    camera_height_m_ = options.motion.camera_height_m;
    ASSERT_TRUE(sim::Simulate(options, *corridor_).ok());
  }
  static void TearDownTestSuite() {
    delete corridor_;
    corridor_ = nullptr;
  }

  static StatusOr<RunReport> Run(const std::string& pipeline, const std::string& dataset,
                                 const std::string& out, std::vector<std::string> overrides) {
    RunRequest request;
    request.pipeline = pipeline;
    request.dataset_path = dataset;
    request.out_dir = out;
    request.overrides = std::move(overrides);
    return RunPipeline(BuiltinPipelines(), request);
  }

  static std::string* corridor_;
  static double camera_height_m_;
};

std::string* PipelineObjects::corridor_ = nullptr;
double PipelineObjects::camera_height_m_ = 0;

TEST_F(PipelineObjects, MappingRunsHeadlessAndCorrectsTheDriftingHeading) {
  const std::string out = testing::TempDir("pipeline_objects") + "/mapping";
  StatusOr<RunReport> report = Run("mapping", *corridor_, out, {});
  ASSERT_TRUE(report.ok()) << report.status().ToString();
  EXPECT_EQ(report->result.frames, 30);
  for (const char* file : {"trajectory.txt", "lines.csv", "map.pgm", "map.yaml", "map.png",
                           "floor.yaml", "mapping_log.txt", "metrics.json"}) {
    EXPECT_TRUE(std::filesystem::exists(out + "/" + file)) << file;
  }
  // Every frame is mapped, the five that calibrated the floor included.
  EXPECT_EQ(DataLines(out + "/trajectory.txt"), 30);
  StatusOr<FloorCalibration> floor = ReadFloorCalibration(out + "/floor.yaml");
  ASSERT_TRUE(floor.ok()) << floor.status().ToString();
  EXPECT_NEAR(floor->plane.CameraHeightM(), camera_height_m_, 0.03);
  EXPECT_EQ(floor->frames, 5);
  // 6 m at 2 deg/m would be 12 deg uncorrected.
  EXPECT_LT(Figure(report->result.accuracy, "heading_error_deg_max"), 1.5);
  EXPECT_GT(Figure(report->result.accuracy, "map_iou"), 0.4);
  // Timing stages keep their names; "total" has one sample per frame.
  for (const char* stage : {"read", "occupancy", "scan", "lines", "rotation", "stitch"}) {
    bool found = false;
    for (const auto& [name, summary] : report->metrics.timing_ms) found |= name == stage;
    EXPECT_TRUE(found) << stage;
  }
  EXPECT_EQ(report->metrics.timing_ms.back().second.count, 30u);
  EXPECT_NEAR(Figure(report->result.counts, "camera_height_m"), camera_height_m_, 0.03);

  const std::string off = testing::TempDir("pipeline_objects") + "/mapping_off";
  StatusOr<RunReport> uncorrected =
      Run("mapping", *corridor_, off, {"mapping.rotation.enabled=false"});
  ASSERT_TRUE(uncorrected.ok()) << uncorrected.status().ToString();
  EXPECT_GT(Figure(uncorrected->result.accuracy, "heading_error_deg_max"), 6.0);
}

TEST_F(PipelineObjects, MappingUsesAFloorFileAndCalibratesOnShortRuns) {
  const std::string dir = testing::TempDir("pipeline_objects") + "/floor";
  std::filesystem::create_directories(dir);
  FloorCalibration tilted;
  tilted.plane.normal = Eigen::Vector3d(0, -std::cos(0.2), std::sin(0.2));
  tilted.plane.d = 0.9;
  ASSERT_TRUE(WriteFloorCalibration(tilted, dir + "/floor_in.yaml").ok());
  StatusOr<RunReport> report =
      Run("mapping", *corridor_, dir + "/run",
          {"mapping.run.floor_file=" + dir + "/floor_in.yaml", "mapping.run.max_frames=4"});
  ASSERT_TRUE(report.ok()) << report.status().ToString();
  EXPECT_EQ(report->result.frames, 4);
  EXPECT_NE(ReadAll(dir + "/run/mapping_log.txt").find("floor: " + dir + "/floor_in.yaml"),
            std::string::npos);
  StatusOr<FloorCalibration> used = ReadFloorCalibration(dir + "/run/floor.yaml");
  ASSERT_TRUE(used.ok());
  EXPECT_NEAR(used->plane.CameraHeightM(), 0.9, 1e-6);

  // Three frames, fewer than floor_frames: the floor is fitted on those three.
  StatusOr<RunReport> short_run =
      Run("mapping", *corridor_, dir + "/short", {"mapping.run.max_frames=3"});
  ASSERT_TRUE(short_run.ok()) << short_run.status().ToString();
  EXPECT_EQ(short_run->result.frames, 3);
  StatusOr<FloorCalibration> fitted = ReadFloorCalibration(dir + "/short/floor.yaml");
  ASSERT_TRUE(fitted.ok());
  EXPECT_EQ(fitted->frames, 3);
  EXPECT_NEAR(fitted->plane.CameraHeightM(), camera_height_m_, 0.03);
}

TEST_F(PipelineObjects, InspectRunsHeadless) {
  const std::string out = testing::TempDir("pipeline_objects") + "/inspect";
  StatusOr<RunReport> report = Run("inspect", *corridor_, out, {"inspect.max_frames=7"});
  ASSERT_TRUE(report.ok()) << report.status().ToString();
  EXPECT_EQ(report->result.frames, 7);
  const std::string csv = ReadAll(out + "/frames.csv");
  EXPECT_EQ(csv.rfind("frame,time_s,valid_depth_fraction,has_gt\n", 0), 0u) << csv;
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 8);
  EXPECT_DOUBLE_EQ(Figure(report->result.accuracy, "gt_coverage"), 1.0);
}

// Three frames of simulated terrain: the camera 1.0 m above flat floor, ramps and boxes.
class MobilityObjects : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    terrain_ = new std::string(testing::TempDir("pipeline_objects") + "/terrain");
    sim::SimulationOptions options = sim::SimulationOptions::ForScene("terrain");
    options.frames = 3;
    ASSERT_TRUE(sim::Simulate(options, *terrain_).ok());
  }
  static void TearDownTestSuite() {
    delete terrain_;
    terrain_ = nullptr;
  }
  static std::string* terrain_;
};

std::string* MobilityObjects::terrain_ = nullptr;

TEST_F(MobilityObjects, RunsHeadlessWithItsFilesAndFigures) {
  const std::string out = testing::TempDir("pipeline_objects") + "/mobility";
  RunRequest request;
  request.pipeline = "mobility";
  request.dataset_path = *terrain_;
  request.out_dir = out;
  StatusOr<RunReport> report = RunPipeline(BuiltinPipelines(), request);
  ASSERT_TRUE(report.ok()) << report.status().ToString();
  EXPECT_EQ(report->result.frames, 3);
  for (const char* file : {"000000_cloud.pcd", "000002_projection.png", "000002_topview.png",
                           "segments.csv", "mobility_log.txt", "metrics.json"}) {
    EXPECT_TRUE(std::filesystem::exists(out + "/" + file)) << file;
  }
  EXPECT_NEAR(Figure(report->result.accuracy, "ground_height_m"), 1.0, 0.02);
  EXPECT_LT(Figure(report->result.accuracy, "slope_error_deg_max"), 1.0);
  EXPECT_NEAR(Figure(report->result.accuracy, "flat_roughness"), 1.0, 0.02);
  EXPECT_EQ(Figure(report->result.counts, "frames_with_ground"), 3);
  for (const std::string& stage : MobilityStages()) {
    EXPECT_GT(Figure(report->result.counts, "points_" + stage), 0) << stage;
  }
}

// The GUI runs the registry's object (mobility_presenter_test checks the presenter takes it):
// the object reads mobility.run.floor_file and takes its normal as the expected up direction.
TEST_F(MobilityObjects, HonoursTheFloorFile) {
  const std::string dir = testing::TempDir("pipeline_objects") + "/mobility_floor";
  std::filesystem::create_directories(dir);
  FloorCalibration floor;
  floor.plane.normal = Eigen::Vector3d(0, -std::cos(0.5), std::sin(0.5)).normalized();
  floor.plane.d = 1.0;
  ASSERT_TRUE(WriteFloorCalibration(floor, dir + "/floor.yaml").ok());

  const PipelineRegistry registry = BuiltinPipelines();
  const PipelineInfo* info = registry.Find("mobility");
  ASSERT_NE(info, nullptr);
  ASSERT_TRUE(info->create);
  EXPECT_TRUE(info->Accepts(SourceKind::kRgbd));
  EXPECT_TRUE(info->Accepts(SourceKind::kCloud));
  OptionSet options;
  ASSERT_TRUE(info->declare_options(&options).ok());
  ASSERT_TRUE(options.ApplyOverride("mobility.run.floor_file=" + dir + "/floor.yaml").ok());
  std::unique_ptr<Pipeline> pipeline = info->create();
  ASSERT_TRUE(pipeline->Configure(options).ok());
  StatusOr<std::unique_ptr<Source>> source = OpenDataset(*terrain_, SourceKind::kRgbd);
  ASSERT_TRUE(source.ok()) << source.status().ToString();
  ASSERT_TRUE(pipeline->Open(PipelineSource::From(**source)).ok());
  ASSERT_TRUE((*source)->Grab().ok());
  StatusOr<Frame> frame = (*source)->Retrieve();
  ASSERT_TRUE(frame.ok());
  StatusOr<std::shared_ptr<const PipelineResult>> result = pipeline->Process(*frame);
  ASSERT_TRUE(result.ok()) << result.status().ToString();
  const auto* mobility = dynamic_cast<const MobilityFrameResult*>(result->get());
  ASSERT_NE(mobility, nullptr);
  ASSERT_NE(mobility->mobility, nullptr);
  EXPECT_LT((mobility->mobility->expected_up - floor.plane.normal).norm(), 1e-6);

  // A missing file is an error naming it, and the previous options stay in force.
  OptionSet bad = options;
  ASSERT_TRUE(bad.ApplyOverride("mobility.run.floor_file=" + dir + "/absent.yaml").ok());
  const Status configured = pipeline->Configure(bad);
  EXPECT_FALSE(configured.ok());
  EXPECT_NE(configured.message().find("absent.yaml"), std::string::npos) << configured.message();
}

}  // namespace
}  // namespace sightline
