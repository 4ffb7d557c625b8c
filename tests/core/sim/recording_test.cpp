// Readers read what the simulator writes (TUM RGB-D, KITTI stereo, image folder), and the same
// seed writes byte-identical recordings.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "core/common/text_file.h"
#include "core/io/dataset.h"
#include "core/sim/simulate.h"
#include "core/sim/simulator.h"
#include "tests/support/test_data.h"

namespace sightline::sim {
namespace {

// FNV-1a hashes of every file below `dir`, by relative path.
std::map<std::string, uint64_t> HashFiles(const std::string& dir) {
  std::map<std::string, uint64_t> hashes;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(dir)) {
    if (!entry.is_regular_file()) continue;
    std::ifstream in(entry.path(), std::ios::binary);
    std::stringstream bytes;
    bytes << in.rdbuf();
    uint64_t h = 1469598103934665603ull;
    for (unsigned char c : bytes.str()) h = (h ^ c) * 1099511628211ull;
    hashes[std::filesystem::relative(entry.path(), dir).string()] = h;
  }
  return hashes;
}

std::vector<std::vector<std::string>> ReadCsv(const std::string& path) {
  std::vector<std::vector<std::string>> rows;
  auto lines = ReadDataLines(path);
  EXPECT_TRUE(lines.ok()) << path;
  if (!lines.ok()) return rows;
  for (const DataLine& line : *lines) rows.push_back(SplitFields(line.text));
  return rows;
}

SimulationOptions SmallCorridor() {
  SimulationOptions o = SimulationOptions::ForScene("corridor");
  o.frames = 4;
  o.sensors = "rgbd,stereo,mono";
  o.stereo.width = 376;  // Small stereo images keep the test fast.
  o.stereo.height = 240;
  o.stereo.focal_px = 300;
  o.mono.width = 320;
  o.mono.height = 240;
  o.mono.focal_px = 262.5;
  return o;
}

TEST(Recording, ReadersReadEverySensorTheSimulatorWrites) {
  const std::string dir = testing::TempDir("sim_rec") + "/corridor";
  const SimulationOptions options = SmallCorridor();
  auto summary = Simulate(options, dir);
  ASSERT_TRUE(summary.ok()) << summary.status().ToString();
  EXPECT_EQ(summary->frames, 4);
  EXPECT_EQ(summary->images, 4 * 5);  // rgb, depth, left, right and mono per frame.
  auto sim = Simulator::Create(options);
  ASSERT_TRUE(sim.ok());

  // RGB-D (TUM): frames, intrinsics, depth in metres, ground truth of the colour camera.
  auto rgbd = OpenDataset(dir, SourceKind::kRgbd);
  ASSERT_TRUE(rgbd.ok()) << rgbd.status().ToString();
  const SourceInfo& info = (*rgbd)->info();
  EXPECT_EQ(info.format, "TUM RGB-D");
  EXPECT_EQ(info.frame_count, 4);
  ASSERT_TRUE(info.camera.has_value());
  EXPECT_DOUBLE_EQ(info.camera->fx, 525);
  EXPECT_DOUBLE_EQ(info.camera->cx, 319.5);
  ASSERT_TRUE(info.rgbd.has_value());
  EXPECT_DOUBLE_EQ(info.rgbd->depth_scale, 5000);
  ASSERT_NE((*rgbd)->ground_truth(), nullptr);
  ASSERT_EQ((*rgbd)->ground_truth()->size(), 4u);
  ASSERT_TRUE((*rgbd)->Seek(2).ok());
  ASSERT_TRUE((*rgbd)->Grab().ok());
  auto frame = (*rgbd)->Retrieve();
  ASSERT_TRUE(frame.ok());
  const RgbdFrame& read = std::get<RgbdFrame>(*frame);
  SimulatedRgbd rendered;
  ASSERT_TRUE(sim->RenderRgbd(2, &rendered).ok());
  EXPECT_EQ(cv::norm(read.color, rendered.color, cv::NORM_INF), 0);
  int compared = 0;
  for (int v = 0; v < read.depth_m.rows; v += 3) {
    for (int u = 0; u < read.depth_m.cols; u += 3) {
      const float written = rendered.depth_m.at<float>(v, u), back = read.depth_m.at<float>(v, u);
      ASSERT_EQ(std::isnan(written), std::isnan(back)) << u << "," << v;
      if (std::isnan(written)) continue;
      ASSERT_NEAR(back, written, 0.5 / 5000 + 1e-6);
      ++compared;
    }
  }
  EXPECT_GT(compared, 10000);
  const Eigen::Isometry3d gt = (*rgbd)->ground_truth()->poses()[2].world_from_sensor;
  EXPECT_TRUE(gt.isApprox(rendered.world_from_camera, 1e-6));

  // Stereo (KITTI): baseline, pairs, poses relative to the first left camera.
  auto stereo = OpenDataset(dir, SourceKind::kStereo);
  ASSERT_TRUE(stereo.ok()) << stereo.status().ToString();
  const SourceInfo& sinfo = (*stereo)->info();
  EXPECT_EQ(sinfo.format, "KITTI odometry");
  EXPECT_EQ(sinfo.frame_count, 4);
  ASSERT_TRUE(sinfo.stereo.has_value());
  EXPECT_NEAR(sinfo.stereo->BaselineM(), options.stereo.baseline_m, 1e-3);
  EXPECT_NEAR(sinfo.stereo->BaselineM(), options.stereo.baseline_m, 1e-9);
  EXPECT_LT(sinfo.stereo->right_from_left.translation().x(), 0);  // Right camera at +x.
  EXPECT_NEAR(sinfo.rate_hz, 30, 1e-3);  // Estimated from times with 6 decimals.
  ASSERT_NE((*stereo)->ground_truth(), nullptr);
  const auto& poses = (*stereo)->ground_truth()->poses();
  ASSERT_EQ(poses.size(), 4u);
  EXPECT_TRUE(poses[0].world_from_sensor.isApprox(Eigen::Isometry3d::Identity(), 1e-9));
  SimulatedStereo s0, s3;
  ASSERT_TRUE(sim->RenderStereo(0, &s0).ok());
  ASSERT_TRUE(sim->RenderStereo(3, &s3).ok());
  EXPECT_TRUE(
      poses[3].world_from_sensor.isApprox(s0.world_from_left.inverse() * s3.world_from_left, 1e-6));
  EXPECT_NEAR(poses[3].time_s, 0.1, 1e-6);
  ASSERT_TRUE((*stereo)->Grab().ok());
  auto pair = (*stereo)->Retrieve();
  ASSERT_TRUE(pair.ok());
  EXPECT_EQ(cv::norm(std::get<StereoFrame>(*pair).right, s0.right, cv::NORM_INF), 0);

  // Mono (image folder): frames, times and intrinsics.
  auto mono = OpenDataset(dir, SourceKind::kMono);
  ASSERT_TRUE(mono.ok()) << mono.status().ToString();
  EXPECT_EQ((*mono)->info().format, "image folder");
  EXPECT_EQ((*mono)->info().frame_count, 4);
  ASSERT_TRUE((*mono)->info().camera.has_value());
  EXPECT_DOUBLE_EQ((*mono)->info().camera->fx, 262.5);
  EXPECT_EQ((*mono)->info().width, 320);

  // Ground truth beside the sensors.
  for (const char* file : {"scene.yaml", "walls.csv", "regions.csv", "people.csv", "odometry.txt",
                           "body_groundtruth.txt"}) {
    EXPECT_TRUE(FileExists(dir + "/" + file)) << file;
  }
  const auto walls = ReadCsv(dir + "/walls.csv");
  ASSERT_EQ(walls.size(), sim->scene().walls.size());
  for (const auto& w : walls) {
    ASSERT_EQ(w.size(), 8u);
    const double a = std::stod(w[5]), b = std::stod(w[6]), c = std::stod(w[7]);
    EXPECT_NEAR(a * a + b * b, 1, 1e-8);
    EXPECT_NEAR(a * std::stod(w[1]) + b * std::stod(w[2]) + c, 0, 1e-5);
  }
  const auto people = ReadCsv(dir + "/people.csv");
  EXPECT_EQ(people.size(), 4u * 2u);  // Two people per frame.
  EXPECT_GT(std::stoi(people[0][6]), 100) << "the leader walks in view";
  auto odometry = ReadTumTrajectory(dir + "/odometry.txt");
  ASSERT_TRUE(odometry.ok());
  EXPECT_EQ(odometry->size(), 4u);
}

TEST(Recording, SameSeedWritesByteIdenticalFilesOtherSeedDiffers) {
  SimulationOptions options = SmallCorridor();
  options.frames = 2;
  options.sensors = "rgbd,stereo";
  const std::string base = testing::TempDir("sim_seed");
  ASSERT_TRUE(Simulate(options, base + "/a").ok());
  ASSERT_TRUE(Simulate(options, base + "/b").ok());
  options.seed = 2;
  ASSERT_TRUE(Simulate(options, base + "/c").ok());
  const auto a = HashFiles(base + "/a"), b = HashFiles(base + "/b"), c = HashFiles(base + "/c");
  ASSERT_GT(a.size(), 15u);
  EXPECT_EQ(a, b);
  for (const char* image :
       {"rgbd/rgb/000001.png", "rgbd/depth/000001.png", "stereo/image_0/000000.png"}) {
    ASSERT_TRUE(a.count(image)) << image;
    EXPECT_NE(a.at(image), c.at(image)) << image;
  }
}

TEST(Recording, PanelWritesButtonsArmPosesAndHandEye) {
  SimulationOptions options = SimulationOptions::ForScene("panel");
  options.frames = 3;
  const std::string dir = testing::TempDir("sim_panel") + "/panel";
  auto summary = Simulate(options, dir);
  ASSERT_TRUE(summary.ok()) << summary.status().ToString();
  EXPECT_EQ(summary->motion, "arm");
  auto mono = OpenDataset(dir);
  ASSERT_TRUE(mono.ok()) << mono.status().ToString();
  EXPECT_EQ((*mono)->info().kind, SourceKind::kMono);
  const auto buttons = ReadCsv(dir + "/buttons.csv");
  ASSERT_EQ(buttons.size(), 3u * 12u);
  for (const auto& row : buttons) {
    ASSERT_EQ(row.size(), 8u);
    // Every button is visible at the start of the approach; at 0.3 m only some.
    if (row[0] == "0") EXPECT_EQ(row[7], "1") << "button " << row[1];
  }
  const auto& target = buttons[2 * 12 + options.panel.target_button];
  EXPECT_EQ(target[7], "1") << "the target stays in view";
  EXPECT_NEAR(std::stod(target[2]), 319.5, 0.01) << "and in the image centre";
  auto arm = ReadTumTrajectory(dir + "/arm_poses.txt");
  ASSERT_TRUE(arm.ok());
  EXPECT_EQ(arm->size(), 3u);
  EXPECT_TRUE(FileExists(dir + "/hand_eye.yaml"));
  EXPECT_FALSE(FileExists(dir + "/odometry.txt"));
  // The arm poses chain to the camera poses: world_from_base * base_from_ee * ee_from_camera.
  auto sim = Simulator::Create(options);
  ASSERT_TRUE(sim.ok());
  const Eigen::Isometry3d camera = sim->motion().world_from_arm_base *
                                   arm->poses()[1].world_from_sensor *
                                   sim->motion().body_from_camera;
  auto gt = ReadTumTrajectory(dir + "/mono/groundtruth.txt");
  ASSERT_TRUE(gt.ok());
  EXPECT_NEAR((camera.translation() - gt->poses()[1].world_from_sensor.translation()).norm(), 0,
              5 * options.arm.pose_noise_m);
}

TEST(Recording, TerrainAt320x240WritesRegions) {
  SimulationOptions options = SimulationOptions::ForScene("terrain");
  options.frames = 2;
  options.rgbd.resolution = "320x240";
  const std::string dir = testing::TempDir("sim_terrain") + "/terrain";
  ASSERT_TRUE(Simulate(options, dir).ok());
  auto rgbd = OpenDataset(dir, SourceKind::kRgbd);
  ASSERT_TRUE(rgbd.ok()) << rgbd.status().ToString();
  EXPECT_EQ((*rgbd)->info().width, 320);
  EXPECT_DOUBLE_EQ((*rgbd)->info().camera->fx, 262.5);
  const auto regions = ReadCsv(dir + "/regions.csv");
  bool ramp = false;
  for (const auto& r : regions) {
    if (r[1] == "ramp") {
      ramp = true;
      EXPECT_DOUBLE_EQ(std::stod(r[2]), options.terrain.ramp_slope_deg);
      EXPECT_EQ(r.size(), 5u + 8u);  // Four polygon corners.
    }
  }
  EXPECT_TRUE(ramp);
}

TEST(Recording, CancelStopsWithReadableFiles) {
  std::atomic<bool> cancel{false};
  SimulationCallbacks callbacks;
  callbacks.cancel = &cancel;
  callbacks.progress = [&](int64_t done, int64_t) {
    if (done == 2) cancel = true;
  };
  SimulationOptions options = SimulationOptions::ForScene("terrain");
  options.frames = 50;
  options.rgbd.resolution = "320x240";
  const std::string dir = testing::TempDir("sim_cancel") + "/terrain";
  auto summary = Simulate(options, dir, callbacks);
  ASSERT_FALSE(summary.ok());
  EXPECT_EQ(summary.status().code(), StatusCode::kCancelled);
  auto rgbd = OpenDataset(dir, SourceKind::kRgbd);
  ASSERT_TRUE(rgbd.ok()) << rgbd.status().ToString();
  EXPECT_EQ((*rgbd)->info().frame_count, 2);
}

}  // namespace
}  // namespace sightline::sim
