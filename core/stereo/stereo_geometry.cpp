#include "core/stereo/stereo_geometry.h"

#include <cmath>
#include <string>

namespace sightline {

StatusOr<RectifiedStereoCamera> RectifiedStereoCamera::FromRig(const StereoRig& rig) {
  if (!rig.rectified) return FailedPrecondition("the stereo rig is not rectified");
  const PinholeCamera& l = rig.left;
  if (!(l.fx > 0) || !(l.fy > 0) || l.width <= 0 || l.height <= 0) {
    return InvalidArgument("stereo calibration: the left camera has no valid intrinsics");
  }
  const Eigen::Vector3d t = rig.right_from_left.translation();
  if (!(t.x() < 0)) {
    return InvalidArgument(
        "stereo calibration: the right camera must sit to the right of the left one "
        "(right_from_left.x < 0, P1[0][3] < 0); found x = " +
        std::to_string(t.x()) + " m (wrong baseline sign?)");
  }
  if (std::abs(t.y()) > 1e-3 * std::abs(t.x()) || std::abs(t.z()) > 1e-3 * std::abs(t.x())) {
    return InvalidArgument("stereo calibration: a rectified rig must have its baseline along x");
  }
  if (std::abs(l.fx - l.fy) > 1e-3 * l.fx) {
    return InvalidArgument("stereo calibration: rectified images need fx == fy");
  }
  RectifiedStereoCamera c;
  c.f = l.fx;
  c.cx = l.cx;
  c.cy = l.cy;
  c.baseline_m = -t.x();
  c.width = l.width;
  c.height = l.height;
  return c;
}

}  // namespace sightline
