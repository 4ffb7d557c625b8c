#include "core/eval/trajectory_plot.h"

#include <gtest/gtest.h>

#include <opencv2/imgcodecs.hpp>

#include "core/eval/plot_canvas.h"
#include "tests/core/eval/eval_test_util.h"
#include "tests/support/test_data.h"

namespace sightline {
namespace {

// Pixels close to a BGR colour.
int CountColour(const cv::Mat& image, const cv::Scalar& colour) {
  cv::Mat mask;
  cv::inRange(image, colour - cv::Scalar(30, 30, 30), colour + cv::Scalar(30, 30, 30), mask);
  return cv::countNonZero(mask);
}

TrajectoryErrors SomeErrors() {
  const Trajectory gt = testing::Helix(100);
  Eigen::Isometry3d offset = Eigen::Isometry3d::Identity();
  offset.translation() = Eigen::Vector3d(0.3, 0, 0);
  EvaluationOptions options;
  options.align = "none";
  return *EvaluateTrajectory(testing::Transformed(gt, offset), gt, options);
}

TEST(TrajectoryPlot, NiceTicksAreRoundNumbers) {
  EXPECT_EQ(NiceTicks(0, 10, 5), (std::vector<double>{0, 2, 4, 6, 8, 10}));
  const std::vector<double> ticks = NiceTicks(-0.13, 0.42, 6);
  const std::vector<double> expected = {-0.1, 0, 0.1, 0.2, 0.3, 0.4};
  ASSERT_EQ(ticks.size(), expected.size());
  for (size_t i = 0; i < ticks.size(); ++i) EXPECT_NEAR(ticks[i], expected[i], 1e-12);
  EXPECT_EQ(NiceTicks(-0.13, 0.42, 5).size(), 3u);  // 0, 0.2, 0.4: step 0.2 is the nearest.
  EXPECT_TRUE(NiceTicks(1, 1, 5).empty());
}

TEST(TrajectoryPlot, AutoPlaneDropsTheFlattestOfYAndZ) {
  std::vector<Eigen::Vector3d> camera_frame = {{0, 0, 0}, {1, 0.1, 20}, {5, 0.2, 40}};
  std::vector<Eigen::Vector3d> z_up = {{0, 0, 1}, {1, 2, 1.1}, {3, 4, 1.2}};
  EXPECT_EQ(ResolvePlotPlane(PlotPlane::kAuto, camera_frame), PlotPlane::kXZ);
  EXPECT_EQ(ResolvePlotPlane(PlotPlane::kAuto, z_up), PlotPlane::kXY);
  EXPECT_EQ(ResolvePlotPlane(PlotPlane::kXY, camera_frame), PlotPlane::kXY);
  EXPECT_EQ(*ParsePlotPlane("xz"), PlotPlane::kXZ);
  EXPECT_FALSE(ParsePlotPlane("yz").ok());
}

TEST(TrajectoryPlot, TopViewShowsBothTrajectoriesInTheirColours) {
  const cv::Mat image = DrawTopView(SomeErrors(), PlotPlane::kXY, {640, 480});
  ASSERT_EQ(image.type(), CV_8UC3);
  EXPECT_EQ(image.cols, 640);
  EXPECT_EQ(image.rows, 480);
  EXPECT_GT(CountColour(image, PlotCanvas::kBlue), 500);
  EXPECT_GT(CountColour(image, PlotCanvas::kRed), 500);
  EXPECT_GT(CountColour(image, cv::Scalar(255, 255, 255)), image.total() / 2);  // Mostly paper.
}

TEST(TrajectoryPlot, ErrorOverTimeDrawsTheErrorCurve) {
  const cv::Mat image = DrawAteOverTime(SomeErrors());
  EXPECT_EQ(image.cols, 960);
  EXPECT_GT(CountColour(image, PlotCanvas::kRed), 500);
}

TEST(TrajectoryPlot, WritesBothPngsIntoANewFolder) {
  const std::string dir = testing::TempDir("eval_plot") + "/nested/plots";
  ASSERT_TRUE(WriteEvaluationPlots(SomeErrors(), dir, PlotPlane::kAuto).ok());
  for (const char* name : {"/top_view.png", "/ate_over_time.png"}) {
    const cv::Mat read = cv::imread(dir + name);
    ASSERT_FALSE(read.empty()) << name;
    EXPECT_EQ(read.cols, 960);
    EXPECT_EQ(read.rows, 720);
  }
  const Status failed = WriteEvaluationPlots(SomeErrors(), "/proc/no/such/dir", PlotPlane::kAuto);
  ASSERT_FALSE(failed.ok());
  EXPECT_NE(failed.message().find("/proc/no/such/dir"), std::string::npos);
}

}  // namespace
}  // namespace sightline
