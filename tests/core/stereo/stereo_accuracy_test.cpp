// End-to-end accuracy of the stereo odometry against ground truth: kitti_clip1 (bounds set to
// beat libviso2's figures on the same clip), the subsampling sweep, EuRoC's static sequence (no
// false motion) and the simulator's corridor with turns.
#include <gtest/gtest.h>

#include <filesystem>
#include <map>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "core/eval/subsample_sweep.h"
#include "core/pipeline/stereo_vo_pipeline.h"
#include "core/sim/simulate.h"
#include "tests/support/test_data.h"

namespace sightline {
namespace {

std::map<std::string, double> Figures(const StereoVoRun& run) {
  std::vector<std::string> notes;
  std::map<std::string, double> m;
  for (const auto& [key, value] : StereoVoAccuracy(run, 0.02, &notes)) m[key] = value;
  return m;
}

// The simulator's corridor seen by its stereo rig only (people walking unless changed).
sim::SimulationOptions Corridor(int frames, double rate_hz, double speed_mps) {
  sim::SimulationOptions options = sim::SimulationOptions::ForScene("corridor");
  options.frames = frames;
  options.rate_hz = rate_hz;
  options.motion.speed_mps = speed_mps;
  options.sensors = "stereo";
  return options;
}

// Simulates `options` into a fresh temp folder named after `name` and returns the folder.
StatusOr<std::string> Simulated(const sim::SimulationOptions& options, const std::string& name) {
  const std::string dir = testing::TempDir(name);
  SIGHTLINE_RETURN_IF_ERROR(sim::Simulate(options, dir).status());
  return dir;
}

int GatedFrames(const StereoVoRun& run) {
  int n = 0;
  for (const FrameStats& s : run.frames) n += s.gated ? 1 : 0;
  return n;
}

TEST(StereoAccuracy, KittiClipBeatsLibviso2) {
  SIGHTLINE_REQUIRE_DATA(path, "kitti_clip1");
  StatusOr<StereoVoRun> run = RunStereoOdometry(path, {}, {});
  ASSERT_TRUE(run.ok()) << run.status().ToString();
  ASSERT_EQ(run->frames.size(), 51u);
  EXPECT_EQ(GatedFrames(*run), 0);
  std::map<std::string, double> m = Figures(*run);
  // libviso2 on this clip: 0.69 %, 1.06 %, 0.120 m, 1.07 %.
  EXPECT_LE(m["length_error_pct"], 0.5);
  EXPECT_LE(m["endpoint_error_pct"], 0.8);
  EXPECT_LE(m["ate_rmse_m"], 0.10);
  EXPECT_LE(m["rpe_trans_pct"], 0.9);
  EXPECT_TRUE(m.count("kitti_t_err_pct"));
  for (const auto& [k, v] : m) std::cout << "kitti_clip1 " << k << " = " << v << "\n";
}

// Motion against keyframes (stereo.keyframe.enabled, off by default: it does not improve every
// figure) keeps the kitti_clip1 bounds and shows no false motion on EuRoC's static sequence.
TEST(StereoAccuracy, KeyframeModeKeepsKittiBoundsAndStaticStill) {
  SIGHTLINE_REQUIRE_DATA(kitti, "kitti_clip1");
  SIGHTLINE_REQUIRE_DATA(euroc, "euroc_v1_01_static");
  StereoOdometryOptions options;
  options.keyframe.enabled = true;
  StatusOr<StereoVoRun> run = RunStereoOdometry(kitti, options, {});
  ASSERT_TRUE(run.ok()) << run.status().ToString();
  ASSERT_EQ(run->frames.size(), 51u);
  EXPECT_EQ(GatedFrames(*run), 0);
  std::map<std::string, double> m = Figures(*run);
  EXPECT_LE(m["length_error_pct"], 0.5);
  EXPECT_LE(m["endpoint_error_pct"], 0.8);
  EXPECT_LE(m["ate_rmse_m"], 0.10);
  EXPECT_LE(m["rpe_trans_pct"], 0.9);
  for (const auto& [k, v] : m) std::cout << "kitti_clip1 keyframes " << k << " = " << v << "\n";

  run = RunStereoOdometry(euroc, options, {});
  ASSERT_TRUE(run.ok()) << run.status().ToString();
  m = Figures(*run);
  ASSERT_TRUE(m.count("static_translation_m"));
  EXPECT_LT(m["static_translation_m"], 0.005);
  EXPECT_LT(m["static_rotation_deg"], 0.2);
}

TEST(StereoAccuracy, KittiClipSubsamplingSweepStaysUnder1p5Percent) {
  SIGHTLINE_REQUIRE_DATA(path, "kitti_clip1");
  std::vector<SubsampleEstimate> estimates;
  std::optional<Trajectory> gt;
  for (int k = 1; k <= 5; ++k) {
    StereoVoRunOptions run_options;
    run_options.subsample = k;
    StatusOr<StereoVoRun> run = RunStereoOdometry(path, {}, run_options);
    ASSERT_TRUE(run.ok()) << run.status().ToString();
    estimates.push_back({k, run->estimate});
    gt = run->ground_truth;
  }
  ASSERT_TRUE(gt);
  StatusOr<std::vector<SubsampleRow>> table = EvaluateSubsampleSweep(estimates, *gt, 0.02);
  ASSERT_TRUE(table.ok()) << table.status().ToString();
  std::cout << FormatSubsampleTable(*table);
  // The goal is < 1.5 % at every k = 1..5. Measured with the online disparity offset
  // (stereo.disparity_offset, 0.2-0.25 px on this clip): 0.33, 0.34, 0.18, 0.21, 0.06 %
  // (without it 0.42, 0.64, 1.01, 1.25, 1.92 %, too long: far points came out too far, and at
  // large k the surviving inliers are far; median inlier depth ~20 m at k = 1, 50-65 m at k = 5).
  for (const SubsampleRow& row : *table) {
    EXPECT_LT(row.length_error_pct, 1.5) << "k = " << row.factor;
  }
}

TEST(StereoAccuracy, EurocStaticShowsNoFalseMotion) {
  SIGHTLINE_REQUIRE_DATA(path, "euroc_v1_01_static");
  StatusOr<StereoVoRun> run = RunStereoOdometry(path, {}, {});
  ASSERT_TRUE(run.ok()) << run.status().ToString();
  std::map<std::string, double> m = Figures(*run);
  ASSERT_TRUE(m.count("static_translation_m"));
  std::cout << "euroc static: " << run->frames.size() << " frames, "
            << m["static_translation_m"] * 1000 << " mm, " << m["static_rotation_deg"] << " deg\n";
  EXPECT_LT(m["static_translation_m"], 0.005);
  EXPECT_LT(m["static_rotation_deg"], 0.2);
}

TEST(StereoAccuracy, SimulatedCorridorWithTurns) {
  // 300 frames at 10 Hz, 1 m/s: about 30 m around the corridor loop's corners.
  StatusOr<std::string> dir = Simulated(Corridor(300, 10, 1.0), "stereo_corridor");
  ASSERT_TRUE(dir.ok()) << dir.status().ToString();
  StatusOr<StereoVoRun> run = RunStereoOdometry(*dir, {}, {});
  ASSERT_TRUE(run.ok()) << run.status().ToString();
  ASSERT_TRUE(run->ground_truth);
  std::map<std::string, double> m = Figures(*run);
  ASSERT_TRUE(m.count("kitti_r_err_deg_per_100m"));
  for (const auto& [k, v] : m) std::cout << "corridor " << k << " = " << v << "\n";
  std::cout << "corridor gated frames: " << GatedFrames(*run) << ", gt length "
            << run->ground_truth->LengthM() << " m\n";
  EXPECT_LT(m["kitti_t_err_pct"], 0.5);
  // The goal is < 0.5 deg/100 m. Measured 0.38 with tracks aligned against their anchors
  // (stereo.anchor; patches warped as the surface their neighbours show), the window's fixed
  // observing frames (stereo.window.fixed_frames) and no centre weighting; seeds 1-6 of this
  // corridor: mean 0.40, largest 0.45. Before, with frame-to-frame tracks that drift and a
  // centre-weighted window: 0.70 (seeds 1-6 mean 0.72, largest 0.90).
  EXPECT_LT(m["kitti_r_err_deg_per_100m"], 0.5);
}

// The corridor's 90 deg corners (95 deg/s) seen at 2 and 2.5 Hz, as every 5th and 4th frame of a
// 10 Hz camera: the sharpest pair turns 47.7 deg (38.2 at 2.5 Hz), and KLT started from the
// constant-motion prediction loses most tracks where a turn begins or ends. The turn search
// (stereo.tracking.turn_search_*) finds the rotation from the images and tracks again from it.
// Measured on `simulate corridor --frames 400 --set sim.rate_hz=10` with --subsample 5: ATE
// 0.027 m over 39.5 m (3.9 m without the search, two pairs gated), with --subsample 4 0.014 m
// (2.5 m, one pair gated).
TEST(StereoAccuracy, SimulatedCorridorAtTwoHertzHoldsThroughItsSharpestTurns) {
  for (const double rate_hz : {2.0, 2.5}) {
    StatusOr<std::string> dir =
        Simulated(Corridor(static_cast<int>(40 * rate_hz), rate_hz, 1.0), "stereo_corridor_2hz");
    ASSERT_TRUE(dir.ok()) << dir.status().ToString();
    StereoOdometryOptions without;
    without.tracking.turn_search_fraction = 0;
    for (const bool search : {true, false}) {
      StatusOr<StereoVoRun> run =
          RunStereoOdometry(*dir, search ? StereoOdometryOptions() : without, {});
      ASSERT_TRUE(run.ok()) << run.status().ToString();
      ASSERT_TRUE(run->ground_truth);
      std::map<std::string, double> m = Figures(*run);
      int searched = 0;
      for (const FrameStats& f : run->frames) searched += f.turn_searched ? 1 : 0;
      std::cout << rate_hz << " Hz, turn search " << (search ? "on" : "off") << ": ATE "
                << m["ate_rmse_m"] << " m, length error " << m["length_error_pct"] << " %, "
                << GatedFrames(*run) << " gated, " << searched << " searched\n";
      if (search) {
        EXPECT_EQ(GatedFrames(*run), 0) << rate_hz;
        EXPECT_LT(m["ate_rmse_m"], 0.1) << rate_hz;
        EXPECT_LT(m["length_error_pct"], 2.0) << rate_hz;
        EXPECT_GE(searched, 2) << rate_hz;  // At least one per corner.
      } else {
        EXPECT_GT(m["ate_rmse_m"], 0.5) << rate_hz;  // What the search prevents.
        EXPECT_EQ(searched, 0);
      }
    }
  }
}

// A rig whose disparities are all 0.3 px too small (both images of every pair shifted 0.15 px
// apart), on the corridor with a 90 deg turn: the online disparity offset finds it and keeps the
// length right; without it the length comes out too long.
TEST(StereoAccuracy, SimulatedCorridorWithADisparityOffsetIsCorrected) {
  StatusOr<std::string> simulated = Simulated(Corridor(200, 10, 1.0), "stereo_corridor_offset");
  ASSERT_TRUE(simulated.ok()) << simulated.status().ToString();
  const std::string& dir = *simulated;
  int shifted = 0;
  for (const char* camera : {"image_0", "image_1"}) {
    const double dx = std::string(camera) == "image_0" ? -0.15 : 0.15;
    for (const auto& e : std::filesystem::directory_iterator(dir + "/stereo/" + camera)) {
      const cv::Mat image = cv::imread(e.path().string(), cv::IMREAD_UNCHANGED);
      ASSERT_FALSE(image.empty()) << e.path();
      cv::Mat out;
      const cv::Mat m = (cv::Mat_<double>(2, 3) << 1, 0, dx, 0, 1, 0);
      cv::warpAffine(image, out, m, image.size(), cv::INTER_CUBIC, cv::BORDER_REPLICATE);
      ASSERT_TRUE(cv::imwrite(e.path().string(), out));
      ++shifted;
    }
  }
  ASSERT_EQ(shifted, 400);
  auto length_error = [&](bool enabled, double* offset_px) {
    StereoOdometryOptions vo;
    vo.disparity_offset.enabled = enabled;
    StatusOr<StereoVoRun> run = RunStereoOdometry(dir, vo, {});
    EXPECT_TRUE(run.ok()) << run.status().ToString();
    if (!run.ok() || !run->ground_truth) return 100.0;
    EXPECT_EQ(GatedFrames(*run), 0);
    *offset_px = run->frames.back().disparity_offset_px;
    std::map<std::string, double> m = Figures(*run);
    EXPECT_TRUE(m.count("length_error_pct"));
    if (!m.count("length_error_pct")) return 100.0;
    std::cout << "corridor with offset, estimator " << (enabled ? "on" : "off") << ": length "
              << m["length_error_pct"] << " %, t_err " << m["kitti_t_err_pct"] << " %, r_err "
              << m["kitti_r_err_deg_per_100m"] << " deg/100 m, offset " << *offset_px << " px\n";
    return m["length_error_pct"];
  };
  double offset_on = 0, offset_off = 0;
  const double on = length_error(true, &offset_on);
  const double off = length_error(false, &offset_off);
  EXPECT_NEAR(offset_on, 0.3, 0.1);
  EXPECT_EQ(offset_off, 0.0);
  EXPECT_LT(on, 0.5);
  EXPECT_GT(off, 2 * on);
}

// The same corridor at the simulator's walking pace (0.5 m/s, 600 frames, 30 m): twice the frames
// per metre, so per-frame errors weigh twice as much. The window keeps a frame only once the
// camera has moved 5 % of its points' median depth (stereo.window.min_parallax), so its frames
// stay far enough apart, and anchored tracks do not drift over the many frames between them.
// Measured 0.35 deg/100 m (0.77 before anchored tracks, 4.1 without the window).
TEST(StereoAccuracy, SimulatedCorridorAtWalkingPace) {
  StatusOr<std::string> dir = Simulated(Corridor(600, 10, 0.5), "stereo_corridor_slow");
  ASSERT_TRUE(dir.ok()) << dir.status().ToString();
  StatusOr<StereoVoRun> run = RunStereoOdometry(*dir, {}, {});
  ASSERT_TRUE(run.ok()) << run.status().ToString();
  ASSERT_TRUE(run->ground_truth);
  std::map<std::string, double> m = Figures(*run);
  ASSERT_TRUE(m.count("kitti_r_err_deg_per_100m"));
  std::cout << "slow corridor: t_err " << m["kitti_t_err_pct"] << " %, r_err "
            << m["kitti_r_err_deg_per_100m"] << " deg/100 m, ATE " << m["ate_rmse_m"] << " m, "
            << GatedFrames(*run) << " gated\n";
  EXPECT_EQ(GatedFrames(*run), 0);
  EXPECT_LT(m["kitti_t_err_pct"], 0.5);
  EXPECT_LT(m["kitti_r_err_deg_per_100m"], 0.5);
}

// A rig without disparity offset at a live camera's rate (25 Hz, 0.5 m/s): the offset estimate
// must not invent one. Tracks followed over the 15 frames it takes here to reach the parallax a
// measurement needs drift, and their drift read as -0.2 px (path 0.61 % too long) before pairs
// were limited to stereo.disparity_offset.max_span_frames (8); now nothing is applied (0.12 %).
TEST(StereoAccuracy, NoDisparityOffsetIsInventedAtALiveCamerasRate) {
  sim::SimulationOptions options = Corridor(100, 25, 0.5);
  options.corridor.people = 0;
  StatusOr<std::string> dir = Simulated(options, "stereo_corridor_25hz");
  ASSERT_TRUE(dir.ok()) << dir.status().ToString();
  StatusOr<StereoVoRun> run = RunStereoOdometry(*dir, {}, {});
  ASSERT_TRUE(run.ok()) << run.status().ToString();
  double largest_offset = 0;
  for (const FrameStats& s : run->frames) {
    largest_offset = std::max(largest_offset, std::abs(s.disparity_offset_px));
  }
  std::map<std::string, double> m = Figures(*run);
  std::cout << "25 Hz corridor: largest applied offset " << largest_offset << " px, length error "
            << m["length_error_pct"] << " %\n";
  EXPECT_LT(largest_offset, 0.05);
  EXPECT_LT(m["length_error_pct"], 0.3);
}

}  // namespace
}  // namespace sightline
