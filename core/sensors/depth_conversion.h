// Conversions shared by the RGB-D drivers: raw depth units to metres, FOV to intrinsics.
#pragma once

#include <opencv2/core.hpp>

#include "core/common/camera.h"

namespace sightline {

// CV_16UC1 raw depth (e.g. millimetres: units_per_metre = 1000) to CV_32FC1 metres; 0 (no
// reading) becomes NaN.
cv::Mat RawDepthToMetres(const cv::Mat& raw, double units_per_metre);

// An ideal pinhole camera (no distortion, principal point at the centre) with the given
// horizontal and vertical fields of view [rad]: fx = width / (2 tan(hfov / 2)).
PinholeCamera PinholeFromFov(int width, int height, double hfov_rad, double vfov_rad);

}  // namespace sightline
