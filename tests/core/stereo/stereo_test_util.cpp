#include "stereo_test_util.h"

#include <cmath>
#include <opencv2/imgproc.hpp>
#include <random>

namespace sightline::testing {

RectifiedStereoCamera TestCamera() {
  RectifiedStereoCamera c;
  c.f = 500;
  c.cx = 320;
  c.cy = 240;
  c.baseline_m = 0.12;
  c.width = 640;
  c.height = 480;
  return c;
}

Eigen::Isometry3d TestMotion() {
  Eigen::Isometry3d m = Eigen::Isometry3d::Identity();
  m.linear() =
      Eigen::AngleAxisd(0.05, Eigen::Vector3d(0.2, 1.0, 0.1).normalized()).toRotationMatrix();
  m.translation() = Eigen::Vector3d(0.1, -0.03, -0.8);
  return m;
}

std::vector<StereoCorrespondence> SyntheticCorrespondences(
    const RectifiedStereoCamera& camera, const Eigen::Isometry3d& current_from_previous, int count,
    int outlier_count, double noise_px, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> ux(-8, 8), uy(-3, 3), uz(3, 30), uu(0, 640), uvv(0, 480),
      ud(2, 40);
  std::normal_distribution<double> noise(0, noise_px);
  std::vector<StereoCorrespondence> out;
  while (static_cast<int>(out.size()) < count) {
    const Eigen::Vector3d x(ux(rng), uy(rng), uz(rng));
    const Eigen::Vector3d y = current_from_previous * x;
    if (y.z() < 2) continue;
    const Eigen::Vector2d pl = camera.ProjectLeft(x), pr = camera.ProjectRight(x);
    const Eigen::Vector2d cl = camera.ProjectLeft(y), cr = camera.ProjectRight(y);
    if (pl.x() < 0 || pl.x() > 640 || pl.y() < 0 || pl.y() > 480) continue;
    if (cl.x() < 0 || cl.x() > 640 || cl.y() < 0 || cl.y() > 480) continue;
    StereoCorrespondence c;
    const double nv0 = noise(rng), nv1 = noise(rng);
    c.previous = {pl.x() + noise(rng), pl.y() + nv0, pr.x() + noise(rng)};
    c.current = {cl.x() + noise(rng), cl.y() + nv1, cr.x() + noise(rng)};
    if (static_cast<int>(out.size()) < outlier_count) {
      const double u = uu(rng);
      c.current = {u, uvv(rng), u - ud(rng)};
    }
    Triangulate(camera, &c);
    out.push_back(c);
  }
  return out;
}

cv::Mat TexturedImage(cv::Size size, unsigned seed) {
  cv::Mat image(size, CV_8UC1, cv::Scalar(128));
  cv::RNG rng(seed);
  for (int i = 0; i < size.area() / 60; ++i) {
    const cv::Point c(rng.uniform(0, size.width), rng.uniform(0, size.height));
    const int r = rng.uniform(2, 7);
    cv::rectangle(image, c - cv::Point(r, r), c + cv::Point(r, r), cv::Scalar(rng.uniform(0, 256)),
                  cv::FILLED);
  }
  cv::GaussianBlur(image, image, cv::Size(3, 3), 0.8);
  return image;
}

cv::Mat Shifted(const cv::Mat& image, double dx, double dy) {
  cv::Mat m = (cv::Mat_<double>(2, 3) << 1, 0, dx, 0, 1, dy);
  cv::Mat out;
  cv::warpAffine(image, out, m, image.size(), cv::INTER_LINEAR, cv::BORDER_REFLECT);
  return out;
}

double RotationErrorDeg(const Eigen::Isometry3d& a, const Eigen::Isometry3d& b) {
  return Eigen::AngleAxisd((a.inverse() * b).rotation()).angle() * 180.0 / M_PI;
}

double TranslationErrorM(const Eigen::Isometry3d& a, const Eigen::Isometry3d& b) {
  return (a.translation() - b.translation()).norm();
}

}  // namespace sightline::testing
