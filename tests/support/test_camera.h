// Test helper: the 640x480 Kinect-class pinhole camera (f = 525 px, centred principal point)
// that unit tests use when the intrinsics themselves are not under test.
#pragma once

#include "core/common/camera.h"

namespace sightline::testing {

inline PinholeCamera VgaCamera() {
  PinholeCamera c;
  c.width = 640;
  c.height = 480;
  c.fx = c.fy = 525;
  c.cx = 319.5;
  c.cy = 239.5;
  return c;
}

}  // namespace sightline::testing
