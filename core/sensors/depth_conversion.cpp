#include "core/sensors/depth_conversion.h"

#include <cmath>
#include <limits>

namespace sightline {

PinholeCamera PinholeFromFov(int width, int height, double hfov_rad, double vfov_rad) {
  PinholeCamera camera;
  camera.width = width;
  camera.height = height;
  camera.fx = width / (2.0 * std::tan(hfov_rad / 2.0));
  camera.fy = height / (2.0 * std::tan(vfov_rad / 2.0));
  camera.cx = width / 2.0;
  camera.cy = height / 2.0;
  return camera;
}

}  // namespace sightline
