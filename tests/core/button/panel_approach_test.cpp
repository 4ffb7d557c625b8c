// The button chain on the simulated panel approach (camera in the arm's hand, true button
// centres known): a tap anywhere on a button selects that button, the tracked centre follows
// the true projection, and the locator finds the button in 3D from points on the panel.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "core/button/button_detector.h"
#include "core/button/button_locator.h"
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
        const cv::Point2d tap = k == 4 ? Pt(c) : cv::Point2d(c.x() + 0.6 * r * std::cos(ang),
                                                             c.y() + 0.6 * r * std::sin(ang));
        ++taps;
        auto region = detector.FindRegion(a.frames[frame].image, tap);
        if (!region.ok()) {
          ADD_FAILURE() << "frame " << frame << " button " << b << " tap " << tap << ": "
                        << region.status().ToString();
          continue;
        }
        const bool ok = NearestButton(a, frame, region->center) == b &&
                        cv::norm(region->center - Pt(c)) < r;
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
  std::printf("model: %zu keypoints, radius %.1f px\n", (*model)->keypoints.size(), (*model)->RadiusPx());
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
    if (std::getenv("VERBOSE")) std::printf("frame %zu: kp %d matches %d inliers %d conf %.2f scale %.2f model %d err %.2f\n", f, t->keypoints, t->matches, t->inliers, t->confidence, t->scale, tracker.model_keypoints(), cv::norm(t->center - Pt(a.Project(int(f), b))));
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

}  // namespace
}  // namespace sightline
