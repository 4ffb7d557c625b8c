// Back-projection of a depth image into a point cloud.
#pragma once

#include <opencv2/core.hpp>

#include "core/common/camera.h"
#include "core/common/frame.h"

namespace sightline {

// Builds an organized cloud (one point per sampled pixel, NaN where depth is invalid) from a
// metric depth image and optional registered BGR colour. `stride` samples every n-th pixel.
PointCloud DepthToCloud(const cv::Mat& depth_m, const cv::Mat& color_bgr,
                        const PinholeCamera& camera, int stride = 1);

}  // namespace sightline
