// The detector on drawn panels: a tap on a button selects it, a tap on blank wall gives
// "no button here", bad input gives a clear status.
#include "core/button/button_detector.h"

#include <gtest/gtest.h>

#include <opencv2/imgproc.hpp>

#include "tests/core/button/panel_sim_util.h"

namespace sightline {
namespace {

// A grey wall with a 3 x 2 grid of round textured buttons (radius 22 px, pitch 80 px) at
// x = 200, 280 and y = 140, 220, 300.
cv::Mat DrawnPanel() {
  cv::Mat image(480, 640, CV_8UC3, cv::Scalar(120, 120, 120));
  cv::rectangle(image, {150, 90, 180, 260}, cv::Scalar(170, 170, 175), cv::FILLED);
  int label = 0;
  for (int y : {140, 220, 300}) {
    for (int x : {200, 280}) {
      cv::circle(image, {x, y}, 22, cv::Scalar(60, 60, 60), cv::FILLED, cv::LINE_AA);
      cv::circle(image, {x, y}, 18, cv::Scalar(220, 220, 220), cv::FILLED, cv::LINE_AA);
      cv::putText(image, std::to_string(label++), {x - 8, y + 8}, cv::FONT_HERSHEY_SIMPLEX, 0.8,
                  cv::Scalar(20, 20, 20), 2, cv::LINE_AA);
    }
  }
  return image;
}

// Taps at the centre and 0.6 radii off it. The seed's rule finds the button's outline from
// all of them; the multiscale method does from the centre, and from off-centre taps at times
// a smaller region on the button around the tap (its centroid still on the tapped button).
void ExpectTapsSelectButtons(const ButtonDetectorOptions& options) {
  const cv::Mat image = DrawnPanel();
  ButtonDetector detector(options);
  for (int y : {140, 220, 300}) {
    for (int x : {200, 280}) {
      for (cv::Point2d offset : {cv::Point2d(0, 0), cv::Point2d(12, 5), cv::Point2d(-8, -12)}) {
        auto model = detector.Detect(image, cv::Point2d(x, y) + offset);
        ASSERT_TRUE(model.ok()) << model.status().ToString();
        const bool exact = options.method == "seed" || offset == cv::Point2d(0, 0);
        EXPECT_LT(cv::norm((*model)->center - cv::Point2d(x, y)), exact ? 3.0 : 15.0)
            << options.method << " " << x << "," << y << " offset " << offset;
        if (exact) EXPECT_NEAR((*model)->RadiusPx(), 22, 4);
        EXPECT_GE((*model)->keypoints.size(), 3u);
        EXPECT_EQ((*model)->descriptors.rows, int((*model)->keypoints.size()));
      }
    }
  }
}

TEST(ButtonDetector, TapOnAButtonSelectsIt) {
  ButtonDetectorOptions multiscale;
  multiscale.method = "multiscale";
  ExpectTapsSelectButtons(multiscale);
}

TEST(ButtonDetector, SeedRuleTapOnAButtonSelectsIt) {
  ButtonDetectorOptions seed;
  seed.method = "seed";
  ExpectTapsSelectButtons(seed);
}

// The first frame of the simulated panel at twelve seeds: a tap 2 px off any button's true
// centre (radius about 9.5 px) selects that button, not the plate holding all of them (whose
// centroid can lie, relative to its size, nearer the tap than the small button's own). Both
// methods.
TEST(ButtonDetector, TapOnASimulatedPanelSelectsTheButtonNotThePlate) {
  int taps = 0;
  for (int seed = 1; seed <= 12; ++seed) {
    const testing::PanelApproach a = testing::RenderPanelApproach(1, 1, seed);
    ASSERT_EQ(a.frames.size(), 1u);
    for (const char* method : {"seed", "multiscale"}) {
      ButtonDetectorOptions options;
      options.method = method;
      const ButtonDetector detector(options);
      for (int b = 0; b < int(a.buttons.size()); ++b) {
        const Eigen::Vector2d c = a.Project(0, b);
        const double r = a.RadiusPx(0, b);
        if (c.x() < 20 || c.y() < 20 || c.x() > 620 || c.y() > 460) continue;
        ++taps;
        auto region = detector.FindRegion(a.frames[0].image, {c.x() + 1.5, c.y() - 1.5});
        ASSERT_TRUE(region.ok()) << "seed " << seed << " " << method << " button " << b << ": "
                                 << region.status().ToString();
        EXPECT_LT(cv::norm(region->center - cv::Point2d(c.x(), c.y())), 0.5 * r)
            << "seed " << seed << " " << method << " button " << b;
        // The button's ring, its face or (on two-character labels) the label's outline.
        EXPECT_NEAR(region->RadiusPx(), r, 0.5 * r)
            << "seed " << seed << " " << method << " button " << b;
      }
    }
  }
  EXPECT_GE(taps, 12 * 2 * 10);
}

TEST(ButtonDetector, TheCallersImageIsNeverTouched) {
  // A grey frame at the working size is searched without a resized copy: the detector must
  // still blur its own pixels, not the caller's (the tracker describes the frame afterwards).
  cv::Mat panel;
  cv::cvtColor(DrawnPanel(), panel, cv::COLOR_BGR2GRAY);
  for (const char* method : {"multiscale", "seed"}) {
    for (int working : {640, 480}) {
      ButtonDetectorOptions o;
      o.method = method;
      o.working_size_px = working;
      const cv::Mat before = panel.clone();
      ASSERT_TRUE(ButtonDetector(o).Detect(panel, {200, 140}).ok()) << method;
      ASSERT_TRUE(ButtonDetector(o).FindRegion(panel, {280, 220}).ok()) << method;
      EXPECT_EQ(cv::norm(panel, before, cv::NORM_INF), 0) << method << " at " << working;
    }
  }
}

TEST(ButtonDetector, TapOnBlankWallIsNoButtonHere) {
  ButtonDetector detector;
  auto model = detector.Detect(DrawnPanel(), {520, 400});
  ASSERT_FALSE(model.ok());
  EXPECT_EQ(model.status().code(), StatusCode::kNotFound);
  EXPECT_NE(model.status().message().find("no button here"), std::string::npos);
}

// Three flat keys on a noisy plate (sigma 2.5 grey levels) whose only outline is a 2 px rim 16
// levels darker: too faint for the contour step's Canny thresholds (at 20 levels it finds
// them), not for the radial outlines.
cv::Mat FaintKeys() {
  cv::Mat noise(480, 640, CV_32F);
  cv::RNG rng(5);
  rng.fill(noise, cv::RNG::NORMAL, 128, 2.5);
  cv::Mat image;
  noise.convertTo(image, CV_8U);
  for (int x : {200, 320, 440}) {
    cv::circle(image, {x, 240}, 30, cv::Scalar(112), 2, cv::LINE_AA);
    cv::putText(image, std::to_string(x / 100), {x - 7, 248}, cv::FONT_HERSHEY_SIMPLEX, 0.6,
                cv::Scalar(110), 1, cv::LINE_AA);
  }
  return image;
}

TEST(ButtonDetector, AFaintRimTheContoursBreakIsClosedByTheRadialOutline) {
  ButtonDetectorOptions o;
  o.method = "multiscale";
  o.radial = false;
  for (int x : {200, 320, 440}) {
    EXPECT_EQ(ButtonDetector(o).FindRegion(FaintKeys(), {x + 3.0, 236}).status().code(),
              StatusCode::kNotFound)
        << x;
  }
  o.radial = true;
  for (int x : {200, 320, 440}) {
    const auto region = ButtonDetector(o).FindRegion(FaintKeys(), {x + 3.0, 236});
    ASSERT_TRUE(region.ok()) << x << ": " << region.status().message();
    EXPECT_LT(cv::norm(region->center - cv::Point2d(x, 240)), 2.5) << x;
    EXPECT_NEAR(region->RadiusPx(), 30, 3) << x;
  }
  // Between the keys: nothing.
  EXPECT_EQ(ButtonDetector(o).FindRegion(FaintKeys(), {260, 240}).status().code(),
            StatusCode::kNotFound);
  EXPECT_EQ(ButtonDetector(o).FindRegion(FaintKeys(), {320, 400}).status().code(),
            StatusCode::kNotFound);
}

TEST(ButtonDetector, BadInputIsAClearStatus) {
  ButtonDetector detector;
  EXPECT_EQ(detector.Detect(cv::Mat(), {1, 1}).status().code(), StatusCode::kInvalidArgument);
  auto outside = detector.Detect(DrawnPanel(), {700, 10});
  EXPECT_EQ(outside.status().code(), StatusCode::kInvalidArgument);
  EXPECT_NE(outside.status().message().find("outside"), std::string::npos);
  EXPECT_EQ(detector.Detect(cv::Mat(10, 10, CV_32FC1), {1, 1}).status().code(),
            StatusCode::kInvalidArgument);
  ButtonDetectorOptions o;
  o.canny_high = 10;  // Below canny_low.
  std::string error;
  EXPECT_FALSE(o.IsValid(&error));
  EXPECT_NE(error.find("canny"), std::string::npos);
  EXPECT_EQ(ButtonDetector(o).Detect(DrawnPanel(), {200, 140}).status().code(),
            StatusCode::kInvalidArgument);
  for (double bad : {0.0, -1.0, 300.0, double(NAN)}) {
    o = ButtonDetectorOptions();
    o.radial_min_edge = bad;
    EXPECT_FALSE(o.IsValid(&error)) << bad;
    EXPECT_NE(error.find("radial_min_edge"), std::string::npos);
    o = ButtonDetectorOptions();
    o.radial_min_contrast = bad;
    EXPECT_FALSE(o.IsValid(&error)) << bad;
    EXPECT_NE(error.find("radial_min_contrast"), std::string::npos);
  }
}

}  // namespace
}  // namespace sightline
