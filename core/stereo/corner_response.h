// The Shi-Tomasi corner response (smallest eigenvalue of the gradient covariance) computed from
// the Scharr derivatives that the KLT pyramid already holds, so detection does not differentiate
// the image a second time. Scaled to cv::cornerMinEigenVal's units with a 3x3 Sobel aperture.
#pragma once

#include <opencv2/core.hpp>

namespace sightline {

// Minimum eigenvalue of the block_size x block_size gradient covariance at every pixel of
// `region` (in the derivative image's coordinates), written to *response (CV_32FC1, region's
// size). `derivatives` is a CV_16SC2 Scharr (dx, dy) image as cv::buildOpticalFlowPyramid makes
// it. Pixels whose block would leave the image get 0.
//
//   MinEigenResponse(pyramid.Derivatives(0), cv::Rect(0, 0, w, h), 3, &response);
void MinEigenResponse(const cv::Mat& derivatives, const cv::Rect& region, int block_size,
                      cv::Mat* response);

// On x86-64 CPUs with AVX2 the response's loops run eight columns at a time, with the same
// operations in the same order (identical values). Turning that off (tests compare the two
// paths) is process-wide and not thread-safe; returns whether the CPU has AVX2.
bool SetCornerResponseAvx2(bool enabled);

}  // namespace sightline
