// The tracker on a drawn, textured panel moved by known similarities: the centre follows,
// the predicted window limits the search, and an empty view is "lost".
#include "core/button/button_tracker.h"

#include <gtest/gtest.h>

#include <opencv2/imgproc.hpp>
#include <random>

#include "core/button/button_detector.h"

namespace sightline {
namespace {

// A textured panel with one round button at (320, 240).
cv::Mat TexturedPanel() {
  cv::Mat image(480, 640, CV_8UC3);
  std::mt19937 rng(11);
  std::uniform_int_distribution<int> grey(40, 220), pos(0, 639), size(4, 18);
  image.setTo(cv::Scalar(128, 128, 128));
  for (int i = 0; i < 900; ++i) {
    const int g = grey(rng);
    cv::rectangle(image, cv::Rect(pos(rng), pos(rng) * 3 / 4, size(rng), size(rng)),
                  cv::Scalar(g, g, g), cv::FILLED);
  }
  cv::circle(image, {320, 240}, 30, cv::Scalar(30, 30, 30), cv::FILLED, cv::LINE_AA);
  cv::circle(image, {320, 240}, 25, cv::Scalar(210, 210, 210), cv::FILLED, cv::LINE_AA);
  cv::putText(image, "7", {308, 254}, cv::FONT_HERSHEY_SIMPLEX, 1.1, cv::Scalar(10, 10, 10), 3,
              cv::LINE_AA);
  return image;
}

// Warps the image; *centre goes in as a still-frame point and comes out where it moved.
cv::Mat Warp(const cv::Mat& image, double scale, double angle_deg, cv::Point2d shift,
             cv::Point2d* centre) {
  cv::Mat m = cv::getRotationMatrix2D(cv::Point2f(320, 240), angle_deg, scale);
  m.at<double>(0, 2) += shift.x;
  m.at<double>(1, 2) += shift.y;
  cv::Mat out;
  cv::warpAffine(image, out, m, image.size(), cv::INTER_LINEAR, cv::BORDER_REPLICATE);
  const cv::Point2d c = *centre;
  *centre = {m.at<double>(0, 0) * c.x + m.at<double>(0, 1) * c.y + m.at<double>(0, 2),
             m.at<double>(1, 0) * c.x + m.at<double>(1, 1) * c.y + m.at<double>(1, 2)};
  return out;
}

TEST(ButtonTracker, FollowsShiftScaleAndRotation) {
  const cv::Mat still = TexturedPanel();
  auto model = ButtonDetector().Detect(still, {322, 236});
  ASSERT_TRUE(model.ok()) << model.status().ToString();
  EXPECT_LT(cv::norm((*model)->center - cv::Point2d(320, 240)), 2.5);
  ButtonTracker tracker(*model);
  for (int i = 1; i <= 10; ++i) {
    cv::Point2d truth = (*model)->center;
    const cv::Mat frame = Warp(still, 1.0 + 0.06 * i, 2.0 * i, cv::Point2d(6 * i, -4 * i), &truth);
    auto t = tracker.Track(frame);  // No prediction: the window follows the last position.
    ASSERT_TRUE(t.ok()) << t.status().ToString();
    ASSERT_TRUE(t->found) << "step " << i << ": " << t->reason;
    EXPECT_LT(cv::norm(t->center - truth), 1.5) << "step " << i;
    EXPECT_NEAR(t->scale, 1.0 + 0.06 * i, 0.05);
    EXPECT_GT(t->confidence, 0.5);
    if (i > 1) EXPECT_LT(t->window.area(), frame.cols * frame.rows);  // A window, not all.
  }
}

// A long approach (the button grows threefold, the model refreshed on the way): the size from
// the tap's own keypoints follows the true scale within 1 %.
TEST(ButtonTracker, AnchorScaleFromTheTapsOwnKeypointsFollowsALongApproach) {
  const cv::Mat still = TexturedPanel();
  auto model = ButtonDetector().Detect(still, {322, 236});
  ASSERT_TRUE(model.ok()) << model.status().ToString();
  ButtonTracker tracker(*model);
  int anchored = 0;
  for (int i = 1; i <= 20; ++i) {
    const double scale = 1.0 + 0.1 * i;
    cv::Point2d truth = (*model)->center;
    const cv::Mat frame = Warp(still, scale, 0.5 * i, cv::Point2d(0, 0), &truth);
    auto t = tracker.Track(frame, TrackPrediction{true, truth, scale});
    ASSERT_TRUE(t.ok() && t->found) << "step " << i << ": " << (t.ok() ? t->reason : "");
    if (t->anchor_scale <= 0) continue;
    ++anchored;
    EXPECT_NEAR(t->anchor_scale / scale, 1.0, 0.01) << "step " << i;
  }
  EXPECT_GE(anchored, 15);
}

TEST(ButtonTracker, CentroidRuleIsAvailable) {
  const cv::Mat still = TexturedPanel();
  auto model = ButtonDetector().Detect(still, {320, 240});
  ASSERT_TRUE(model.ok());
  ButtonTrackerOptions o;
  o.centre = "centroid";
  ButtonTracker tracker(*model, o);
  cv::Point2d truth = (*model)->center;
  const cv::Mat frame = Warp(still, 1.0, 0, {10, 5}, &truth);
  auto t = tracker.Track(frame);
  ASSERT_TRUE(t.ok() && t->found);
  // The keypoints' centroid is near, not at, the button centre.
  EXPECT_LT(cv::norm(t->center - truth), 0.6 * (*model)->RadiusPx() * 5);
  EXPECT_EQ(t->inliers, t->matches);
}

TEST(ButtonTracker, AButtonOutOfViewIsLost) {
  const cv::Mat still = TexturedPanel();
  auto model = ButtonDetector().Detect(still, {320, 240});
  ASSERT_TRUE(model.ok());
  ButtonTracker tracker(*model);
  const cv::Mat blank(480, 640, CV_8UC3, cv::Scalar(90, 90, 90));
  auto t = tracker.Track(blank);
  ASSERT_TRUE(t.ok());
  EXPECT_FALSE(t->found);
  EXPECT_NE(t->reason.find("lost"), std::string::npos);
  // After a loss the whole image is searched again, and the button is found.
  auto again = tracker.Track(still);
  ASSERT_TRUE(again.ok() && again->found);
  EXPECT_EQ(again->window.area(), still.cols * still.rows);
  EXPECT_LT(cv::norm(again->center - (*model)->center), 1.0);
}

TEST(ButtonTracker, ThePredictedWindowAndGateRejectADistantCopy) {
  // Two identical buttons; the prediction says the left one.
  cv::Mat still = TexturedPanel();
  auto model = ButtonDetector().Detect(still, {320, 240});
  ASSERT_TRUE(model.ok());
  cv::Mat two = still.clone();
  still(cv::Rect(250, 170, 140, 140)).copyTo(two(cv::Rect(450, 170, 140, 140)));
  ButtonTracker tracker(*model);
  TrackPrediction p{true, {325, 236}, 1.0};
  auto t = tracker.Track(two, p);
  ASSERT_TRUE(t.ok() && t->found);
  EXPECT_LT(cv::norm(t->center - cv::Point2d(320, 240)), 1.5);
  EXPECT_FALSE(t->window.contains({520, 240}));
}

TEST(ButtonTracker, BadInputIsAClearStatus) {
  auto model = ButtonDetector().Detect(TexturedPanel(), {320, 240});
  ASSERT_TRUE(model.ok());
  ButtonTracker tracker(*model);
  EXPECT_EQ(tracker.Track(cv::Mat()).status().code(), StatusCode::kInvalidArgument);
  ButtonTrackerOptions o;
  o.ratio = 1.5;
  EXPECT_EQ(ButtonTracker(*model, o).Track(TexturedPanel()).status().code(),
            StatusCode::kInvalidArgument);
  ButtonTracker empty(nullptr);
  EXPECT_EQ(empty.Track(TexturedPanel()).status().code(), StatusCode::kFailedPrecondition);
}

}  // namespace
}  // namespace sightline
