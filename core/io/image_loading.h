// Image decoding shared by the dataset readers, with errors that name the file and say what was
// expected. OpenCV's imread returns an empty Mat without a reason; these functions give one.
#pragma once

#include <opencv2/core.hpp>
#include <string>

#include "core/common/frame.h"
#include "core/common/status.h"

namespace sightline {

// Checks that `path` is a regular file that can be opened (CheckRegularFile): NotFound when
// nothing is there, InvalidArgument for a folder or device, Unavailable with the system's reason
// (e.g. "permission denied") when it cannot be read. The loaders below check this first, so that
// "cannot decode" means the bytes are not an image.
Status CheckFileExists(const std::string& path);

// Loads an 8-bit image as CV_8UC3 BGR (grey images are expanded, alpha dropped).
// NotFound when missing, ParseError when undecodable or not 8-bit.
StatusOr<cv::Mat> LoadColorImage(const std::string& path);

// Loads an 8-bit image as stored: CV_8UC1 for grey, CV_8UC3 BGR for colour (alpha dropped).
StatusOr<cv::Mat> LoadImage8(const std::string& path);

// Loads a 16-bit single-channel depth image and converts it to CV_32FC1 metres:
// value / units_per_metre, NaN where the raw value is 0. ParseError when the image is not
// 16-bit single-channel (e.g. an 8-bit PNG where depth was expected).
StatusOr<cv::Mat> LoadDepthImage(const std::string& path, double units_per_metre);

// "8-bit 1-channel" for CV_8UC1 etc., for messages.
std::string DescribeMatType(int type);

// Loads a left/right pair (8-bit grey or colour); both must have the same size and type.
StatusOr<StereoFrame> LoadStereoPair(const std::string& left_path, const std::string& right_path);

}  // namespace sightline
