// Synthetic inputs for the stereo tests: a rectified camera, 3D points seen at two times with a
// known motion (plus outliers and pixel noise), and textured images.
#pragma once

#include <Eigen/Geometry>
#include <opencv2/core.hpp>
#include <vector>

#include "core/stereo/stereo_correspondence.h"
#include "core/stereo/stereo_geometry.h"

namespace sightline::testing {

// 640x480, f = 500 px, baseline 0.12 m.
RectifiedStereoCamera TestCamera();

// A small rotation about an oblique axis and a translation mostly forward.
Eigen::Isometry3d TestMotion();

// `count` points 3..30 m ahead observed before and after `current_from_previous`, with Gaussian
// pixel noise; the first outlier_count correspondences get a random current observation.
std::vector<StereoCorrespondence> SyntheticCorrespondences(
    const RectifiedStereoCamera& camera, const Eigen::Isometry3d& current_from_previous, int count,
    int outlier_count, double noise_px, unsigned seed);

// A CV_8UC1 image of random blurred blobs (good corners everywhere).
cv::Mat TexturedImage(cv::Size size, unsigned seed);

// `image` shifted by (dx, dy) with bilinear interpolation (content moves right/down for > 0).
cv::Mat Shifted(const cv::Mat& image, double dx, double dy);

// Rotation angle of a.inverse() * b [deg] and translation distance [m].
double RotationErrorDeg(const Eigen::Isometry3d& a, const Eigen::Isometry3d& b);
double TranslationErrorM(const Eigen::Isometry3d& a, const Eigen::Isometry3d& b);

}  // namespace sightline::testing
