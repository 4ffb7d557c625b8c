#include "core/stereo/rectifier.h"

#include <opencv2/calib3d.hpp>
#include <opencv2/imgproc.hpp>
#include <string>

namespace sightline {

bool RectifierOptions::IsValid(std::string* error) const {
  if (!(alpha >= 0 && alpha <= 1)) {
    if (error) *error = "stereo.rectify.alpha must lie in [0, 1]";
    return false;
  }
  return true;
}

OptionTable<RectifierOptions> RectifierOptions::Describe() {
  using O = RectifierOptions;
  return OptionTable<O>("stereo.rectify")
      .Double("alpha", &O::alpha, "", 0, 1, 0.05,
              "Free scaling of cv::stereoRectify: 0 keeps only valid pixels, 1 keeps all.")
      .Bool("force", &O::force, "Rectify even when the rig says its images are rectified.");
}

namespace {

cv::Mat ToCv(const Eigen::Matrix3d& m) {
  cv::Mat out(3, 3, CV_64F);
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) out.at<double>(r, c) = m(r, c);
  }
  return out;
}

cv::Mat Distortion(const PinholeCamera& c) {
  cv::Mat d(1, 5, CV_64F);
  for (int i = 0; i < 5; ++i) d.at<double>(0, i) = c.distortion[i];
  return d;
}

Status ToGray(const cv::Mat& in, cv::Mat* out, const char* which) {
  if (in.empty()) return InvalidArgument(std::string("the ") + which + " image is empty");
  if (in.channels() == 1) {
    *out = in;
  } else if (in.channels() == 3) {
    cv::cvtColor(in, *out, cv::COLOR_BGR2GRAY);
  } else if (in.channels() == 4) {
    cv::cvtColor(in, *out, cv::COLOR_BGRA2GRAY);
  } else {
    return InvalidArgument(std::string("the ") + which + " image has an unsupported type");
  }
  if (out->depth() != CV_8U) out->convertTo(*out, CV_8U);
  return Status::Ok();
}

}  // namespace

Status Rectifier::Configure(const StereoRig& rig) {
  rig_ = rig;
  map_left_x_ = map_left_y_ = map_right_x_ = map_right_y_ = cv::Mat();
  if (rig.rectified && !options_.force) {
    StatusOr<RectifiedStereoCamera> camera = RectifiedStereoCamera::FromRig(rig);
    if (!camera.ok()) return camera.status();
    camera_ = *camera;
    return Status::Ok();
  }
  SIGHTLINE_RETURN_IF_ERROR(rig.left.Validate().WithContext("left camera"));
  SIGHTLINE_RETURN_IF_ERROR(rig.right.Validate().WithContext("right camera"));
  if (!(rig.right_from_left.translation().x() < 0)) {
    return InvalidArgument(
        "stereo calibration: the right camera must sit to the right of the left one "
        "(right_from_left.x < 0); found x = " +
        std::to_string(rig.right_from_left.translation().x()) + " m (wrong baseline sign?)");
  }
  const cv::Size size(rig.left.width, rig.left.height);
  const Eigen::Matrix3d rotation = rig.right_from_left.rotation();
  const Eigen::Vector3d t = rig.right_from_left.translation();
  const cv::Mat translation = (cv::Mat_<double>(3, 1) << t.x(), t.y(), t.z());
  cv::Mat r1, r2, p1, p2, q;
  cv::stereoRectify(ToCv(rig.left.K()), Distortion(rig.left), ToCv(rig.right.K()),
                    Distortion(rig.right), size, ToCv(rotation), translation, r1, r2, p1, p2, q,
                    cv::CALIB_ZERO_DISPARITY, options_.alpha, size);
  cv::initUndistortRectifyMap(ToCv(rig.left.K()), Distortion(rig.left), r1, p1, size, CV_16SC2,
                              map_left_x_, map_left_y_);
  cv::initUndistortRectifyMap(ToCv(rig.right.K()), Distortion(rig.right), r2, p2, size, CV_16SC2,
                              map_right_x_, map_right_y_);
  camera_.f = p1.at<double>(0, 0);
  camera_.cx = p1.at<double>(0, 2);
  camera_.cy = p1.at<double>(1, 2);
  camera_.baseline_m = -p2.at<double>(0, 3) / p2.at<double>(0, 0);
  camera_.width = size.width;
  camera_.height = size.height;
  if (!(camera_.baseline_m > 0) || !(camera_.f > 0)) {
    return InvalidArgument("stereo rectification produced a non-positive baseline or focal length");
  }
  return Status::Ok();
}

Status Rectifier::Rectify(const StereoFrame& frame, cv::Mat* left, cv::Mat* right) const {
  cv::Mat gray_left, gray_right;
  SIGHTLINE_RETURN_IF_ERROR(ToGray(frame.left, &gray_left, "left"));
  SIGHTLINE_RETURN_IF_ERROR(ToGray(frame.right, &gray_right, "right"));
  if (gray_left.size() != gray_right.size()) {
    return InvalidArgument("the left and right images differ in size");
  }
  if (camera_.width > 0 && (gray_left.cols != camera_.width || gray_left.rows != camera_.height)) {
    return InvalidArgument("image size " + std::to_string(gray_left.cols) + "x" +
                           std::to_string(gray_left.rows) + " differs from the calibration's " +
                           std::to_string(camera_.width) + "x" + std::to_string(camera_.height));
  }
  if (!remaps()) {
    *left = gray_left;
    *right = gray_right;
    return Status::Ok();
  }
  cv::remap(gray_left, *left, map_left_x_, map_left_y_, cv::INTER_LINEAR);
  cv::remap(gray_right, *right, map_right_x_, map_right_y_, cv::INTER_LINEAR);
  return Status::Ok();
}

}  // namespace sightline
