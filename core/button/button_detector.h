// Button detection from a tap (the seed's plan phase): contours of the still frame's edges,
// each closed by its convex hull, the one whose centroid lies nearest the tap (within a limit,
// relative to its size), its region, and SIFT features on it.
// No contour near the tap means "no button here": the operator is asked to tap again.
#pragma once

#include <memory>
#include <opencv2/core.hpp>
#include <string>

#include "core/button/button_model.h"
#include "core/common/status.h"
#include "core/options/option_table.h"

namespace sightline {

// Detector options. Keys "button.detect.*". Pixel sizes refer to the working image, the still
// frame scaled so its longer side is at most working_size_px.
struct ButtonDetectorOptions {
  int working_size_px = 960;        // Longer image side the contours are searched at [px].
  double blur_sigma_px = 1.2;       // Gaussian blur before edge detection [px].
  double canny_low = 30;            // Canny lower hysteresis threshold [grey levels].
  double canny_high = 90;           // Canny upper hysteresis threshold [grey levels].
  int close_px = 3;                 // Morphological closing of the edge map (0 = none) [px].
  double min_area_px = 150;         // Smallest region area [px^2].
  double max_area_fraction = 0.08;  // Largest region area as a fraction of the image.
  double min_coverage = 0.75;       // Fraction of directions (16 sectors) around a region's
                                    // centre in which its outline lies.
  double max_aspect = 3.0;          // Longest / shortest side of the rotated bounding box.
  double max_tap_distance_px = 35;  // Centroid farther from the tap: not this button [px].
  double sift_margin_px = 8;        // Features up to this far outside the region are kept [px]
  double sift_margin_radius = 5.0;  // ... or this many region radii, if larger.
  int min_keypoints = 3;            // Fewer SIFT keypoints: the button cannot be tracked.
  double sift_contrast = 0.01;      // SIFT contrast threshold (lower finds more on plain buttons).

  bool IsValid(std::string* error) const;
  static OptionTable<ButtonDetectorOptions> Describe();
};

// Stateless; constructible many times; thread-safe (each call builds its own SIFT).
//
//   ButtonDetector detector(options);
//   StatusOr<std::shared_ptr<const ButtonModel>> model = detector.Detect(frame, {412, 230});
//   if (model.status().code() == StatusCode::kNotFound) AskAgain(model.status().message());
class ButtonDetector {
 public:
  explicit ButtonDetector(ButtonDetectorOptions options = {}) : options_(options) {}

  // The button under (or nearest) the tap. NotFound ("no button here ...") when no compact
  // region lies within the limit, or when it has too few features to track; InvalidArgument
  // for an empty image or a tap outside it.
  StatusOr<std::shared_ptr<const ButtonModel>> Detect(const cv::Mat& image, cv::Point2d tap) const;

  // Only the region step (no features): used by tests and the operator panel's outline.
  StatusOr<ButtonModel> FindRegion(const cv::Mat& image, cv::Point2d tap) const;

  const ButtonDetectorOptions& options() const { return options_; }

 private:
  ButtonDetectorOptions options_;
};

// Grey CV_8UC1 view of a BGR, BGRA or grey 8-bit image (shared when already grey).
cv::Mat ToGrey(const cv::Mat& image);

}  // namespace sightline
