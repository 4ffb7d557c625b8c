// What the detector learns about the button the operator tapped: its region in the still
// frame and the SIFT features the tracker looks for in later frames.
#pragma once

#include <memory>
#include <opencv2/core.hpp>
#include <opencv2/features2d.hpp>
#include <vector>

namespace sightline {

// The tapped button in the still frame (full-resolution pixel coordinates). Immutable once
// built; shared as std::shared_ptr<const ButtonModel>.
struct ButtonModel {
  cv::Point2d tap;                      // Where the operator tapped.
  cv::Point2d center;                   // Centroid of the button's region.
  cv::Rect box;                         // Bounding box of the region.
  std::vector<cv::Point> contour;       // Outline of the region.
  double area_px = 0;                   // Region area, pixels^2.
  std::vector<cv::KeyPoint> keypoints;  // SIFT keypoints on and around the region.
  cv::Mat descriptors;                  // CV_32F, one row per keypoint.
  cv::Size image_size;                  // Size of the still frame.
  double button_probability = 1;        // The region classifier's, when it was asked.

  // Radius of a disc of the region's area, pixels.
  double RadiusPx() const;
};

}  // namespace sightline
