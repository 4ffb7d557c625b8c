#include "core/mono/features.h"

#include <cmath>
#include <opencv2/calib3d.hpp>
#include <opencv2/imgproc.hpp>

namespace sightline {

FeatureExtractor::FeatureExtractor(const MonoFeatureOptions& options, const PinholeCamera& camera)
    : options_(options), camera_(camera) {
  orb_ =
      cv::ORB::create(options.max_features, static_cast<float>(options.scale_factor),
                      options.levels, 19, 0, 2, cv::ORB::HARRIS_SCORE, 31, options.fast_threshold);
}

double FeatureExtractor::LevelScale(int octave) const {
  return std::pow(options_.scale_factor, octave);
}

FrameFeatures FeatureExtractor::Extract(const cv::Mat& image) const {
  FrameFeatures f;
  f.cell_px = options_.grid_cell_px;
  if (image.empty()) return f;
  cv::Mat grey;
  if (image.channels() == 3) {
    cv::cvtColor(image, grey, cv::COLOR_BGR2GRAY);
  } else if (image.channels() == 4) {
    cv::cvtColor(image, grey, cv::COLOR_BGRA2GRAY);
  } else {
    grey = image;
  }
  if (grey.depth() != CV_8U) grey.convertTo(grey, CV_8U);
  f.width = grey.cols;
  f.height = grey.rows;
  orb_->detectAndCompute(grey, cv::noArray(), f.keypoints, f.descriptors);
  f.pixels.reserve(f.keypoints.size());
  if (camera_.HasDistortion() && !f.keypoints.empty()) {
    std::vector<cv::Point2f> raw, undistorted;
    for (const cv::KeyPoint& k : f.keypoints) raw.push_back(k.pt);
    cv::Mat K =
        (cv::Mat_<double>(3, 3) << camera_.fx, 0, camera_.cx, 0, camera_.fy, camera_.cy, 0, 0, 1);
    cv::Mat d(1, 5, CV_64F);
    for (int i = 0; i < 5; ++i) d.at<double>(i) = camera_.distortion[i];
    cv::undistortPoints(raw, undistorted, K, d, cv::noArray(), K);
    for (const cv::Point2f& p : undistorted) f.pixels.emplace_back(p.x, p.y);
  } else {
    for (const cv::KeyPoint& k : f.keypoints) f.pixels.emplace_back(k.pt.x, k.pt.y);
  }
  f.grid_columns = std::max(1, (f.width + f.cell_px - 1) / f.cell_px);
  f.grid_rows = std::max(1, (f.height + f.cell_px - 1) / f.cell_px);
  f.grid.assign(static_cast<size_t>(f.grid_columns) * f.grid_rows, {});
  for (size_t i = 0; i < f.pixels.size(); ++i) {
    const int c = std::clamp(static_cast<int>(f.pixels[i].x() / f.cell_px), 0, f.grid_columns - 1);
    const int r = std::clamp(static_cast<int>(f.pixels[i].y() / f.cell_px), 0, f.grid_rows - 1);
    f.grid[r * f.grid_columns + c].push_back(static_cast<int>(i));
  }
  return f;
}

bool Triangulate(const Eigen::Isometry3d& a_from_map, const Eigen::Isometry3d& b_from_map,
                 const Eigen::Vector2d& a, const Eigen::Vector2d& b, Eigen::Vector3d* x_in_map) {
  const Eigen::Matrix<double, 3, 4> Pa = a_from_map.matrix().topRows<3>();
  const Eigen::Matrix<double, 3, 4> Pb = b_from_map.matrix().topRows<3>();
  Eigen::Matrix4d A;
  A.row(0) = a.x() * Pa.row(2) - Pa.row(0);
  A.row(1) = a.y() * Pa.row(2) - Pa.row(1);
  A.row(2) = b.x() * Pb.row(2) - Pb.row(0);
  A.row(3) = b.y() * Pb.row(2) - Pb.row(1);
  Eigen::JacobiSVD<Eigen::Matrix4d> svd(A, Eigen::ComputeFullV);
  const Eigen::Vector4d h = svd.matrixV().col(3);
  if (std::abs(h(3)) < 1e-12) return false;
  *x_in_map = h.head<3>() / h(3);
  return x_in_map->allFinite();
}

double ParallaxDeg(const Eigen::Vector3d& x, const Eigen::Vector3d& centre_a,
                   const Eigen::Vector3d& centre_b) {
  const Eigen::Vector3d ra = (x - centre_a).normalized(), rb = (x - centre_b).normalized();
  return std::atan2(ra.cross(rb).norm(), ra.dot(rb)) * 180.0 / M_PI;
}

bool AcceptTriangulated(const PinholeCamera& camera, const Eigen::Vector3d& x,
                        const Eigen::Isometry3d& a_from_map, const Eigen::Isometry3d& b_from_map,
                        const Eigen::Vector2d& a_pixel, const Eigen::Vector2d& b_pixel,
                        double a_scale, double b_scale, double min_parallax_deg, double max_px) {
  const Eigen::Vector3d xa = a_from_map * x, xb = b_from_map * x;
  if (!(xa.z() > 0) || !(xb.z() > 0)) return false;
  if (ParallaxDeg(x, a_from_map.inverse().translation(), b_from_map.inverse().translation()) <
      min_parallax_deg) {
    return false;
  }
  if ((ProjectToPixel(camera, xa) - a_pixel).norm() > max_px * a_scale) return false;
  if ((ProjectToPixel(camera, xb) - b_pixel).norm() > max_px * b_scale) return false;
  return true;
}

}  // namespace sightline
