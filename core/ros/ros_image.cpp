#include "core/ros/ros_image.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "core/common/depth_cloud.h"

namespace sightline {
namespace {

struct EncodingInfo {
  const char* name;
  int cv_type;
  int channels_out;  // Colour role: 1 or 3 (BGR) after conversion; depth: 1.
  bool depth;
};

constexpr EncodingInfo kEncodings[] = {
    {"mono8", CV_8UC1, 1, false}, {"rgb8", CV_8UC3, 3, false},  {"bgr8", CV_8UC3, 3, false},
    {"rgba8", CV_8UC4, 3, false}, {"bgra8", CV_8UC4, 3, false}, {"8UC1", CV_8UC1, 1, false},
    {"8UC3", CV_8UC3, 3, false},  {"16UC1", CV_16UC1, 1, true}, {"mono16", CV_16UC1, 1, true},
    {"32FC1", CV_32FC1, 1, true},
};

const EncodingInfo* FindEncoding(const std::string& name) {
  for (const EncodingInfo& e : kEncodings) {
    if (name == e.name) return &e;
  }
  return nullptr;
}

std::string SupportedEncodings() {
  std::string list;
  for (const EncodingInfo& e : kEncodings) list += (list.empty() ? "" : ", ") + std::string(e.name);
  return list;
}

// A view of the message's rows (checked sizes), of the encoding's type.
StatusOr<cv::Mat> RowsView(const sensor_msgs::Image& msg, const EncodingInfo& e) {
  if (msg.width == 0 || msg.height == 0) {
    return InvalidArgument("image is empty (width " + std::to_string(msg.width) + ", height " +
                           std::to_string(msg.height) + ")");
  }
  if (msg.width > 1u << 15 || msg.height > 1u << 15) {
    return InvalidArgument("image size " + std::to_string(msg.width) + "x" +
                           std::to_string(msg.height) + " exceeds 32768 pixels per side");
  }
  const size_t row_bytes = static_cast<size_t>(msg.width) * CV_ELEM_SIZE(e.cv_type);
  if (msg.step < row_bytes) {
    return ParseError("step " + std::to_string(msg.step) + " is shorter than a row of " +
                      std::to_string(msg.width) + " " + e.name + " pixels (" +
                      std::to_string(row_bytes) + " bytes)");
  }
  const size_t needed = static_cast<size_t>(msg.height) * msg.step;
  if (msg.data.size() < needed) {
    return ParseError("data holds " + std::to_string(msg.data.size()) + " bytes, height " +
                      std::to_string(msg.height) + " x step " + std::to_string(msg.step) +
                      " needs " + std::to_string(needed));
  }
  if (msg.is_bigendian && CV_ELEM_SIZE1(e.cv_type) > 1) {
    return InvalidArgument(std::string("big-endian ") + e.name + " images are not supported");
  }
  return cv::Mat(static_cast<int>(msg.height), static_cast<int>(msg.width), e.cv_type,
                 const_cast<uint8_t*>(msg.data.data()), msg.step);
}

// 32FC1 metres with 0, NaN and inf as NaN (no reading); 16UC1 millimetres through
// RawDepthToMetres.
cv::Mat DepthToMetres(const cv::Mat& raw) {
  if (raw.type() == CV_16UC1) return RawDepthToMetres(raw, 1000);
  cv::Mat metres(raw.size(), CV_32FC1);
  const float nan = std::numeric_limits<float>::quiet_NaN();
  for (int r = 0; r < raw.rows; ++r) {
    const float* in = raw.ptr<float>(r);
    float* out = metres.ptr<float>(r);
    for (int c = 0; c < raw.cols; ++c) out[c] = std::isfinite(in[c]) && in[c] > 0 ? in[c] : nan;
  }
  return metres;
}

}  // namespace

StatusOr<cv::Mat> DecodeRosImage(const sensor_msgs::Image& msg, RosImageRole role) {
  const EncodingInfo* e = FindEncoding(msg.encoding);
  if (e == nullptr) {
    return InvalidArgument("unsupported encoding '" + msg.encoding +
                           "' (supported: " + SupportedEncodings() + ")");
  }
  if (e->depth != (role == RosImageRole::kDepth)) {
    return InvalidArgument("encoding " + msg.encoding + " is " +
                           (e->depth ? "a depth image, not a colour one"
                                     : "a colour image, not a depth one (16UC1 or 32FC1)"));
  }
  StatusOr<cv::Mat> view = RowsView(msg, *e);
  if (!view.ok()) return view.status();
  if (e->depth) return DepthToMetres(*view);
  cv::Mat out;
  const std::string& enc = msg.encoding;
  if (enc == "rgb8") {
    cv::cvtColor(*view, out, cv::COLOR_RGB2BGR);
  } else if (enc == "rgba8") {
    cv::cvtColor(*view, out, cv::COLOR_RGBA2BGR);
  } else if (enc == "bgra8") {
    cv::cvtColor(*view, out, cv::COLOR_BGRA2BGR);
  } else {
    out = view->clone();
  }
  return out;
}

StatusOr<cv::Mat> DecodeRosCompressedImage(const sensor_msgs::CompressedImage& msg) {
  if (msg.data.empty()) return ParseError("format '" + msg.format + "': no image bytes");
  cv::Mat image;
  try {
    image = cv::imdecode(msg.data, cv::IMREAD_UNCHANGED);
  } catch (const cv::Exception& e) {
    image.release();
  }
  if (image.empty()) {
    return ParseError("format '" + msg.format + "': " + std::to_string(msg.data.size()) +
                      " bytes do not decode as an image");
  }
  if (image.depth() != CV_8U) {
    return InvalidArgument("format '" + msg.format + "': only 8-bit compressed images are read");
  }
  if (image.channels() == 4) cv::cvtColor(image, image, cv::COLOR_BGRA2BGR);
  return image;
}

StatusOr<sensor_msgs::CompressedImage> EncodeRosJpeg(const cv::Mat& image, double stamp_s,
                                                     const std::string& frame_id, int quality) {
  if (image.type() != CV_8UC1 && image.type() != CV_8UC3) {
    return InvalidArgument("JPEG needs an 8-bit grey or BGR image");
  }
  sensor_msgs::CompressedImage msg;
  msg.header.stamp = RosTimeFromSeconds(stamp_s);
  msg.header.frame_id = frame_id;
  const char* encoding = image.type() == CV_8UC1 ? "mono8" : "bgr8";
  msg.format = std::string(encoding) + "; jpeg compressed " + encoding;
  const std::vector<int> params = {cv::IMWRITE_JPEG_QUALITY, std::clamp(quality, 1, 100)};
  if (!cv::imencode(".jpg", image, msg.data, params)) {
    return Internal("the image does not encode as JPEG");
  }
  return msg;
}

StatusOr<sensor_msgs::Image> EncodeRosImage(const cv::Mat& image, double stamp_s,
                                            const std::string& frame_id) {
  sensor_msgs::Image msg;
  switch (image.type()) {
    case CV_8UC1:
      msg.encoding = "mono8";
      break;
    case CV_8UC3:
      msg.encoding = "bgr8";
      break;
    case CV_16UC1:
      msg.encoding = "16UC1";
      break;
    case CV_32FC1:
      msg.encoding = "32FC1";
      break;
    default:
      return InvalidArgument("cannot encode a cv::Mat of type " + std::to_string(image.type()) +
                             " as a ROS image (mono8, bgr8, 16UC1, 32FC1)");
  }
  msg.header.stamp = RosTimeFromSeconds(stamp_s);
  msg.header.frame_id = frame_id;
  msg.width = static_cast<uint32_t>(image.cols);
  msg.height = static_cast<uint32_t>(image.rows);
  msg.is_bigendian = 0;
  msg.step = static_cast<uint32_t>(image.cols * image.elemSize());
  msg.data.resize(static_cast<size_t>(msg.step) * image.rows);
  for (int r = 0; r < image.rows; ++r) {
    std::memcpy(msg.data.data() + static_cast<size_t>(r) * msg.step, image.ptr(r), msg.step);
  }
  return msg;
}

StatusOr<PinholeCamera> CameraFromRosInfo(const sensor_msgs::CameraInfo& info) {
  PinholeCamera camera;
  camera.width = static_cast<int>(info.width);
  camera.height = static_cast<int>(info.height);
  camera.fx = info.K[0];
  camera.fy = info.K[4];
  camera.cx = info.K[2];
  camera.cy = info.K[5];
  if (info.width == 0 || info.height == 0) {
    return InvalidArgument("CameraInfo width/height is " + std::to_string(info.width) + "x" +
                           std::to_string(info.height) + " (uncalibrated camera)");
  }
  if (!(camera.fx > 0) || !(camera.fy > 0) || !std::isfinite(camera.fx) ||
      !std::isfinite(camera.fy) || !std::isfinite(camera.cx) || !std::isfinite(camera.cy)) {
    return InvalidArgument("CameraInfo K has fx " + std::to_string(camera.fx) + ", fy " +
                           std::to_string(camera.fy) + " (all zero: the camera is uncalibrated)");
  }
  const std::string& model = info.distortion_model;
  if (!info.D.empty()) {
    if (model != "plumb_bob" && model != "rational_polynomial") {
      return InvalidArgument("CameraInfo distortion_model '" + model +
                             "' is not supported (plumb_bob, rational_polynomial)");
    }
    for (size_t i = 0; i < info.D.size() && i < 5; ++i) {
      if (!std::isfinite(info.D[i])) {
        return InvalidArgument("CameraInfo D[" + std::to_string(i) + "] is not finite");
      }
      camera.distortion[i] = info.D[i];
    }
  }
  if (Status valid = camera.Validate(); !valid.ok()) return valid;
  return camera;
}

sensor_msgs::CameraInfo RosInfoFromCamera(const PinholeCamera& camera, double stamp_s,
                                          const std::string& frame_id) {
  sensor_msgs::CameraInfo info;
  info.header.stamp = RosTimeFromSeconds(stamp_s);
  info.header.frame_id = frame_id;
  info.width = static_cast<uint32_t>(camera.width);
  info.height = static_cast<uint32_t>(camera.height);
  info.distortion_model = "plumb_bob";
  info.D.assign(camera.distortion.begin(), camera.distortion.end());
  info.K = {camera.fx, 0, camera.cx, 0, camera.fy, camera.cy, 0, 0, 1};
  info.R = {1, 0, 0, 0, 1, 0, 0, 0, 1};
  info.P = {camera.fx, 0, camera.cx, 0, 0, camera.fy, camera.cy, 0, 0, 0, 1, 0};
  return info;
}

StatusOr<Frame> FrameFromRosImages(SourceKind kind, const FrameStamp& stamp, cv::Mat first,
                                   cv::Mat second, const std::string& first_name,
                                   const std::string& second_name) {
  if (kind == SourceKind::kMono) return Frame(MonoFrame{stamp, std::move(first)});
  if (second.size() != first.size()) {
    return ParseError(second_name + ": image is " + std::to_string(second.cols) + "x" +
                      std::to_string(second.rows) + " but " + first_name + " is " +
                      std::to_string(first.cols) + "x" + std::to_string(first.rows));
  }
  if (kind == SourceKind::kStereo) {
    if (second.type() != first.type()) {
      cv::cvtColor(second, second,
                   second.channels() == 1 ? cv::COLOR_GRAY2BGR : cv::COLOR_BGR2GRAY);
    }
    return Frame(StereoFrame{stamp, std::move(first), std::move(second)});
  }
  if (first.channels() == 1) cv::cvtColor(first, first, cv::COLOR_GRAY2BGR);
  return Frame(RgbdFrame{stamp, std::move(first), std::move(second)});
}

double RosSeconds(const ros::Time& time) { return time.toSec(); }

ros::Time RosTimeFromSeconds(double seconds) {
  if (!(seconds > 0) || !std::isfinite(seconds)) return ros::Time(0, 0);
  return ros::Time(seconds);
}

}  // namespace sightline
