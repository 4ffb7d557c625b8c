#include "core/button/button_detector.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <opencv2/features2d.hpp>
#include <opencv2/imgproc.hpp>
#include <optional>

#include "core/button/option_check.h"
#include "core/button/radial_outline.h"
#include "core/button/region_classifier.h"

namespace sightline {

using button_internal::Invalid;

double ButtonModel::RadiusPx() const { return std::sqrt(std::max(area_px, 0.0) / M_PI); }

bool ButtonDetectorOptions::IsValid(std::string* error) const {
  if (method != "multiscale" && method != "seed") {
    return Invalid(error, "button.detect.method must be multiscale or seed");
  }
  if (working_size_px < 160 || working_size_px > 8192) {
    return Invalid(error, "button.detect.working_size_px must lie in [160, 8192]");
  }
  if (!(blur_sigma_px >= 0 && blur_sigma_px <= 20)) {
    return Invalid(error, "button.detect.blur_sigma_px must lie in [0, 20]");
  }
  if (!(canny_low > 0 && canny_high > canny_low)) {
    return Invalid(error, "button.detect.canny_low must be > 0 and below canny_high");
  }
  if (close_px < 0 || close_px > 31)
    return Invalid(error, "button.detect.close_px must lie in [0, 31]");
  if (!(min_area_px >= 4)) return Invalid(error, "button.detect.min_area_px must be >= 4");
  if (!(max_area_fraction > 0 && max_area_fraction <= 1)) {
    return Invalid(error, "button.detect.max_area_fraction must lie in (0, 1]");
  }
  if (!(min_coverage >= 0 && min_coverage <= 1)) {
    return Invalid(error, "button.detect.min_coverage must lie in [0, 1]");
  }
  if (!(max_aspect >= 1)) return Invalid(error, "button.detect.max_aspect must be >= 1");
  if (!(max_tap_distance_px > 0))
    return Invalid(error, "button.detect.max_tap_distance_px must be > 0");
  if (!(sift_margin_px >= 0)) return Invalid(error, "button.detect.sift_margin_px must be >= 0");
  if (!(sift_margin_radius >= 0))
    return Invalid(error, "button.detect.sift_margin_radius must be >= 0");
  if (!(search_radius_px >= 16))
    return Invalid(error, "button.detect.search_radius_px must be >= 16");
  if (!(second_blur >= 1 && second_blur <= 10)) {
    return Invalid(error, "button.detect.second_blur must lie in [1, 10]");
  }
  if (!(canny_spread >= 1 && canny_spread <= 10)) {
    return Invalid(error, "button.detect.canny_spread must lie in [1, 10]");
  }
  if (!(max_centre_offset > 0 && max_centre_offset <= 1)) {
    return Invalid(error, "button.detect.max_centre_offset must lie in (0, 1]");
  }
  if (!(region_max_aspect >= 1))
    return Invalid(error, "button.detect.region_max_aspect must be >= 1");
  if (!(size_bias_px >= 0)) return Invalid(error, "button.detect.size_bias_px must be >= 0");
  if (!(circle_votes >= 1)) return Invalid(error, "button.detect.circle_votes must be >= 1");
  if (!(circle_support >= 0 && circle_support <= 1)) {
    return Invalid(error, "button.detect.circle_support must lie in [0, 1]");
  }
  if (!(circle_min_radius_px >= 2 && circle_max_radius_px > circle_min_radius_px)) {
    return Invalid(
        error, "button.detect.circle_min_radius_px must be >= 2 and below circle_max_radius_px");
  }
  if (!(radial_min_contrast >= 1 && radial_min_contrast <= 100)) {
    return Invalid(error, "button.detect.radial_min_contrast must lie in [1, 100]");
  }
  if (!(radial_min_edge > 0 && radial_min_edge <= 255)) {
    return Invalid(error, "button.detect.radial_min_edge must lie in (0, 255]");
  }
  if (!(sift_max_radius_px == 0 || (sift_max_radius_px >= 4 && sift_max_radius_px <= 1000))) {
    return Invalid(error, "button.detect.sift_max_radius_px must be 0 or lie in [4, 1000]");
  }
  if (min_keypoints < 1) return Invalid(error, "button.detect.min_keypoints must be >= 1");
  if (!(sift_contrast > 0 && sift_contrast < 1)) {
    return Invalid(error, "button.detect.sift_contrast must lie in (0, 1)");
  }
  if (!(min_button_probability >= 0 && min_button_probability < 1)) {
    return Invalid(error, "button.detect.min_button_probability must lie in [0, 1)");
  }
  return true;
}

OptionTable<ButtonDetectorOptions> ButtonDetectorOptions::Describe() {
  using O = ButtonDetectorOptions;
  return OptionTable<O>("button.detect")
      .Choice("method", &O::method, {"multiscale", "seed"},
              "Region from the tap: outlines at two scales plus Hough circles, the one holding "
              "the tap nearest its centre (multiscale), or the published rule (the centroid "
              "nearest the tap within max_tap_distance_px).")
      .Int("working_size_px", &O::working_size_px, "px", 160, 8192, 32,
           "Longer image side at which contours are searched; larger frames are scaled down.")
      .Double("blur_sigma_px", &O::blur_sigma_px, "px", 0, 20, 0.1,
              "Gaussian blur before edge detection.")
      .Double("canny_low", &O::canny_low, "grey", 1, 1000, 1, "Canny lower threshold.")
      .Double("canny_high", &O::canny_high, "grey", 2, 2000, 1, "Canny upper threshold.")
      .Int("close_px", &O::close_px, "px", 0, 31, 1,
           "Morphological closing that joins broken button outlines; 0 = none.")
      .Double("min_area_px", &O::min_area_px, "px^2", 4, 1e6, 10, "Smallest button region.")
      .Double("max_area_fraction", &O::max_area_fraction, "", 0.0001, 1, 0.005,
              "Largest button region as a fraction of the image area.")
      .Double("min_coverage", &O::min_coverage, "", 0, 1, 1.0 / 16,
              "Fraction of directions around a region's centre in which its outline lies; a "
              "button's (even broken) outline surrounds its centre.")
      .Double("max_aspect", &O::max_aspect, "", 1, 20, 0.1,
              "Longest over shortest side of the region's rotated box.")
      .Double("max_tap_distance_px", &O::max_tap_distance_px, "px", 1, 1000, 1,
              "A region whose centroid is farther from the tap and that does not contain it is "
              "not the tapped button (published method).")
      .Double("search_radius_px", &O::search_radius_px, "px", 16, 4096, 8,
              "multiscale: half size of the window around the tap that is searched.")
      .Double("second_blur", &O::second_blur, "", 1, 10, 0.1,
              "multiscale: blur of the second scale, times blur_sigma_px.")
      .Double("canny_spread", &O::canny_spread, "", 1, 10, 0.1,
              "multiscale: the two Canny pairs are the thresholds times 2/(1+s) and 2s/(1+s).")
      .Double("max_centre_offset", &O::max_centre_offset, "radii", 0.05, 1, 0.05,
              "multiscale: the region's centroid lies at most this many radii from the tap.")
      .Double("region_max_aspect", &O::region_max_aspect, "", 1, 20, 0.1,
              "multiscale: longest over shortest side of a region's rotated box.")
      .Double("size_bias_px", &O::size_bias_px, "px", 0, 100, 1,
              "multiscale: regions are ranked by (offset + bias) / radius, so the button's "
              "outline wins over a glyph on it.")
      .Bool("circles", &O::circles, "multiscale: add Hough circles (round buttons, thin rings).")
      .Double("circle_votes", &O::circle_votes, "", 1, 500, 1, "Hough accumulator threshold.")
      .Double("circle_support", &O::circle_support, "", 0, 1, 0.05,
              "Fraction of a circle's rim that must lie on an edge.")
      .Double("circle_min_radius_px", &O::circle_min_radius_px, "px", 2, 1000, 1,
              "Smallest Hough circle radius.")
      .Double("circle_max_radius_px", &O::circle_max_radius_px, "px", 3, 4000, 1,
              "Largest Hough circle radius.")
      .Bool("radial", &O::radial,
            "multiscale: when no outline holds the tap, look for closed outlines of the "
            "strongest radial edges around it (faint or thin-ringed buttons).")
      .Double("radial_min_edge", &O::radial_min_edge, "grey/px", 0.5, 255, 0.5,
              "Edge strength most rays of such an outline must reach.")
      .Double("radial_min_contrast", &O::radial_min_contrast, "", 1, 100, 0.1,
              "A ray of such an outline is on an edge when that edge is also this many times "
              "the median edge along the ray in its radius band (texture stands out less).")
      .Double("sift_margin_px", &O::sift_margin_px, "px", 0, 200, 1,
              "SIFT keypoints up to this far outside the region belong to the button model.")
      .Double("sift_margin_radius", &O::sift_margin_radius, "radii", 0, 20, 0.1,
              "The SIFT margin grows to this many region radii when that is larger.")
      .Double("sift_max_radius_px", &O::sift_max_radius_px, "px", 0, 1000, 1,
              "SIFT on a larger region runs on its crop scaled down so the region's radius is "
              "this (fewer, coarser features, much faster on close-up photos); 0 = never.")
      .Int("min_keypoints", &O::min_keypoints, "", 1, 1000, 1,
           "Fewer SIFT keypoints on the region: the button cannot be tracked.")
      .Double("sift_contrast", &O::sift_contrast, "", 0.001, 0.5, 0.005,
              "SIFT contrast threshold; lower finds more keypoints on plain buttons.")
      .Double("min_button_probability", &O::min_button_probability, "", 0, 0.99, 0.05,
              "The appearance model's probability that the region at the tap is a button and "
              "not a printed label or sign beside one; below it: no button here. 0 = off.");
}

cv::Mat ToGrey(const cv::Mat& image) {
  if (image.type() == CV_8UC1) return image;
  cv::Mat grey;
  if (image.type() == CV_8UC3)
    cv::cvtColor(image, grey, cv::COLOR_BGR2GRAY);
  else if (image.type() == CV_8UC4)
    cv::cvtColor(image, grey, cv::COLOR_BGRA2GRAY);
  return grey;
}

namespace {

struct Candidate {
  std::vector<cv::Point> contour;  // Working-image pixels.
  cv::Point2d centroid;
  double area = 0;
};

// Fraction of 16 angular sectors around `centre` that hold a contour point at least
// `min_dist` away: a button's outline surrounds its centre even when it is broken (a U of
// light on a bezel); a stroke of a label or a texture speck does not.
double AngularCoverage(const std::vector<cv::Point>& contour, cv::Point2d centre, double min_dist) {
  constexpr int kSectors = 16;
  bool seen[kSectors] = {};
  for (const cv::Point& p : contour) {
    const double dx = p.x - centre.x, dy = p.y - centre.y;
    if (dx * dx + dy * dy < min_dist * min_dist) continue;
    const int k = int((std::atan2(dy, dx) + M_PI) / (2 * M_PI) * kSectors) % kSectors;
    seen[k] = true;
  }
  int n = 0;
  for (bool b : seen) n += b ? 1 : 0;
  return double(n) / kSectors;
}

// The convex hull of `contour` as a candidate when its area lies in [min_area, max_area] and
// its bounding rectangle is no longer than `max_aspect` times its width; nullopt otherwise.
std::optional<Candidate> CompactHull(const std::vector<cv::Point>& contour, double min_area,
                                     double max_area, double max_aspect) {
  std::vector<cv::Point> hull;
  cv::convexHull(contour, hull);
  const cv::Moments m = cv::moments(hull);
  const double area = m.m00;
  if (area < min_area || area > max_area) return std::nullopt;
  const cv::RotatedRect box = cv::minAreaRect(hull);
  const double lo = std::min(box.size.width, box.size.height);
  const double hi = std::max(box.size.width, box.size.height);
  if (lo <= 0 || hi / lo > max_aspect) return std::nullopt;
  Candidate c;
  c.centroid = {m.m10 / area, m.m01 / area};
  c.area = area;
  c.contour = std::move(hull);
  return c;
}

// Button-like regions of the edge map, in working-image pixels: the convex hull of every
// contour that is compact and surrounds its own centre.
std::vector<Candidate> Candidates(const cv::Mat& grey, const ButtonDetectorOptions& o) {
  cv::Mat blurred;  // A new image: `grey` may be the caller's.
  if (o.blur_sigma_px > 0) {
    cv::GaussianBlur(grey, blurred, cv::Size(0, 0), o.blur_sigma_px);
  } else {
    blurred = grey;
  }
  cv::Mat edges;
  cv::Canny(blurred, edges, o.canny_low, o.canny_high);
  if (o.close_px > 0) {
    const cv::Mat kernel =
        cv::getStructuringElement(cv::MORPH_ELLIPSE, cv::Size(o.close_px, o.close_px));
    cv::morphologyEx(edges, edges, cv::MORPH_CLOSE, kernel);
  }
  std::vector<std::vector<cv::Point>> contours;
  cv::findContours(edges, contours, cv::RETR_LIST, cv::CHAIN_APPROX_NONE);
  const double max_area = o.max_area_fraction * grey.cols * grey.rows;
  std::vector<Candidate> out;
  for (const auto& contour : contours) {
    std::optional<Candidate> c = CompactHull(contour, o.min_area_px, max_area, o.max_aspect);
    if (!c) continue;
    const double radius = std::sqrt(c->area / M_PI);
    if (AngularCoverage(contour, c->centroid, 0.5 * radius) < o.min_coverage) continue;
    out.push_back(std::move(*c));
  }
  return out;
}

// True when `outer` holds, besides a smaller region at the tap, two or more other regions of
// about that region's size (half to twice its area) that the tap is not on: a plate or a group
// of buttons whose one button at the tap is itself a region. A button's glyphs are either not
// alike or fewer than two besides the one at the tap.
bool HoldsRegionsLikeTheTapped(const Candidate& outer, const std::vector<Candidate>& all,
                               cv::Point2d tap) {
  for (const Candidate& t : all) {
    if (&t == &outer || t.area > 0.25 * outer.area) continue;
    if (cv::pointPolygonTest(t.contour, cv::Point2f(tap), false) < 0) continue;
    const double rt = std::sqrt(t.area / M_PI);
    std::vector<cv::Point2d> alike;
    for (const Candidate& c : all) {
      if (&c == &outer || c.area < 0.5 * t.area || c.area > 2 * t.area) continue;
      if (cv::norm(c.centroid - t.centroid) < 1.5 * rt) continue;
      if (cv::pointPolygonTest(c.contour, cv::Point2f(tap), false) >= 0) continue;
      if (cv::pointPolygonTest(outer.contour, cv::Point2f(c.centroid), false) <= 0) continue;
      bool seen = false;
      for (const cv::Point2d& a : alike) seen = seen || cv::norm(c.centroid - a) < rt;
      if (seen) continue;
      alike.push_back(c.centroid);
      if (alike.size() >= 2) return true;
    }
  }
  return false;
}

// True when `outer` holds at least two other regions away from its centre that the tap is not
// on: a panel plate or a group of buttons rather than one button (whose label sits near its
// centre).
bool IsGroup(const Candidate& outer, const std::vector<Candidate>& all,
             const std::vector<bool>& on_tap) {
  const double off_centre = 0.4 * std::sqrt(outer.area / M_PI);
  int others = 0;
  for (size_t i = 0; i < all.size(); ++i) {
    const Candidate& c = all[i];
    if (&c == &outer || on_tap[i] || c.area >= outer.area || c.area < 0.01 * outer.area) continue;
    if (cv::norm(c.centroid - outer.centroid) < off_centre) continue;
    if (cv::pointPolygonTest(outer.contour, cv::Point2f(c.centroid), false) > 0) ++others;
  }
  return others >= 2;
}

// The candidate for a tap: centroid distance relative to the region's size, so a tap on a
// button prefers the button's outline over a small label printed on it; regions that hold
// other buttons (plates, groups) are skipped.
const Candidate* Choose(const std::vector<Candidate>& candidates, cv::Point2d tap,
                        double max_dist) {
  std::vector<bool> on_tap(candidates.size());
  for (size_t i = 0; i < candidates.size(); ++i) {
    on_tap[i] = cv::pointPolygonTest(candidates[i].contour, cv::Point2f(tap), false) >= 0;
  }
  const Candidate* best = nullptr;
  double best_score = 0;
  for (size_t i = 0; i < candidates.size(); ++i) {
    const Candidate& c = candidates[i];
    const double dist = std::hypot(c.centroid.x - tap.x, c.centroid.y - tap.y);
    if (!on_tap[i] && dist > max_dist) continue;
    const double radius = std::sqrt(c.area / M_PI);
    if (on_tap[i] && dist > radius) continue;  // Tap inside a bent or lopsided outline.
    const double score = dist / radius;
    if (best && score >= best_score) continue;
    if (IsGroup(c, candidates, on_tap) || HoldsRegionsLikeTheTapped(c, candidates, tap)) continue;
    best = &c;
    best_score = score;
  }
  return best;
}

// Multiscale candidates in `window` of the working image, in working-image pixels: the
// convex hulls of compact contours of the edges at two blurs and two Canny pairs, and Hough
// circles whose rim lies on edges.
//
// The scales blur `work`'s window in place, one after the other: the second scale sees the
// first's blur (its sigma is in effect sqrt(1 + second_blur^2) times blur_sigma_px) and the
// circles the second's; the window's surroundings stay unblurred. `work` is the detector's own.
std::vector<Candidate> MultiScaleCandidates(cv::Mat& work, cv::Rect window,
                                            const ButtonDetectorOptions& o) {
  cv::Mat grey = work(window);
  const double max_area = o.max_area_fraction * work.cols * work.rows;
  const double s = o.canny_spread;
  const double factors[2] = {2 / (1 + s), 2 * s / (1 + s)};
  std::vector<Candidate> out;
  const cv::Mat kernel = o.close_px > 0 ? cv::getStructuringElement(
                                              cv::MORPH_ELLIPSE, cv::Size(o.close_px, o.close_px))
                                        : cv::Mat();
  const cv::Point offset = window.tl();
  for (double sigma : {o.blur_sigma_px, o.blur_sigma_px * o.second_blur}) {
    cv::Mat blurred = grey;  // In place (see above).
    if (sigma > 0) cv::GaussianBlur(grey, blurred, cv::Size(0, 0), sigma);
    for (double f : factors) {
      cv::Mat edges;
      cv::Canny(blurred, edges, o.canny_low * f, o.canny_high * f);
      if (!kernel.empty()) cv::morphologyEx(edges, edges, cv::MORPH_CLOSE, kernel);
      std::vector<std::vector<cv::Point>> contours;
      cv::findContours(edges, contours, cv::RETR_LIST, cv::CHAIN_APPROX_SIMPLE, offset);
      for (const auto& contour : contours) {
        if (contour.size() < 5) continue;
        std::optional<Candidate> c =
            CompactHull(contour, o.min_area_px, max_area, o.region_max_aspect);
        if (c) out.push_back(std::move(*c));
      }
    }
  }
  if (!o.circles) return out;
  cv::Mat smooth;
  cv::GaussianBlur(grey, smooth, cv::Size(0, 0), std::max(0.5, 1.25 * o.blur_sigma_px));
  std::vector<cv::Vec3f> circles;
  cv::HoughCircles(smooth, circles, cv::HOUGH_GRADIENT, 1, 12, 100, o.circle_votes,
                   int(o.circle_min_radius_px), int(o.circle_max_radius_px));
  if (circles.empty()) return out;
  cv::Mat rim_edges;
  cv::Canny(smooth, rim_edges, o.canny_low, o.canny_high);
  cv::dilate(rim_edges, rim_edges, cv::Mat::ones(3, 3, CV_8U));
  for (const cv::Vec3f& circle : circles) {
    const cv::Point centre(int(std::lround(circle[0])), int(std::lround(circle[1])));
    const int radius = int(std::lround(circle[2]));
    std::vector<cv::Point> rim;
    cv::ellipse2Poly(centre, {radius, radius}, 0, 0, 360, 5, rim);
    int inside = 0, on_edge = 0;
    for (const cv::Point& p : rim) {
      if (p.x < 0 || p.y < 0 || p.x >= rim_edges.cols || p.y >= rim_edges.rows) continue;
      ++inside;
      on_edge += rim_edges.at<uchar>(p) ? 1 : 0;
    }
    if (inside < 10 || on_edge < o.circle_support * inside) continue;
    const double area = M_PI * radius * radius;
    if (area < o.min_area_px || area > max_area) continue;
    Candidate c;
    cv::ellipse2Poly(centre + offset, {radius, radius}, 0, 0, 360, 10, c.contour);
    c.centroid = cv::Point2d(circle[0], circle[1]) + cv::Point2d(offset);
    c.area = area;
    out.push_back(std::move(c));
  }
  return out;
}

// multiscale: true when `outer` holds two or more distinct button-sized regions (4-50 % of its
// area) away from its centre that do not hold the tap: a plate or a group of buttons. Glyphs
// and slots on a button are smaller or near its centre; regions that overlap (centres less
// than 0.9 of their summed radii apart) count once: the halves of one large digit on a small
// button are not two buttons, a plate's buttons do not overlap.
bool HoldsOtherButtons(const Candidate& outer, const std::vector<Candidate>& all, cv::Point2d tap) {
  const double off_centre = 0.4 * std::sqrt(outer.area / M_PI);
  std::vector<const Candidate*> held;
  for (const Candidate& c : all) {
    if (&c == &outer || c.area < 0.04 * outer.area || c.area > 0.5 * outer.area) continue;
    if (cv::norm(c.centroid - outer.centroid) < off_centre) continue;
    if (cv::pointPolygonTest(c.contour, cv::Point2f(tap), false) >= 0) continue;
    if (cv::pointPolygonTest(outer.contour, cv::Point2f(c.centroid), false) <= 0) continue;
    const double r = std::sqrt(c.area / M_PI);
    bool seen = false;
    for (const Candidate* h : held) {
      seen = seen || cv::norm(c.centroid - h->centroid) < 0.9 * (r + std::sqrt(h->area / M_PI));
    }
    if (seen) continue;
    held.push_back(&c);
    if (held.size() >= 2) return true;
  }
  return false;
}

// multiscale: the region that contains the tap with its centroid nearest the tap relative to
// its radius, at most max_offset radii away.
const Candidate* ChooseContaining(const std::vector<Candidate>& candidates, cv::Point2d tap,
                                  double max_offset, double bias) {
  const Candidate* best = nullptr;
  double best_score = 0;
  for (const Candidate& c : candidates) {
    const double radius = std::sqrt(c.area / M_PI);
    const double offset = std::hypot(c.centroid.x - tap.x, c.centroid.y - tap.y);
    if (offset > max_offset * radius) continue;
    const double score = (offset + bias) / radius;
    if (best && score >= best_score) continue;
    if (cv::pointPolygonTest(c.contour, cv::Point2f(tap), false) < 0) continue;
    if (HoldsOtherButtons(c, candidates, tap) || HoldsRegionsLikeTheTapped(c, candidates, tap)) {
      continue;
    }
    best = &c;
    best_score = score;
  }
  return best;
}

// multiscale fallback: closed outlines of the strongest radial edges around the tap, found on
// `grey` (the full-resolution frame: small buttons keep their shape) and scaled by `scale` to
// the working image, as candidates: most rays on an edge first and, among equals, the smaller.
std::vector<Candidate> RadialCandidates(const cv::Mat& grey, double scale, cv::Point2d tap,
                                        const ButtonDetectorOptions& o, double image_area) {
  RadialOutlineOptions r;
  r.min_radius_px = 3;
  r.max_radius_px = std::min(o.circle_max_radius_px, o.search_radius_px) / scale;
  r.min_edge = o.radial_min_edge;
  r.min_contrast = o.radial_min_contrast;
  r.min_support = o.min_coverage;
  r.blur_sigma_px = o.blur_sigma_px;
  std::vector<RadialOutline> outlines = RadialOutlines(grey, tap, r);
  std::stable_sort(outlines.begin(), outlines.end(),
                   [](const RadialOutline& a, const RadialOutline& b) {
                     return a.support > b.support;  // Bands come smallest first.
                   });
  std::vector<Candidate> out;
  for (RadialOutline& outline : outlines) {
    for (cv::Point& p : outline.points) {
      p = cv::Point(int(std::lround(p.x * scale)), int(std::lround(p.y * scale)));
    }
    std::optional<Candidate> c = CompactHull(outline.points, o.min_area_px,
                                             o.max_area_fraction * image_area, o.region_max_aspect);
    if (c) out.push_back(std::move(*c));
  }
  return out;
}

// The first of candidates[first...] (radial outlines, best first) whose centroid lies within
// max_offset radii of the tap and that holds no other buttons.
const Candidate* ChooseRadial(const std::vector<Candidate>& candidates, size_t first,
                              cv::Point2d tap, double max_offset) {
  for (size_t i = first; i < candidates.size(); ++i) {
    const Candidate& c = candidates[i];
    const double offset = std::hypot(c.centroid.x - tap.x, c.centroid.y - tap.y);
    if (offset > max_offset * std::sqrt(c.area / M_PI)) continue;
    if (HoldsOtherButtons(c, candidates, tap) || HoldsRegionsLikeTheTapped(c, candidates, tap)) {
      continue;
    }
    return &c;
  }
  return nullptr;
}

}  // namespace

StatusOr<ButtonModel> ButtonDetector::FindRegion(const cv::Mat& image, cv::Point2d tap) const {
  std::string error;
  if (!options_.IsValid(&error)) return InvalidArgument(error);
  if (image.empty()) return InvalidArgument("button detector: empty image");
  const cv::Mat grey = ToGrey(image);
  if (grey.empty())
    return InvalidArgument("button detector: image must be 8-bit grey, BGR or BGRA");
  if (!(tap.x >= 0 && tap.y >= 0 && tap.x < image.cols && tap.y < image.rows)) {
    char text[160];
    std::snprintf(text, sizeof(text),
                  "button detector: tap (%.1f, %.1f) lies outside the %dx%d image", tap.x, tap.y,
                  image.cols, image.rows);
    return InvalidArgument(text);
  }
  const double scale = double(options_.working_size_px) / std::max(image.cols, image.rows);
  // The detector's own working image (it is blurred in place): never the caller's pixels.
  cv::Mat work;
  if (scale != 1.0) {
    cv::resize(grey, work, cv::Size(), scale, scale, scale < 1 ? cv::INTER_AREA : cv::INTER_LINEAR);
  } else {
    work = grey.clone();
  }
  std::vector<Candidate> candidates;
  const Candidate* best = nullptr;
  if (options_.method == "seed") {
    candidates = Candidates(work, options_);
    best = Choose(candidates, tap * scale, options_.max_tap_distance_px);
    if (!best) {
      return NotFound("no button here: no compact outline within " +
                      std::to_string(int(options_.max_tap_distance_px)) + " px of the tap");
    }
  } else {
    const cv::Point2d t = tap * scale;
    const double half = options_.search_radius_px;
    const cv::Rect window =
        cv::Rect(cv::Point(int(std::floor(t.x - half)), int(std::floor(t.y - half))),
                 cv::Point(int(std::ceil(t.x + half)), int(std::ceil(t.y + half)))) &
        cv::Rect(0, 0, work.cols, work.rows);
    candidates = MultiScaleCandidates(work, window, options_);
    best = ChooseContaining(candidates, t, options_.max_centre_offset, options_.size_bias_px);
    if (!best && options_.radial) {
      const std::vector<Candidate> outlines =
          RadialCandidates(grey, scale, tap, options_, work.cols * work.rows);
      const size_t first = candidates.size();
      candidates.insert(candidates.end(), outlines.begin(), outlines.end());
      best = ChooseRadial(candidates, first, t, options_.max_centre_offset);
    }
    if (!best) {
      return NotFound("no button here: no outline around the tap with its centre within " +
                      std::to_string(options_.max_centre_offset).substr(0, 4) + " radii of it");
    }
  }
  ButtonModel model;
  model.tap = tap;
  model.image_size = image.size();
  model.center = best->centroid / scale;
  model.area_px = best->area / (scale * scale);
  for (const cv::Point& p : best->contour) {
    model.contour.emplace_back(int(std::lround(p.x / scale)), int(std::lround(p.y / scale)));
  }
  model.box = cv::boundingRect(model.contour);
  if (options_.min_button_probability > 0) {
    const RegionClassifier& classifier = RegionClassifier::BuiltIn();
    model.button_probability = classifier.ButtonProbability(RegionFeatures(grey, model.box));
    if (model.button_probability < options_.min_button_probability) {
      char text[160];
      std::snprintf(text, sizeof(text),
                    "no button here: the region at the tap looks like a printed label or sign "
                    "(button probability %.2f, below %.2f)",
                    model.button_probability, options_.min_button_probability);
      return NotFound(text);
    }
  }
  return model;
}

StatusOr<std::shared_ptr<const ButtonModel>> ButtonDetector::Detect(const cv::Mat& image,
                                                                    cv::Point2d tap) const {
  const cv::Mat grey = ToGrey(image);  // Once for both steps (shared when already grey).
  StatusOr<ButtonModel> region = FindRegion(grey.empty() ? image : grey, tap);
  if (!region.ok()) return region.status();
  auto model = std::make_shared<ButtonModel>(std::move(*region));
  const double keep =
      std::max(options_.sift_margin_px, options_.sift_margin_radius * model->RadiusPx());
  const int margin = int(std::ceil(keep)) + 16;  // + SIFT support.
  const cv::Rect crop =
      (model->box + cv::Size(2 * margin, 2 * margin) - cv::Point(margin, margin)) &
      cv::Rect(0, 0, image.cols, image.rows);
  // A large region is described at a coarser scale: SIFT's cost grows with the crop's area, and
  // the tracker matches by descriptor, whatever the scale the features were found at.
  const double radius = model->RadiusPx();
  const double shrink = options_.sift_max_radius_px > 0 && radius > options_.sift_max_radius_px
                            ? options_.sift_max_radius_px / radius
                            : 1.0;
  cv::Mat patch = grey(crop);
  if (shrink < 1) cv::resize(patch, patch, cv::Size(), shrink, shrink, cv::INTER_AREA);
  cv::Ptr<cv::SIFT> sift = cv::SIFT::create(0, 3, options_.sift_contrast);
  std::vector<cv::KeyPoint> keypoints;
  cv::Mat descriptors;
  sift->detectAndCompute(patch, cv::noArray(), keypoints, descriptors);
  for (size_t i = 0; i < keypoints.size(); ++i) {
    cv::KeyPoint k = keypoints[i];
    if (shrink < 1) {  // Back to image pixels (pixel centres, not corners, scale).
      k.pt = (k.pt + cv::Point2f(0.5f, 0.5f)) * float(1 / shrink) - cv::Point2f(0.5f, 0.5f);
      k.size = float(k.size / shrink);
    }
    k.pt += cv::Point2f(crop.tl());
    if (cv::pointPolygonTest(model->contour, k.pt, true) < -keep) continue;
    model->keypoints.push_back(k);
    model->descriptors.push_back(descriptors.row(int(i)));
  }
  if (int(model->keypoints.size()) < options_.min_keypoints) {
    return NotFound("no button here: the region at the tap has " +
                    std::to_string(model->keypoints.size()) + " features (needs " +
                    std::to_string(options_.min_keypoints) + ")");
  }
  return std::shared_ptr<const ButtonModel>(std::move(model));
}

}  // namespace sightline
