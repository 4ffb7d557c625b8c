// The reference of calib_chessboard (reference_calibration/, computed with OpenCV 4.6
// findChessboardCorners + calibrateCamera + stereoCalibrate with fixed intrinsics, 25 mm squares):
// 13/13 pairs, RMS left 0.408 px, right 0.458 px, stereo 0.447 px, baseline 0.0836 m, fx ~536.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "core/calib/board_detection.h"
#include "core/calib/stereo_calibration.h"
#include "tests/support/test_data.h"

namespace sightline {
namespace {

// Detection and calibration of the 13 pairs are done once for the whole suite.
class ReferenceCalibration : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    const std::string dir = ::sightline::testing::DataPath("calib_chessboard");
    if (dir.empty()) return;
    auto files = FindStereoImages(dir);
    ASSERT_TRUE(files.ok()) << files.status().ToString();
    auto detections = DetectBoardsInPairs(*files, Board());
    ASSERT_TRUE(detections.ok()) << detections.status().ToString();
    detections_ = std::make_unique<Detections>(std::move(*detections));
    // The reference keeps every view: no rejection.
    MonoCalibrationOptions mono;
    mono.max_view_error_px = 0;
    StereoCalibrationOptions stereo;
    stereo.max_pair_error_px = 0;
    auto calibration =
        CalibrateStereo(detections_->views, detections_->right_views, Board(), mono, stereo);
    ASSERT_TRUE(calibration.ok()) << calibration.status().ToString();
    calibration_ = std::make_unique<StereoCalibration>(std::move(*calibration));
  }
  static void TearDownTestSuite() {
    detections_.reset();
    calibration_.reset();
  }
  void SetUp() override {
    SIGHTLINE_REQUIRE_DATA(dir, "calib_chessboard");
    ASSERT_NE(calibration_, nullptr);
  }
  static ChessboardOptions Board() { return ChessboardOptions{}; }  // 9x6, 25 mm.

  static std::unique_ptr<Detections> detections_;
  static std::unique_ptr<StereoCalibration> calibration_;
};

std::unique_ptr<Detections> ReferenceCalibration::detections_;
std::unique_ptr<StereoCalibration> ReferenceCalibration::calibration_;

TEST_F(ReferenceCalibration, FindsTheBoardInAllThirteenPairs) {
  EXPECT_EQ(detections_->inputs, 13);
  EXPECT_EQ(detections_->views.size(), 13u);
  EXPECT_TRUE(detections_->without_board.empty());
  EXPECT_EQ(detections_->views[0].name, "left01.jpg");
  EXPECT_EQ(detections_->right_views[12].name, "right14.jpg");
  EXPECT_EQ(detections_->views[0].corners.size(), 54u);
}

TEST_F(ReferenceCalibration, MonoRmsMatchesTheReference) {
  // Reference: 0.408 and 0.458 px; agreement to the reference's second decimal.
  EXPECT_NEAR(calibration_->left.rms_px, 0.408, 0.01);
  EXPECT_NEAR(calibration_->right.rms_px, 0.458, 0.01);
  EXPECT_EQ(calibration_->left.used.size(), 13u);
  EXPECT_EQ(calibration_->left.rejected(), 0);
}

TEST_F(ReferenceCalibration, IntrinsicsMatchTheReference) {
  // Reference M1: fx 536.06, fy 536.01, cx 342.37, cy 235.53; M2: fx 542.34, cx 328.33.
  const PinholeCamera& l = calibration_->rig.left;
  const PinholeCamera& r = calibration_->rig.right;
  EXPECT_NEAR(l.fx, 536.06, 536.06 * 0.01);
  EXPECT_NEAR(l.fy, 536.01, 536.01 * 0.01);
  EXPECT_NEAR(l.cx, 342.37, 3.0);
  EXPECT_NEAR(l.cy, 235.53, 3.0);
  EXPECT_NEAR(r.fx, 542.34, 542.34 * 0.01);
  EXPECT_NEAR(r.cx, 328.33, 3.0);
  EXPECT_NEAR(l.distortion[0], -0.265, 0.02);
  EXPECT_EQ(l.width, 640);
  EXPECT_EQ(l.height, 480);
}

TEST_F(ReferenceCalibration, StereoRmsAndBaselineMatchTheReference) {
  EXPECT_NEAR(calibration_->rms_px, 0.447, 0.01);
  // 83.6 mm within 1 %.
  EXPECT_NEAR(calibration_->BaselineM(), 0.0836, 0.0836 * 0.01);
  // The right camera sits to the right: x_right = R x_left + T with T.x about -83.6 mm.
  EXPECT_LT(calibration_->rig.right_from_left.translation().x(), -0.08);
  const Eigen::AngleAxisd rotation(calibration_->rig.right_from_left.linear());
  EXPECT_LT(rotation.angle() * 180 / M_PI, 1.0);  // Reference: 0.36 deg.
  EXPECT_EQ(calibration_->used_pairs(), 13);
}

TEST_F(ReferenceCalibration, PerViewErrorsAverageToTheRms) {
  double sum = 0;
  for (const ViewError& v : calibration_->left.views) {
    EXPECT_GT(v.rms_px, 0.0) << v.name;
    EXPECT_LT(v.rms_px, 2.0) << v.name;
    sum += v.rms_px * v.rms_px;
  }
  // Equal corner counts per view: the mean squared per-view error is the squared RMS.
  EXPECT_NEAR(std::sqrt(sum / calibration_->left.views.size()), calibration_->left.rms_px, 1e-3);
  for (const PairError& p : calibration_->pairs) {
    EXPECT_GT(p.left_rms_px, 0.0) << p.name;
    EXPECT_GT(p.right_rms_px, 0.0) << p.name;
  }
}

TEST_F(ReferenceCalibration, CoverageDescribesTheViews) {
  const Coverage& c = calibration_->left.coverage;
  EXPECT_EQ(c.views, 13);
  EXPECT_GT(c.cells_covered, 0.5);
  EXPECT_LE(c.cells_covered, 1.0);
  EXPECT_LT(c.x_min, c.x_max);
  EXPECT_GT(c.scale_max, c.scale_min);
  EXPECT_GE(c.tilt_min_deg, 0.0);
  EXPECT_GT(c.tilt_max_deg, 10.0);
}

TEST_F(ReferenceCalibration, RejectionDropsTheWorstViewsAndLowersTheRms) {
  MonoCalibrationOptions strict;
  strict.max_view_error_ratio = 2.0;  // Views above twice the median error.
  auto calibration = CalibrateMono(detections_->views, Board(), strict);
  ASSERT_TRUE(calibration.ok()) << calibration.status().ToString();
  EXPECT_GT(calibration->rejected(), 0);
  EXPECT_EQ(calibration->used.size() + calibration->rejected(), 13u);
  EXPECT_LT(calibration->rms_px, calibration_->left.rms_px);
}

}  // namespace
}  // namespace sightline
