// Depth images: raw sensor units to metres, and back-projection into a point cloud.
#pragma once

#include <opencv2/core.hpp>

#include "core/common/camera.h"
#include "core/common/frame.h"

namespace sightline {

// CV_16UC1 raw depth (e.g. millimetres: units_per_metre = 1000) to CV_32FC1 metres; 0 (no
// reading) becomes NaN.
cv::Mat RawDepthToMetres(const cv::Mat& raw, double units_per_metre);

// Builds an organized cloud (one point per sampled pixel, NaN where depth is invalid) from a
// metric depth image and optional registered BGR colour. `stride` samples every n-th pixel.
PointCloud DepthToCloud(const cv::Mat& depth_m, const cv::Mat& color_bgr,
                        const PinholeCamera& camera, int stride = 1);

}  // namespace sightline
