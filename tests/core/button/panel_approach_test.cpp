// The button chain on the simulated panel approach (camera in the arm's hand, true button
// centres known): a tap anywhere on a button selects that button, the tracked centre follows
// the true projection, and the locator finds the button in 3D from points on the panel.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "core/button/button_detector.h"
#include "core/button/button_locator.h"
#include "core/button/button_picker.h"
#include "core/button/button_tracker.h"
#include "tests/core/button/panel_sim_util.h"

namespace sightline {
namespace {

using testing::PanelApproach;

const PanelApproach& Approach() {
  static const PanelApproach approach = testing::RenderPanelApproach();
  return approach;
}

cv::Point2d Pt(const Eigen::Vector2d& p) { return {p.x(), p.y()}; }

// The button whose true centre is nearest a pixel in a frame.
int NearestButton(const PanelApproach& a, int frame, cv::Point2d at) {
  int best = -1;
  double best_d = 1e9;
  for (int b = 0; b < int(a.buttons.size()); ++b) {
    const Eigen::Vector2d p = a.Project(frame, b);
    const double d = std::hypot(p.x() - at.x, p.y() - at.y);
    if (d < best_d) best_d = d, best = b;
  }
  return best;
}

TEST(PanelApproach, TapAnywhereOnAButtonSelectsIt) {
  const PanelApproach& a = Approach();
  ASSERT_GT(a.frames.size(), 100u);
  ButtonDetector detector;
  int taps = 0, selected = 0;
  for (int frame : {0, 60, 120}) {
    for (int b = 0; b < int(a.buttons.size()); ++b) {
      const Eigen::Vector2d c = a.Project(frame, b);
      const double r = a.RadiusPx(frame, b);
      if (c.x() < r || c.y() < r || c.x() > 639 - r || c.y() > 479 - r) continue;
      // The centre and four points at 60 % of the radius.
      for (int k = 0; k < 5; ++k) {
        const double ang = k * M_PI / 2 + 0.3;
        const cv::Point2d tap =
            k == 4 ? Pt(c)
                   : cv::Point2d(c.x() + 0.6 * r * std::cos(ang), c.y() + 0.6 * r * std::sin(ang));
        ++taps;
        auto region = detector.FindRegion(a.frames[frame].image, tap);
        if (!region.ok()) {
          ADD_FAILURE() << "frame " << frame << " button " << b << " tap " << tap << ": "
                        << region.status().ToString();
          continue;
        }
        const bool ok =
            NearestButton(a, frame, region->center) == b && cv::norm(region->center - Pt(c)) < r;
        selected += ok ? 1 : 0;
        EXPECT_TRUE(ok) << "frame " << frame << " button " << b << " tap " << tap
                        << " region centre " << region->center << " true " << Pt(c);
      }
    }
  }
  EXPECT_GT(taps, 50);
  EXPECT_EQ(selected, taps);
}

TEST(PanelApproach, TrackedCentreStaysWithinThreePixels) {
  const PanelApproach& a = Approach();
  const int b = a.target_button;
  ASSERT_GE(b, 0);
  auto model = ButtonDetector().Detect(a.frames[0].image, Pt(a.Project(0, b)));
  ASSERT_TRUE(model.ok()) << model.status().ToString();
  std::printf("model: %zu keypoints, radius %.1f px\n", (*model)->keypoints.size(),
              (*model)->RadiusPx());
  ButtonTracker tracker(*model);
  std::vector<double> errors;
  for (size_t f = 1; f < a.frames.size(); ++f) {
    // The prediction a SLAM pose gives: the button's projection (here the true pose) with a
    // few pixels of error.
    TrackPrediction p;
    p.valid = true;
    p.center = Pt(a.Project(int(f), b)) + cv::Point2d(4, -3);
    p.scale = a.RadiusPx(int(f), b) / a.RadiusPx(0, b);
    auto t = tracker.Track(a.frames[f].image, p);
    ASSERT_TRUE(t.ok()) << t.status().ToString();
    if (std::getenv("VERBOSE"))
      std::printf("frame %zu: kp %d matches %d inliers %d conf %.2f scale %.2f model %d err %.2f\n",
                  f, t->keypoints, t->matches, t->inliers, t->confidence, t->scale,
                  tracker.model_keypoints(), cv::norm(t->center - Pt(a.Project(int(f), b))));
    ASSERT_TRUE(t->found) << "frame " << f << ": " << t->reason;
    errors.push_back(cv::norm(t->center - Pt(a.Project(int(f), b))));
  }
  std::vector<double> sorted = errors;
  std::sort(sorted.begin(), sorted.end());
  const double max_err = sorted.back();
  std::printf("track error over %zu frames: median %.2f px, max %.2f px\n", sorted.size(),
              sorted[sorted.size() / 2], max_err);
  EXPECT_LT(max_err, 3.0);
}

// A stand-in for the SLAM's map: points from the exact depth of a few frames, 1 mm noise and
// 10 % outliers, in the map frame.
std::shared_ptr<const std::vector<Eigen::Vector3d>> StandInMap(const PanelApproach& a) {
  auto points = std::make_shared<std::vector<Eigen::Vector3d>>();
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> unit(0, 1);
  std::normal_distribution<double> noise(0, 0.001);
  for (size_t f = 0; f < a.frames.size(); f += 30) {
    const cv::Mat& depth = a.frames[f].depth_m;
    for (int k = 0; k < 1500; ++k) {
      const int u = int(unit(rng) * depth.cols), v = int(unit(rng) * depth.rows);
      const float z = depth.at<float>(v, u);
      if (!std::isfinite(z)) continue;
      Eigen::Vector3d x =
          a.camera.Unproject(u, v, z) + Eigen::Vector3d(noise(rng), noise(rng), noise(rng));
      if (unit(rng) < 0.1) x *= 0.7 + 0.6 * unit(rng);
      points->push_back(a.frames[f].world_from_camera * x);
    }
  }
  return points;
}

struct ApproachRun {
  int targets = 0;
  int first_target_frame = -1;
  int lost = 0;
  double final_error_mm = -1;
  std::vector<double> approach_error_deg;  // Per target, against the true push direction.
  int approach_within_3_sigma = 0;         // Targets whose stated approach sigma covers it.
  std::vector<std::string> reasons;        // Gate reason key per frame.
};

// Tap at frame 0 on the target button, Yes, then every frame with the true pose as the SLAM's.
ApproachRun RunApproach(const PanelApproach& a, bool scale_converged, double age_s,
                        int stop_at = -1) {
  ApproachRun run;
  const int b = a.target_button;
  ButtonPicker picker;
  EXPECT_TRUE(picker.Tap(a.frames[0].image, Pt(a.Project(0, b)), 0).ok());
  picker.Confirm();
  SlamView slam;
  slam.camera = a.camera;
  slam.map_points_in_world = StandInMap(a);
  slam.scale_converged = scale_converged;
  slam.scale_sigma_rel = 0.002;
  slam.tracking = true;
  const Eigen::Vector3d truth_in_base = a.world_from_base.inverse() * a.buttons[b].center;
  for (size_t f = 1; f < a.frames.size(); ++f) {
    if (int(f) == stop_at) picker.Stop();
    slam.camera_from_world = a.frames[f].world_from_camera.inverse();
    const Eigen::Isometry3d base_from_camera =
        a.world_from_base.inverse() * a.frames[f].world_from_camera;
    const double stamp = f / 30.0;
    const PickerFrame out =
        picker.Process(int64_t(f), stamp, a.frames[f].image, slam, base_from_camera, stamp + age_s);
    run.reasons.push_back(GateReasonKey(out.verdict.reason));
    if (std::getenv("VERBOSE") && f % 20 == 1)
      std::printf("frame %zu: %s (%s)\n", f, out.verdict.message.c_str(),
                  PickerStateKey(out.state));
    run.lost += out.track.found ? 0 : 1;
    if (out.target) {
      ++run.targets;
      if (run.first_target_frame < 0) run.first_target_frame = int(f);
      run.final_error_mm = (out.target->position_m - truth_in_base).norm() * 1e3;
      const Eigen::Vector3d push = -(a.world_from_base.linear().transpose() * a.buttons[b].normal);
      const double angle =
          std::acos(std::clamp(out.target->approach.dot(push.normalized()), -1.0, 1.0)) * 180 /
          M_PI;
      run.approach_error_deg.push_back(angle);
      if (std::getenv("VERBOSE") && f % 20 == 1)
        std::printf("frame %zu: approach (%.4f %.4f %.4f) sigma %.2f deg\n", f,
                    out.target->approach.x(), out.target->approach.y(), out.target->approach.z(),
                    out.target->approach_sigma_deg);
      run.approach_within_3_sigma += angle <= 3 * out.target->approach_sigma_deg;
      EXPECT_EQ(out.target->frame_id, "arm_base");
      EXPECT_EQ(out.target->source_frames.back(), int64_t(f));
    }
  }
  return run;
}

TEST(PanelApproach, TheChainSendsTargetsWithinThreeMillimetresWithTheTruePose) {
  const PanelApproach& a = Approach();
  const ApproachRun run = RunApproach(a, true, 0.03);
  std::printf(
      "picker on the simulated approach: %d targets in %zu frames, first at frame %d after "
      "the tap, final 3D error %.2f mm in the arm base frame\n",
      run.targets, a.frames.size() - 1, run.first_target_frame, run.final_error_mm);
  EXPECT_EQ(run.lost, 0);
  EXPECT_EQ(run.first_target_frame, 1);
  EXPECT_GT(run.targets, int(a.frames.size()) * 9 / 10);
  EXPECT_GE(run.final_error_mm, 0);
  EXPECT_LT(run.final_error_mm, 3.0);
}

TEST(PanelApproach, TheApproachIsThePanelNormalWithinTwoDegreesAndHonest) {
  const PanelApproach& a = Approach();
  const ApproachRun run = RunApproach(a, true, 0.03);
  ASSERT_GT(run.approach_error_deg.size(), a.frames.size() * 9 / 10);
  std::vector<double> sorted = run.approach_error_deg;
  std::sort(sorted.begin(), sorted.end());
  std::printf(
      "approach error over %zu targets: median %.2f deg, max %.2f deg, final %.2f deg, "
      "%d within 3 sigma\n",
      sorted.size(), sorted[sorted.size() / 2], sorted.back(), run.approach_error_deg.back(),
      run.approach_within_3_sigma);
  EXPECT_LT(sorted[sorted.size() / 2], 1.0);
  EXPECT_LT(sorted.back(), 2.0);
  // Frame to frame the direction barely moves (it is averaged in data time).
  for (size_t i = 1; i < run.approach_error_deg.size(); ++i) {
    EXPECT_LT(std::abs(run.approach_error_deg[i] - run.approach_error_deg[i - 1]), 0.5) << i;
  }
  EXPECT_GE(run.approach_within_3_sigma, int(0.95 * run.approach_error_deg.size()));
}

TEST(PanelApproach, NoTargetWithoutScaleWhenStaleOrAfterStop) {
  const PanelApproach& a = Approach();
  const ApproachRun unscaled = RunApproach(a, false, 0.03);
  EXPECT_EQ(unscaled.targets, 0);
  EXPECT_EQ(unscaled.reasons[10], "scale_not_converged");
  const ApproachRun stale = RunApproach(a, true, 0.5);
  EXPECT_EQ(stale.targets, 0);
  EXPECT_EQ(stale.reasons[10], "stale");
  const ApproachRun stopped = RunApproach(a, true, 0.03, 50);
  // reasons[i] is frame i + 1: frames 1..49 before STOP, 50.. after.
  const int sent_before =
      int(std::count(stopped.reasons.begin(), stopped.reasons.begin() + 49, "send"));
  EXPECT_GT(sent_before, 40);
  EXPECT_EQ(stopped.targets, sent_before);
  for (size_t i = 49; i < stopped.reasons.size(); ++i) EXPECT_EQ(stopped.reasons[i], "stopped");
}

}  // namespace
}  // namespace sightline
