// The button pipeline without an arm (no arm_poses.txt, no streamed arm): on a plain folder of
// the simulator's panel frames it tracks the tapped button, locates it in map units, writes
// button.csv and the overlay, and never publishes a target; checked against the simulator's
// truth (true button projections, true camera poses and button centre).
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <atomic>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/videoio.hpp>
#include <sstream>
#include <thread>

#include "core/button/arm_client.h"
#include "core/button/arm_server.h"
#include "core/common/trajectory.h"
#include "core/pipeline/button_pipeline.h"
#include "core/pipeline/pipeline_registry.h"
#include "core/sim/simulate.h"
#include "tests/support/button_csv.h"
#include "tests/support/plain_frames.h"
#include "tests/support/test_data.h"

namespace sightline {
namespace {

namespace fs = std::filesystem;
using testing::ReadAll;

// button.csv by column name.
struct Csv {
  std::map<std::string, std::vector<double>> columns;
  size_t rows = 0;
};

Csv ReadCsv(const std::string& path) {
  const testing::CsvColumns read = testing::ReadCsvColumns(path);
  return {read.columns, read.rows};
}

class ButtonTrackingOnly : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    sim_ = new std::string(testing::TempDir("tracking_only_sim"));
    plain_ = new std::string(testing::TempDir("tracking_only_plain") + "/frames");
    sim::SimulationOptions options = sim::SimulationOptions::ForScene("panel");
    options.arm.sideways_m = 0.12;
    ASSERT_TRUE(sim::Simulate(options, *sim_).ok());
    ASSERT_GT(testing::MakePlainFrameFolder(*sim_, *plain_), 50);
  }
  static void TearDownTestSuite() {
    delete sim_;
    delete plain_;
  }

  static const TrueButton& Target() {
    static const std::vector<TrueButton> buttons = *ReadTrueButtons(*sim_ + "/buttons.csv");
    for (const TrueButton& b : buttons) {
      if (b.id == 5) return b;
    }
    ADD_FAILURE() << "button 5 not in buttons.csv";
    return buttons.front();
  }
  // A few pixels off the true centre of button 5 at frame 0.
  static std::string Tap() {
    char tap[96];
    std::snprintf(tap, sizeof(tap), "button.run.tap=%.1f,%.1f@0", Target().pixel[0].x() + 2,
                  Target().pixel[0].y() - 2);
    return tap;
  }
  static StatusOr<RunReport> Run(const std::string& path, const std::string& out,
                                 std::vector<std::string> overrides) {
    RunRequest request;
    request.pipeline = "button";
    request.dataset_path = path;
    request.out_dir = out;
    request.overrides = std::move(overrides);
    return RunPipeline(BuiltinPipelines(), request);
  }
  static double Count(const RunReport& report, const std::string& key) {
    for (const auto& [k, v] : report.result.counts) {
      if (k == key) return v;
    }
    return std::nan("");
  }

  static std::string* sim_;
  static std::string* plain_;
};
std::string* ButtonTrackingOnly::sim_ = nullptr;
std::string* ButtonTrackingOnly::plain_ = nullptr;

// The tracked pixel against the true projection, and the unscaled 3D against the true button
// after one similarity (Sim(3) of the map's camera centres onto the true ones).
TEST_F(ButtonTrackingOnly, PlainFramesAreTrackedAndLocatedUpToScaleWithoutATarget) {
  const std::string out = testing::TempDir("tracking_only_run");
  StatusOr<RunReport> report = Run(*plain_, out, {Tap()});
  ASSERT_TRUE(report.ok()) << report.status().ToString();
  for (const std::string& note : report->result.notes) std::printf("  note: %s\n", note.c_str());
  EXPECT_TRUE(report->result.nothing_achieved.empty()) << report->result.nothing_achieved;
  ASSERT_FALSE(report->result.notes.empty());
  EXPECT_EQ(report->result.notes[0].rfind("no metric scale: no arm motion", 0), 0u);
  EXPECT_NE(report->result.notes[1].find("auto found no arm_poses.txt"), std::string::npos);
  EXPECT_EQ(Count(*report, "metric_scale"), 0);
  const std::string json = ReadAll(report->metrics_path);
  EXPECT_NE(json.find("\"notes\""), std::string::npos) << json;
  EXPECT_NE(json.find("no metric scale: no arm motion"), std::string::npos);
  EXPECT_EQ(json.find("\"failure\""), std::string::npos);

  const Csv csv = ReadCsv(out + "/button.csv");
  ASSERT_GT(csv.rows, 50u);
  for (const char* column : {"button_x_map_units", "camera_z_map_units", "metric_scale"}) {
    EXPECT_TRUE(csv.columns.count(column)) << column;
  }
  const TrueButton& button = Target();
  StatusOr<Trajectory> truth = ReadTumTrajectory(*sim_ + "/mono/groundtruth.txt");
  ASSERT_TRUE(truth.ok()) << truth.status().ToString();
  int compared = 0, within = 0;
  std::vector<Eigen::Vector3d> map_cams, true_cams, map_buttons;
  for (size_t i = 0; i < csv.rows; ++i) {
    const size_t f = static_cast<size_t>(csv.columns.at("frame")[i]);
    EXPECT_TRUE(std::isnan(csv.columns.at("cam_z_m")[i])) << "metres in row " << i;
    EXPECT_TRUE(std::isnan(csv.columns.at("base_x_m")[i])) << "metres in row " << i;
    EXPECT_EQ(csv.columns.at("target_sent")[i], 0);
    EXPECT_EQ(csv.columns.at("metric_scale")[i], 0);
    if (f >= button.visible.size() || !button.visible[f]) continue;
    ++compared;
    const Eigen::Vector2d px(csv.columns.at("u_px")[i], csv.columns.at("v_px")[i]);
    within += px.allFinite() && (px - button.pixel[f]).norm() <= 3.0 ? 1 : 0;
    const Eigen::Vector3d cam(csv.columns.at("camera_x_map_units")[i],
                              csv.columns.at("camera_y_map_units")[i],
                              csv.columns.at("camera_z_map_units")[i]);
    const Eigen::Vector3d b(csv.columns.at("button_x_map_units")[i],
                            csv.columns.at("button_y_map_units")[i],
                            csv.columns.at("button_z_map_units")[i]);
    if (!cam.allFinite() || f >= truth->size()) continue;
    map_cams.push_back(cam);
    true_cams.push_back(truth->poses()[f].world_from_sensor.translation());
    if (b.allFinite()) map_buttons.push_back(b);
  }
  std::printf("  tracked within 3 px of the true projection: %d of %d frames\n", within, compared);
  ASSERT_GT(compared, 50);
  EXPECT_GE(within, 0.9 * compared);

  // One similarity for the whole run: the map's camera centres onto the true ones.
  ASSERT_GT(map_cams.size(), 20u);
  ASSERT_GT(map_buttons.size(), 20u);
  Eigen::Matrix3Xd src(3, map_cams.size()), dst(3, map_cams.size());
  for (size_t i = 0; i < map_cams.size(); ++i) src.col(i) = map_cams[i], dst.col(i) = true_cams[i];
  const Eigen::Matrix4d sim3 = Eigen::umeyama(src, dst, true);
  auto to_world = [&](const Eigen::Vector3d& x) {
    return Eigen::Vector3d((sim3 * x.homogeneous()).head<3>());
  };
  std::vector<double> errors_m, angles_deg;
  for (size_t i = 0; i < map_buttons.size(); ++i) {
    errors_m.push_back((to_world(map_buttons[i]) - button.center_in_world).norm());
  }
  for (size_t i = 0; i < map_cams.size() && i < map_buttons.size(); ++i) {
    const Eigen::Vector3d seen = to_world(map_buttons[i]) - to_world(map_cams[i]);
    const Eigen::Vector3d real = button.center_in_world - true_cams[i];
    angles_deg.push_back(
        std::acos(std::clamp(seen.normalized().dot(real.normalized()), -1.0, 1.0)) * 180.0 / M_PI);
  }
  std::sort(errors_m.begin(), errors_m.end());
  std::sort(angles_deg.begin(), angles_deg.end());
  const double distance_m = (button.center_in_world - true_cams.front()).norm();
  const double median_error = errors_m[errors_m.size() / 2];
  std::printf(
      "  unscaled 3D after one Sim(3): median %.2f mm (%.2f %% of the %.0f mm distance), "
      "direction median %.2f deg\n",
      median_error * 1e3, 100 * median_error / distance_m, distance_m * 1e3,
      angles_deg[angles_deg.size() / 2]);
  EXPECT_LT(median_error, 0.03 * distance_m);
  EXPECT_LT(angles_deg[angles_deg.size() / 2], 1.5);

  // The overlay: one PNG per row of button.csv.
  int pngs = 0;
  std::string first_png;
  for (const fs::directory_entry& e : fs::directory_iterator(out + "/overlay")) {
    if (e.path().extension() != ".png") continue;
    ++pngs;
    if (first_png.empty() || e.path().filename().string() < first_png) {
      first_png = e.path().filename().string();
    }
  }
  EXPECT_EQ(pngs, static_cast<int>(csv.rows));
  EXPECT_NE(std::find(report->result.outputs.begin(), report->result.outputs.end(), "overlay/"),
            report->result.outputs.end());
  // The video, written frame by frame during the run: the same frames, in place at the end.
  cv::VideoCapture video(out + "/overlay.avi", cv::CAP_OPENCV_MJPEG);
  ASSERT_TRUE(video.isOpened());
  EXPECT_EQ(static_cast<int>(video.get(cv::CAP_PROP_FRAME_COUNT)), pngs);
  cv::Mat first;
  ASSERT_TRUE(video.read(first));
  EXPECT_EQ(first.cols, cv::imread(out + "/overlay/" + first_png).cols);
  EXPECT_NE(std::find(report->result.outputs.begin(), report->result.outputs.end(), "overlay.avi"),
            report->result.outputs.end());
}

// A connected arm client over TCP receives heartbeats and the closing stop, never a target.
TEST_F(ButtonTrackingOnly, ServingPublishesNoTargetToAConnectedClient) {
  int port = 0;
  {
    ArmServerOptions probe;
    probe.port = 0;
    auto server = ArmServer::Start(probe);
    ASSERT_TRUE(server.ok()) << server.status().ToString();
    port = (*server)->port();
  }
  std::vector<std::string> lines;
  std::atomic<bool> connected{false};
  std::thread client([&] {
    for (int attempt = 0; attempt < 600; ++attempt) {
      auto c = ArmClient::Connect("127.0.0.1", port, "", 1000);
      if (!c.ok()) {
        std::this_thread::sleep_for(std::chrono::milliseconds(50));
        continue;
      }
      connected = true;
      for (;;) {
        StatusOr<std::string> line = c->ReadLine(60000);
        if (!line.ok()) return;
        lines.push_back(*line);
      }
    }
  });
  const std::string out = testing::TempDir("tracking_only_serve");
  StatusOr<RunReport> report =
      Run(*plain_, out,
          {Tap(), "button.run.serve=true", "button.arm.port=" + std::to_string(port),
           "button.run.wait_clients=1", "button.arm.heartbeat_s=0.05", "button.overlay.png=false"});
  client.join();
  ASSERT_TRUE(report.ok()) << report.status().ToString();
  EXPECT_TRUE(connected);
  int heartbeats = 0, targets = 0, stops = 0;
  for (const std::string& line : lines) {
    heartbeats += line.find("\"type\":\"heartbeat\"") != std::string::npos;
    targets += line.find("\"type\":\"target\"") != std::string::npos;
    stops += line.find("\"type\":\"stop\"") != std::string::npos;
  }
  std::printf("  client lines: %zu (heartbeats %d, targets %d, stops %d); suppressed %g\n",
              lines.size(), heartbeats, targets, stops,
              Count(*report, "targets_suppressed_no_scale"));
  EXPECT_GT(heartbeats, 0);
  EXPECT_EQ(targets, 0);
  EXPECT_EQ(stops, 1);  // "source ended".
  EXPECT_EQ(Count(*report, "arm_targets_published"), 0);
  EXPECT_EQ(Count(*report, "arm_clients_at_start"), 1);
  EXPECT_GT(Count(*report, "targets_suppressed_no_scale"), 0);
  EXPECT_FALSE(fs::exists(out + "/overlay"));
}

// Explicit options beat the guess: none forces tracking only beside arm poses; arm without
// arm poses is an error naming the file; ground truth is no metric source for targets.
TEST_F(ButtonTrackingOnly, MetricSourceNoneForcesTrackingOnlyBesideTheArmsPoses) {
  const std::string out = testing::TempDir("tracking_only_forced");
  StatusOr<RunReport> report =
      Run(*sim_, out, {Tap(), "mono.run.metric_source=none", "button.overlay.video=false"});
  ASSERT_TRUE(report.ok()) << report.status().ToString();
  EXPECT_EQ(Count(*report, "metric_scale"), 0);
  ASSERT_GE(report->result.notes.size(), 2u);
  EXPECT_EQ(report->result.notes[0].rfind("no metric scale: no arm motion", 0), 0u);
  EXPECT_NE(report->result.notes[1].find("mono.run.metric_source = none"), std::string::npos);
  for (const auto& [key, value] : report->result.accuracy) {
    if (key == "targets_sent") EXPECT_EQ(value, 0);
    if (key == "track_error_px_median") EXPECT_LT(value, 2.0);
  }
  EXPECT_FALSE(fs::exists(out + "/overlay.avi"));
}

TEST_F(ButtonTrackingOnly, ExplicitArmWithoutArmPosesIsAnErrorNamingTheFile) {
  StatusOr<RunReport> report =
      Run(*plain_, testing::TempDir("tracking_only_arm"), {Tap(), "mono.run.metric_source=arm"});
  ASSERT_FALSE(report.ok());
  EXPECT_NE(report.status().message().find("arm_poses.txt"), std::string::npos)
      << report.status().ToString();
  StatusOr<RunReport> gt = Run(*plain_, testing::TempDir("tracking_only_gt"),
                               {Tap(), "mono.run.metric_source=ground_truth"});
  ASSERT_FALSE(gt.ok());
  EXPECT_NE(gt.status().message().find("mono.run.metric_source"), std::string::npos);
}

TEST_F(ButtonTrackingOnly, NothingTrackedIsNothingAchieved) {
  // The tap frame alone: the button is found at the tap but never tracked after it.
  const std::string out = testing::TempDir("tracking_only_nothing");
  StatusOr<RunReport> report = Run(*plain_, out, {Tap(), "mono.run.max_frames=1"});
  ASSERT_TRUE(report.ok()) << report.status().ToString();
  EXPECT_EQ(report->result.nothing_achieved.rfind("nothing tracked", 0), 0u)
      << report->result.nothing_achieved;
  EXPECT_NE(ReadAll(report->metrics_path).find("\"failure\""), std::string::npos);
}

}  // namespace
}  // namespace sightline
