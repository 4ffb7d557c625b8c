// An image pyramid built once per image (cv::buildOpticalFlowPyramid) and shared by temporal
// tracking (previous left -> current left) and stereo matching (left <-> right).
#pragma once

#include <opencv2/core.hpp>
#include <vector>

namespace sightline {

// The pyramid of one CV_8UC1 image with Scharr derivatives, as calcOpticalFlowPyrLK takes it.
struct ImagePyramid {
  cv::Mat image;                // Level 0 (the image itself).
  std::vector<cv::Mat> levels;  // buildOpticalFlowPyramid's output (image, derivative, ...).
  int max_level = 0;            // Deepest level built.

  bool empty() const { return levels.empty(); }
  // The image at level l (0 = full resolution).
  const cv::Mat& Level(int l) const { return levels[2 * static_cast<size_t>(l)]; }
  // The Scharr derivatives (dx, dy; CV_16SC2) of level l.
  const cv::Mat& Derivatives(int l) const { return levels[2 * static_cast<size_t>(l) + 1]; }
};

// Builds levels 0..max_level for KLT windows up to window_px.
ImagePyramid BuildImagePyramid(const cv::Mat& image, int window_px, int max_level);

}  // namespace sightline
