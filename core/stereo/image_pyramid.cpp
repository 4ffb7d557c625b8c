#include "core/stereo/image_pyramid.h"

#include <opencv2/video/tracking.hpp>

namespace sightline {

ImagePyramid BuildImagePyramid(const cv::Mat& image, int window_px, int max_level) {
  ImagePyramid pyramid;
  pyramid.image = image;
  pyramid.max_level =
      cv::buildOpticalFlowPyramid(image, pyramid.levels, cv::Size(window_px, window_px), max_level,
                                  /*withDerivatives=*/true);
  return pyramid;
}

}  // namespace sightline
