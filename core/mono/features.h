// ORB keypoints and descriptors of one image, undistorted and binned in a grid for window
// searches; and the geometry shared by initialisation, tracking and mapping.
#pragma once

#include <Eigen/Geometry>
#include <cstdint>
#include <cstring>
#include <opencv2/core.hpp>
#include <opencv2/features2d.hpp>

#include "core/common/camera.h"
#include "core/mono/mono_options.h"
#include "core/mono/slam_map.h"

namespace sightline {

// Extracts ORB features. One per thread (holds the detector).
//
//   FeatureExtractor extractor(options.features, camera);
//   FrameFeatures f = extractor.Extract(grey_image);
class FeatureExtractor {
 public:
  FeatureExtractor(const MonoFeatureOptions& options, const PinholeCamera& camera);
  // `image` CV_8UC1 or CV_8UC3; an empty or uniform image gives no keypoints.
  FrameFeatures Extract(const cv::Mat& image) const;
  // Pixel size of a keypoint's level relative to level 0 (scale_factor^octave).
  double LevelScale(int octave) const;

 private:
  MonoFeatureOptions options_;
  PinholeCamera camera_;
  cv::Ptr<cv::ORB> orb_;
};

// Hamming distance of two 32-byte ORB descriptors.
inline int DescriptorDistance(const uint8_t* a, const uint8_t* b) {
  int d = 0;
  for (int i = 0; i < 32; i += 8) {
    uint64_t x, y;
    std::memcpy(&x, a + i, 8);
    std::memcpy(&y, b + i, 8);
    d += __builtin_popcountll(x ^ y);
  }
  return d;
}
inline int DescriptorDistance(const cv::Mat& a, const cv::Mat& b) {
  return DescriptorDistance(a.ptr<uint8_t>(), b.ptr<uint8_t>());
}

// Pixel of a point in the camera frame; no distortion (keypoints are undistorted).
inline Eigen::Vector2d ProjectToPixel(const PinholeCamera& camera, const Eigen::Vector3d& x) {
  return Eigen::Vector2d(camera.fx * x.x() / x.z() + camera.cx,
                         camera.fy * x.y() / x.z() + camera.cy);
}

// Normalised image coordinates (x/z, y/z) of a pixel.
inline Eigen::Vector2d Normalised(const PinholeCamera& camera, const Eigen::Vector2d& pixel) {
  return Eigen::Vector2d((pixel.x() - camera.cx) / camera.fx, (pixel.y() - camera.cy) / camera.fy);
}

// Linear (DLT) triangulation of one point seen in two views (normalised coordinates). Returns
// false when the system is degenerate.
bool Triangulate(const Eigen::Isometry3d& a_from_map, const Eigen::Isometry3d& b_from_map,
                 const Eigen::Vector2d& a_normalised, const Eigen::Vector2d& b_normalised,
                 Eigen::Vector3d* x_in_map);

// Angle between the rays from two camera centres to a point [deg].
double ParallaxDeg(const Eigen::Vector3d& x, const Eigen::Vector3d& centre_a,
                   const Eigen::Vector3d& centre_b);

// Checks a triangulated point: in front of both cameras, ray angle >= min_parallax_deg and
// reprojection error <= max_px (scaled by each keypoint's level) in both.
bool AcceptTriangulated(const PinholeCamera& camera, const Eigen::Vector3d& x,
                        const Eigen::Isometry3d& a_from_map, const Eigen::Isometry3d& b_from_map,
                        const Eigen::Vector2d& a_pixel, const Eigen::Vector2d& b_pixel,
                        double a_scale, double b_scale, double min_parallax_deg, double max_px);

}  // namespace sightline
