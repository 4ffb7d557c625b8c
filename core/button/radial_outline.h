// Closed outlines around a point found on the unthresholded image gradient. Along rays from
// the point the blurred image is sampled in polar form; in each of a few radius bands a dynamic
// programme finds the closed path of strongest radial edges (one radius per ray, neighbouring
// rays at most 0.3 radii apart). A path is an outline when most of its rays lie on an edge that
// is both min_edge strong and min_contrast times the median edge along that ray in the band
// (the strongest path through a texture does not stand out of it). No threshold on an edge map
// decides whether the outline exists, so a faint or thin ring that Canny breaks still closes.
#pragma once

#include <opencv2/core.hpp>
#include <vector>

namespace sightline {

struct RadialOutlineOptions {
  int rays = 64;               // Angular samples.
  double min_radius_px = 3;    // Smallest outline radius searched [px].
  double max_radius_px = 120;  // Largest [px].
  double band_ratio = 2.6;     // Each band spans [r, band_ratio r]; bands start 1.6x apart.
  double min_edge = 4;         // Edge a ray must reach [grey levels per px] ...
  double min_contrast = 3;     // ... and this many times the median edge of its band.
  double min_support = 0.75;   // Fraction of rays on such an edge.
  double blur_sigma_px = 1.2;  // Gaussian blur of the image before sampling [px].
};

struct RadialOutline {
  std::vector<cv::Point> points;  // One per ray, image pixels.
  double support = 0;             // Fraction of rays on an edge (see above).
};

// Outlines around `centre` in `grey` (CV_8UC1), at most one per radius band, smallest band
// first. Only the disc the rays reach is read.
std::vector<RadialOutline> RadialOutlines(const cv::Mat& grey, cv::Point2d centre,
                                          const RadialOutlineOptions& options);

}  // namespace sightline
