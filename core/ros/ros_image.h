// Conversions between ROS 1 sensor messages and Sightline's images and cameras, shared by the
// rosbag reader, the live-topic source and sightline-node. Errors name the encoding or field.
// Only core/ros and the ROS front ends include this header (it pulls ROS's message headers).
#pragma once

#include <sensor_msgs/CameraInfo.h>
#include <sensor_msgs/CompressedImage.h>
#include <sensor_msgs/Image.h>

#include <opencv2/core.hpp>
#include <string>

#include "core/common/camera.h"
#include "core/common/frame.h"
#include "core/common/status.h"
#include "core/io/source.h"

namespace sightline {

// What a decoded image holds.
enum class RosImageRole {
  kColor,  // mono8 -> CV_8UC1; rgb8, bgr8, rgba8, bgra8 -> CV_8UC3 BGR.
  kDepth,  // 16UC1 (millimetres) or 32FC1 (metres) -> CV_32FC1 metres, NaN where 0 / NaN / inf.
};

// Decodes a sensor_msgs/Image into a new cv::Mat (never a view of the message's buffer). Checks
// the encoding, width * height against the data size and the row step. Errors:
// InvalidArgument "unsupported encoding 'yuv422' (supported: ...)" or "encoding 16UC1 is a
// depth image, not a colour one"; ParseError "data holds N bytes, height 480 x step 1920 needs M".
StatusOr<cv::Mat> DecodeRosImage(const sensor_msgs::Image& msg, RosImageRole role);

// Decodes a sensor_msgs/CompressedImage (jpeg or png) to CV_8UC3 BGR or CV_8UC1. ParseError when
// the bytes do not decode ("format 'jpeg': 1234 bytes do not decode as an image").
StatusOr<cv::Mat> DecodeRosCompressedImage(const sensor_msgs::CompressedImage& msg);

// An image message for a CV_8UC1 (mono8), CV_8UC3 BGR (bgr8), CV_16UC1 (16UC1) or CV_32FC1
// (32FC1) matrix, stamped with `stamp_s` (seconds) and `frame_id`. InvalidArgument for other types.
StatusOr<sensor_msgs::Image> EncodeRosImage(const cv::Mat& image, double stamp_s,
                                            const std::string& frame_id);

// A JPEG CompressedImage (format "bgr8; jpeg compressed bgr8" or "mono8; jpeg compressed mono8",
// as image_transport's compressed publisher writes) of a CV_8UC1 or CV_8UC3 BGR image at
// `quality` (1-100). InvalidArgument for other types.
StatusOr<sensor_msgs::CompressedImage> EncodeRosJpeg(const cv::Mat& image, double stamp_s,
                                                     const std::string& frame_id, int quality);

// The pinhole camera of a CameraInfo: K, width, height and plumb_bob / rational_polynomial's first
// five coefficients (k1 k2 p1 p2 k3). InvalidArgument naming the field for zero sizes, a zero or
// non-finite K, or an unsupported distortion model ("distortion_model 'equidistant' ...").
StatusOr<PinholeCamera> CameraFromRosInfo(const sensor_msgs::CameraInfo& info);

// A CameraInfo for a camera (plumb_bob, identity R, P = [K | 0]).
sensor_msgs::CameraInfo RosInfoFromCamera(const PinholeCamera& camera, double stamp_s,
                                          const std::string& frame_id);

// A frame of `kind` from its decoded images, the same for bags and live topics: RGB-D pairs a
// colour image (a mono one becomes BGR) with a depth image, stereo a left with a right image
// (converted to the left's type), mono uses `first` alone. ParseError when a pair's sizes
// differ: "<second_name>: image is WxH but <first_name> is WxH".
StatusOr<Frame> FrameFromRosImages(SourceKind kind, const FrameStamp& stamp, cv::Mat first,
                                   cv::Mat second, const std::string& first_name,
                                   const std::string& second_name);

// Seconds of a ROS time, and back.
double RosSeconds(const ros::Time& time);
ros::Time RosTimeFromSeconds(double seconds);

}  // namespace sightline
