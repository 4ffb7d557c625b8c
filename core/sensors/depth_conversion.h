// Conversions shared by the RGB-D drivers: FOV to intrinsics (raw depth units to metres:
// RawDepthToMetres, core/common/depth_cloud.h).
#pragma once

#include <opencv2/core.hpp>

#include "core/common/camera.h"
#include "core/common/depth_cloud.h"

namespace sightline {

// An ideal pinhole camera (no distortion, principal point at the centre) with the given
// horizontal and vertical fields of view [rad]: fx = width / (2 tan(hfov / 2)).
PinholeCamera PinholeFromFov(int width, int height, double hfov_rad, double vfov_rad);

}  // namespace sightline
