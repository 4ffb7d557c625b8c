#include "tests/core/mapping/synthetic_scene.h"

#include <cmath>
#include <limits>
#include <random>

namespace sightline::testing {

PinholeCamera KinectCamera(int width, int height) {
  PinholeCamera camera;
  camera.width = 640;
  camera.height = 480;
  camera.fx = camera.fy = 525;
  camera.cx = 319.5;
  camera.cy = 239.5;
  return (width == 640 && height == 480) ? camera : camera.Scaled(width, height);
}

Eigen::Matrix3d WorldFromCameraRotation(const SyntheticView& view) {
  const double ch = std::cos(view.heading_rad), sh = std::sin(view.heading_rad);
  const double cp = std::cos(view.pitch_down_rad), sp = std::sin(view.pitch_down_rad);
  const Eigen::Vector3d z(ch * cp, sh * cp, -sp);
  const Eigen::Vector3d x0(sh, -ch, 0);
  const Eigen::Vector3d y0 = z.cross(x0);
  const double cr = std::cos(view.roll_rad), sr = std::sin(view.roll_rad);
  const Eigen::Vector3d x = cr * x0 + sr * y0;
  const Eigen::Vector3d y = z.cross(x);
  Eigen::Matrix3d r;
  r.col(0) = x;
  r.col(1) = y;
  r.col(2) = z;
  return r;
}

FloorPlane FloorPlaneOf(const SyntheticView& view) {
  FloorPlane plane;
  plane.normal = WorldFromCameraRotation(view).transpose() * Eigen::Vector3d::UnitZ();
  plane.d = view.height_m;
  return plane;
}

cv::Mat RenderDepth(const PinholeCamera& camera, const SyntheticView& view,
                    const std::vector<SyntheticWall>& walls, bool with_floor, double max_depth_m,
                    double noise_sigma_m, unsigned seed) {
  cv::Mat depth(camera.height, camera.width, CV_32FC1);
  const Eigen::Matrix3d r = WorldFromCameraRotation(view);
  const Eigen::Vector3d origin(view.position.x(), view.position.y(), view.height_m);
  std::mt19937 rng(seed);
  std::normal_distribution<double> gauss(0.0, 1.0);
  const float nan = std::numeric_limits<float>::quiet_NaN();
  for (int v = 0; v < camera.height; ++v) {
    for (int u = 0; u < camera.width; ++u) {
      // Ray with camera z = 1, so the ray parameter is the depth.
      const Eigen::Vector3d d =
          r * Eigen::Vector3d((u - camera.cx) / camera.fx, (v - camera.cy) / camera.fy, 1.0);
      double best = std::numeric_limits<double>::infinity();
      if (with_floor && d.z() < -1e-9) best = -origin.z() / d.z();
      for (const SyntheticWall& wall : walls) {
        // origin.xy + t d.xy = a + s (b - a)
        const Eigen::Vector2d e = wall.b - wall.a;
        const double det = d.x() * (-e.y()) - d.y() * (-e.x());
        if (std::abs(det) < 1e-12) continue;
        const Eigen::Vector2d q = wall.a - origin.head<2>();
        const double t = (q.x() * (-e.y()) - q.y() * (-e.x())) / det;
        const double s = (d.x() * q.y() - d.y() * q.x()) / det;
        if (t <= 1e-6 || s < 0 || s > 1) continue;
        const double z = origin.z() + t * d.z();
        if (z < 0 || z > wall.height_m) continue;
        best = std::min(best, t);
      }
      float value = nan;
      if (best <= max_depth_m) {
        value = static_cast<float>(best + noise_sigma_m * best * best * gauss(rng));
      }
      depth.at<float>(v, u) = value;
    }
  }
  return depth;
}

std::vector<SyntheticWall> Corridor(double x0, double x1, double width_m) {
  const double h = 0.5 * width_m;
  return {{{x0, h}, {x1, h}}, {{x0, -h}, {x1, -h}}, {{x1, -h}, {x1, h}}};
}

}  // namespace sightline::testing
