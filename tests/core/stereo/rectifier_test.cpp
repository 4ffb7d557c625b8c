#include "core/stereo/rectifier.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <opencv2/calib3d.hpp>
#include <opencv2/imgproc.hpp>

#include "stereo_test_util.h"

namespace sightline {
namespace {

StereoRig RectifiedRig(double baseline_sign = 1) {
  StereoRig rig;
  rig.left.width = rig.right.width = 640;
  rig.left.height = rig.right.height = 480;
  rig.left.fx = rig.left.fy = rig.right.fx = rig.right.fy = 500;
  rig.left.cx = rig.right.cx = 320;
  rig.left.cy = rig.right.cy = 240;
  rig.right_from_left.translation() = Eigen::Vector3d(-0.12 * baseline_sign, 0, 0);
  rig.rectified = true;
  return rig;
}

TEST(Rectifier, PassesRectifiedImagesThrough) {
  Rectifier rectifier;
  ASSERT_TRUE(rectifier.Configure(RectifiedRig()).ok());
  EXPECT_FALSE(rectifier.remaps());
  EXPECT_DOUBLE_EQ(rectifier.camera().baseline_m, 0.12);
  StereoFrame frame;
  frame.left = testing::TexturedImage(cv::Size(640, 480), 1);
  frame.right = frame.left.clone();
  cv::Mat l, r;
  ASSERT_TRUE(rectifier.Rectify(frame, &l, &r).ok());
  EXPECT_EQ(cv::norm(l, frame.left, cv::NORM_INF), 0);
}

TEST(Rectifier, RefusesAWrongBaselineSign) {
  Rectifier rectifier;
  const Status s = rectifier.Configure(RectifiedRig(-1));
  ASSERT_FALSE(s.ok());
  EXPECT_NE(s.message().find("wrong baseline sign"), std::string::npos) << s.message();
  StereoRig raw = RectifiedRig(-1);
  raw.rectified = false;
  EXPECT_FALSE(rectifier.Configure(raw).ok());
}

TEST(Rectifier, RejectsEmptyAndMismatchedImages) {
  Rectifier rectifier;
  ASSERT_TRUE(rectifier.Configure(RectifiedRig()).ok());
  StereoFrame frame;
  cv::Mat l, r;
  Status s = rectifier.Rectify(frame, &l, &r);
  EXPECT_NE(s.message().find("empty"), std::string::npos);
  frame.left = cv::Mat::zeros(240, 320, CV_8UC1);
  frame.right = frame.left;
  s = rectifier.Rectify(frame, &l, &r);
  EXPECT_NE(s.message().find("differs from the calibration"), std::string::npos);
}

TEST(Rectifier, UndistortsAndAlignsRowsOfARawRig) {
  // A raw rig with distortion and a small relative rotation: after rectification a point
  // projects to the same row in both images, and the baseline is preserved.
  StereoRig rig = RectifiedRig();
  rig.rectified = false;
  rig.left.distortion = {-0.28, 0.07, 0.0002, 0.00002, 0};
  rig.right.distortion = {-0.28, 0.07, 0.0002, 0.00002, 0};
  rig.right_from_left.linear() =
      Eigen::AngleAxisd(0.01, Eigen::Vector3d(0.3, 1, 0.2).normalized()).toRotationMatrix();
  Rectifier rectifier;
  ASSERT_TRUE(rectifier.Configure(rig).ok());
  EXPECT_TRUE(rectifier.remaps());
  EXPECT_NEAR(rectifier.camera().baseline_m, 0.12, 1e-6);
  // Project a 3D point with OpenCV's distortion into both raw images, rectify the point maps.
  const cv::Mat k_left = (cv::Mat_<double>(3, 3) << 500, 0, 320, 0, 500, 240, 0, 0, 1);
  std::vector<cv::Point3d> x = {{0.5, 0.3, 4.0}, {-1.0, -0.4, 6.0}};
  std::vector<cv::Point2d> in_left, in_right;
  cv::Mat d = (cv::Mat_<double>(1, 5) << -0.28, 0.07, 0.0002, 0.00002, 0);
  cv::projectPoints(x, cv::Vec3d(0, 0, 0), cv::Vec3d(0, 0, 0), k_left, d, in_left);
  const Eigen::AngleAxisd aa(rig.right_from_left.rotation());
  const Eigen::Vector3d rv = aa.axis() * aa.angle();
  const Eigen::Vector3d t = rig.right_from_left.translation();
  cv::projectPoints(x, cv::Vec3d(rv.x(), rv.y(), rv.z()), cv::Vec3d(t.x(), t.y(), t.z()), k_left, d,
                    in_right);
  // Render small white dots on black images at those positions and rectify.
  StereoFrame frame;
  frame.left = cv::Mat::zeros(480, 640, CV_8UC1);
  frame.right = cv::Mat::zeros(480, 640, CV_8UC1);
  for (size_t i = 0; i < x.size(); ++i) {
    cv::circle(frame.left, cv::Point(cvRound(in_left[i].x), cvRound(in_left[i].y)), 3, 255,
               cv::FILLED);
    cv::circle(frame.right, cv::Point(cvRound(in_right[i].x), cvRound(in_right[i].y)), 3, 255,
               cv::FILLED);
  }
  cv::Mat l, r;
  ASSERT_TRUE(rectifier.Rectify(frame, &l, &r).ok());
  // Rows of the two blobs' centroids agree within a pixel in the rectified pair.
  std::vector<std::vector<cv::Point>> cl, cr;
  cv::findContours(l > 100, cl, cv::RETR_EXTERNAL, cv::CHAIN_APPROX_NONE);
  cv::findContours(r > 100, cr, cv::RETR_EXTERNAL, cv::CHAIN_APPROX_NONE);
  ASSERT_EQ(cl.size(), 2u);
  ASSERT_EQ(cr.size(), 2u);
  std::vector<double> rows_l, rows_r;
  for (const auto& c : cl)
    rows_l.push_back(cv::boundingRect(c).y + cv::boundingRect(c).height / 2.0);
  for (const auto& c : cr)
    rows_r.push_back(cv::boundingRect(c).y + cv::boundingRect(c).height / 2.0);
  std::sort(rows_l.begin(), rows_l.end());
  std::sort(rows_r.begin(), rows_r.end());
  for (size_t i = 0; i < 2; ++i) EXPECT_NEAR(rows_l[i], rows_r[i], 1.5);
}

}  // namespace
}  // namespace sightline
