#include "core/mobility/mobility_map.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>
#include <opencv2/imgproc.hpp>

namespace sightline {

namespace {

// Nearest integer, halves away from zero (std::lround without the library call), for |x| < 2^30.
int RoundToPixel(double x) {
  const double shifted = x + (x >= 0 ? 0.5 : -0.5);
  return static_cast<int>(shifted);  // Truncates towards zero.
}

}  // namespace

cv::Vec3b ScoreColorBgr(float score) {
  if (!std::isfinite(score)) return cv::Vec3b(128, 128, 128);
  const float s = std::clamp(score, 0.f, 1.f);
  const float red = s < 0.5f ? 1.f : 2.f * (1.f - s);
  const float green = s < 0.5f ? 2.f * s : 1.f;
  return cv::Vec3b(0, static_cast<uchar>(std::lround(220 * green)),
                   static_cast<uchar>(std::lround(230 * red)));
}

Eigen::Isometry3d GroundFromCamera(const GroundPlane& ground) {
  const Eigen::Vector3d z = ground.normal.normalized();
  Eigen::Vector3d x = Eigen::Vector3d::UnitZ() - z * z.z();
  if (x.norm() < 1e-6) x = Eigen::Vector3d::UnitX() - z * z.x();  // Looking straight down.
  x.normalize();
  const Eigen::Vector3d y = z.cross(x);
  Eigen::Matrix3d camera_from_ground_rotation;
  camera_from_ground_rotation << x, y, z;
  Eigen::Isometry3d camera_from_ground = Eigen::Isometry3d::Identity();
  camera_from_ground.linear() = camera_from_ground_rotation;
  camera_from_ground.translation() = -ground.d * z;  // The camera's foot on the ground.
  return camera_from_ground.inverse();
}

TopViewMap BuildTopView(const std::vector<Eigen::Vector3f>& points,
                        const std::vector<float>& scores, const GroundPlane& ground, double cell_m,
                        double range_m) {
  TopViewMap map;
  map.cell_m = cell_m;
  map.x_max_m = range_m;
  map.y_max_m = range_m;
  const int rows = std::max(1, static_cast<int>(std::ceil(range_m / cell_m)));
  const int cols = std::max(1, static_cast<int>(std::ceil(2 * range_m / cell_m)));
  map.score = cv::Mat(rows, cols, CV_32FC1, cv::Scalar(std::numeric_limits<float>::quiet_NaN()));
  if (!ground.found) return map;
  map.ground_from_camera = GroundFromCamera(ground);
  const Eigen::Matrix3f rotation = map.ground_from_camera.linear().cast<float>();
  const Eigen::Vector3f translation = map.ground_from_camera.translation().cast<float>();
  const float inv = static_cast<float>(1.0 / cell_m);
  float* cells = map.score.ptr<float>();  // Continuous: rows x cols.
  for (size_t i = 0; i < points.size(); ++i) {
    if (!std::isfinite(scores[i])) continue;
    const Eigen::Vector3f g = rotation * points[i] + translation;
    const double fr = (range_m - g.x()) * inv, fc = (range_m - g.y()) * inv;
    // Off the map either way (also guards the conversions below).
    if (!(fr >= 0 && fc >= 0 && fr < rows && fc < cols)) continue;
    const int r = static_cast<int>(fr), c = static_cast<int>(fc);  // Floor: non-negative.
    float& cell = cells[static_cast<size_t>(r) * cols + c];
    if (!(cell <= scores[i])) cell = scores[i];  // NaN or higher: take the lower score.
  }
  return map;
}

cv::Mat RenderTopView(const TopViewMap& map) {
  cv::Mat image(map.score.size(), CV_8UC3, cv::Scalar(60, 60, 60));
  for (int r = 0; r < map.score.rows; ++r) {
    for (int c = 0; c < map.score.cols; ++c) {
      const float s = map.score.at<float>(r, c);
      if (std::isfinite(s)) image.at<cv::Vec3b>(r, c) = ScoreColorBgr(s);
    }
  }
  // The camera's foot: a white mark at the bottom centre.
  cv::circle(image, cv::Point(image.cols / 2, image.rows - 1), 4, cv::Scalar(255, 255, 255), -1);
  return image;
}

cv::Mat ProjectScores(const std::vector<Eigen::Vector3f>& points, const std::vector<float>& scores,
                      const PinholeCamera& camera, const cv::Mat& color_bgr, double offset_x_m,
                      double offset_y_m, int dot_px) {
  cv::Mat base = color_bgr.empty()
                     ? cv::Mat(camera.height, camera.width, CV_8UC3, cv::Scalar(40, 40, 40))
                     : color_bgr.clone();
  if (base.channels() == 1) cv::cvtColor(base, base, cv::COLOR_GRAY2BGR);
  // Dots are blended straight into the pixels (one pass, no per-dot matrix operations).
  cv::Mat out = base;
  const int half = dot_px / 2;
  // Scores repeat along a segment: the colour of the last one is kept.
  float last_score = std::numeric_limits<float>::quiet_NaN();
  cv::Vec3b color;
  for (size_t i = 0; i < points.size(); ++i) {
    if (!std::isfinite(scores[i])) continue;
    const Eigen::Vector3f& p = points[i];
    if (!(p.z() > 0)) continue;
    const double inv_z = 1.0 / p.z();
    const double u = camera.fx * (p.x() + offset_x_m) * inv_z + camera.cx;
    const double v = camera.fy * (p.y() + offset_y_m) * inv_z + camera.cy;
    // Pixel of the dot's centre; far outside the image is the same as just outside it.
    const int px = RoundToPixel(std::clamp(u, -1e6, 1e6));
    const int py = RoundToPixel(std::clamp(v, -1e6, 1e6));
    if (dot_px == 1) {  // Full resolution: one pixel per point.
      if (px < 0 || py < 0 || px >= out.cols || py >= out.rows) continue;
      if (!(scores[i] == last_score)) color = ScoreColorBgr(scores[i]), last_score = scores[i];
      cv::Vec3b& pixel = out.ptr<cv::Vec3b>(py)[px];
      for (int c = 0; c < 3; ++c)
        pixel[c] = static_cast<uchar>((9 * pixel[c] + 11 * color[c]) / 20);
      continue;
    }
    const int x0 = std::max(0, px - half);
    const int y0 = std::max(0, py - half);
    const int x1 = std::min(out.cols, px - half + dot_px);
    const int y1 = std::min(out.rows, py - half + dot_px);
    if (x0 >= x1 || y0 >= y1) continue;
    if (!(scores[i] == last_score)) color = ScoreColorBgr(scores[i]), last_score = scores[i];
    for (int y = y0; y < y1; ++y) {
      cv::Vec3b* row = out.ptr<cv::Vec3b>(y);
      for (int x = x0; x < x1; ++x) {
        for (int c = 0; c < 3; ++c)
          row[x][c] = static_cast<uchar>((9 * row[x][c] + 11 * color[c]) / 20);
      }
    }
  }
  return out;
}

StatusOr<PinholeCamera> EstimateIntrinsics(const PointCloud& cloud) {
  if (!cloud.organized()) {
    return FailedPrecondition("intrinsics can only be recovered from an organized cloud");
  }
  // Normal equations of u = fx a + cx (a = x / z) and v = fy b + cy (b = y / z).
  Eigen::Matrix2d au = Eigen::Matrix2d::Zero(), av = Eigen::Matrix2d::Zero();
  Eigen::Vector2d bu = Eigen::Vector2d::Zero(), bv = Eigen::Vector2d::Zero();
  int used = 0;
  const int step = std::max(1, static_cast<int>(cloud.size() / 20000));
  for (size_t i = 0; i < cloud.size(); i += step) {
    const Eigen::Vector3f& p = cloud.points[i];
    if (!p.allFinite() || p.z() <= 0) continue;
    const double a = p.x() / p.z(), b = p.y() / p.z();
    const size_t column = i % cloud.width, row = i / cloud.width;
    const double u = static_cast<double>(column), v = static_cast<double>(row);
    au += Eigen::Vector2d(a, 1) * Eigen::Vector2d(a, 1).transpose();
    bu += Eigen::Vector2d(a, 1) * u;
    av += Eigen::Vector2d(b, 1) * Eigen::Vector2d(b, 1).transpose();
    bv += Eigen::Vector2d(b, 1) * v;
    ++used;
  }
  if (used < 100) {
    return FailedPrecondition("too few valid points (" + std::to_string(used) +
                              ") to recover the cloud's intrinsics");
  }
  const Eigen::Vector2d fu = au.ldlt().solve(bu), fv = av.ldlt().solve(bv);
  PinholeCamera camera;
  camera.width = cloud.width;
  camera.height = cloud.height;
  camera.fx = fu(0), camera.cx = fu(1), camera.fy = fv(0), camera.cy = fv(1);
  if (!(camera.fx > 0 && camera.fy > 0)) {
    return FailedPrecondition("the cloud's points do not follow a pinhole camera");
  }
  return camera;
}

cv::Mat CloudColorImage(const PointCloud& cloud) {
  if (!cloud.organized() || !cloud.has_colors()) return cv::Mat();
  cv::Mat image(cloud.height, cloud.width, CV_8UC3);
  for (int r = 0; r < cloud.height; ++r) {
    for (int c = 0; c < cloud.width; ++c) {
      const auto& rgb = cloud.colors[static_cast<size_t>(r) * cloud.width + c];
      image.at<cv::Vec3b>(r, c) = cv::Vec3b(rgb[2], rgb[1], rgb[0]);
    }
  }
  return image;
}

}  // namespace sightline
