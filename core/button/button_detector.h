// Button detection from a tap (the seed's plan phase): outlines of the still frame's edges,
// each closed by its convex hull, the one that best fits the tap, its region, and SIFT
// features on it. Two methods:
//  - multiscale (default): in a window around the tap, contours of the edges at two blurs and
//    two Canny threshold pairs plus Hough circles confirmed by edges along their rim (round
//    buttons with a thin ring); the region that contains the tap with its centroid nearest
//    the tap relative to its radius (at most max_centre_offset radii away; size_bias_px favours
//    the button's outline over a glyph on it), skipping regions that hold other buttons. When
//    no region fits, the closed outlines of the strongest radial edges around the tap
//    (radial_outline.h, on the full-resolution frame; faint rims and thin rings whose Canny
//    contours break): the one with most rays on an edge, among equals the smaller.
//  - seed: the seed's rule, contours at one scale and the centroid nearest the tap within
//    max_tap_distance_px (on real panels it selects a neighbouring button or a label more often).
// Both skip a region that holds, besides a smaller region at the tap, two or more regions like
// that one: a plate full of buttons, whose centroid relative to its size can lie nearer the tap
// than the small tapped button's own.
// No region fits the tap: "no button here", the operator is asked to tap again.
#pragma once

#include <memory>
#include <opencv2/core.hpp>
#include <string>
#include <utility>

#include "core/button/button_model.h"
#include "core/common/status.h"
#include "core/options/option_table.h"

namespace sightline {

// Detector options. Keys "button.detect.*". Pixel sizes refer to the working image, the still
// frame scaled so its longer side is at most working_size_px.
struct ButtonDetectorOptions {
  std::string method = "multiscale";  // multiscale or seed (see the file comment).
  int working_size_px = 960;          // Longer image side the contours are searched at [px].
  double blur_sigma_px = 1.2;         // Gaussian blur before edge detection [px].
  double canny_low = 30;              // Canny lower hysteresis threshold [grey levels].
  double canny_high = 90;             // Canny upper hysteresis threshold [grey levels].
  int close_px = 3;                   // Morphological closing of the edge map (0 = none) [px].
  double min_area_px = 150;           // Smallest region area [px^2].
  double max_area_fraction = 0.08;    // Largest region area as a fraction of the image.
  double min_coverage = 0.75;         // Fraction of directions (16 sectors) around a region's
                                      // centre in which its outline lies.
  double max_aspect = 3.0;            // Longest / shortest side of the rotated bounding box.
  double max_tap_distance_px = 35;    // seed: centroid farther from the tap: not this button [px].
  // multiscale only:
  double search_radius_px = 200;    // Half size of the window around the tap searched [px].
  double second_blur = 2.0;         // The second scale's blur, times blur_sigma_px.
  double canny_spread = 2.0;        // Two Canny pairs: (canny_low, canny_high) times
                                    // 2 / (1 + spread) and 2 spread / (1 + spread).
  double max_centre_offset = 0.85;  // Region centroid at most this many radii from the tap.
  double region_max_aspect = 2.2;   // Longest / shortest side of a region (max_aspect: seed).
  double size_bias_px = 4;      // Ranking (offset + bias) / radius: of the regions about the tap,
                                // the larger (the button around its glyph) wins [px].
  bool circles = true;          // Add Hough circles (round buttons with a thin ring).
  double circle_votes = 28;     // Hough accumulator threshold.
  double circle_support = 0.6;  // Fraction of the circle's rim on an edge to keep it.
  double circle_min_radius_px = 8;    // Smallest circle radius [px].
  double circle_max_radius_px = 120;  // Largest circle radius [px].
  bool radial = true;                 // No region at the tap: closed outlines of the strongest
                                      // radial edges around it (radial_outline.h).
  double radial_min_edge = 4;         // Edge a ray of such an outline must reach [grey/px].
  double radial_min_contrast = 3;     // ... and this many times the ray's median edge.
  double sift_margin_px = 8;          // Features up to this far outside the region are kept [px]
  double sift_margin_radius = 5.0;    // ... or this many region radii, if larger.
  double sift_max_radius_px = 12;     // Larger regions: SIFT on the crop scaled down so the
                                      // region's radius is this [px] (0 = never scaled).
  int min_keypoints = 3;              // Fewer SIFT keypoints: the button cannot be tracked.
  double sift_contrast = 0.01;  // SIFT contrast threshold (lower finds more on plain buttons).
  // The region classifier's probability that the selected region is a button, not a printed
  // label (region_classifier.h); lower: "no button here". 0 = not used.
  double min_button_probability = 0;

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
  explicit ButtonDetector(ButtonDetectorOptions options = {}) : options_(std::move(options)) {}

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
