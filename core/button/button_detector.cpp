#include "core/button/button_detector.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <opencv2/features2d.hpp>
#include <opencv2/imgproc.hpp>

#include "core/button/option_check.h"

namespace sightline {

using button_internal::Invalid;

double ButtonModel::RadiusPx() const { return std::sqrt(std::max(area_px, 0.0) / M_PI); }

bool ButtonDetectorOptions::IsValid(std::string* error) const {
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
  if (min_keypoints < 1) return Invalid(error, "button.detect.min_keypoints must be >= 1");
  if (!(sift_contrast > 0 && sift_contrast < 1)) {
    return Invalid(error, "button.detect.sift_contrast must lie in (0, 1)");
  }
  return true;
}

OptionTable<ButtonDetectorOptions> ButtonDetectorOptions::Describe() {
  using O = ButtonDetectorOptions;
  return OptionTable<O>("button.detect")
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
              "not the tapped button.")
      .Double("sift_margin_px", &O::sift_margin_px, "px", 0, 200, 1,
              "SIFT keypoints up to this far outside the region belong to the button model.")
      .Double("sift_margin_radius", &O::sift_margin_radius, "radii", 0, 20, 0.1,
              "The SIFT margin grows to this many region radii when that is larger.")
      .Int("min_keypoints", &O::min_keypoints, "", 1, 1000, 1,
           "Fewer SIFT keypoints on the region: the button cannot be tracked.")
      .Double("sift_contrast", &O::sift_contrast, "", 0.001, 0.5, 0.005,
              "SIFT contrast threshold; lower finds more keypoints on plain buttons.");
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

// Button-like regions of the edge map, in working-image pixels: the convex hull of every
// contour that is compact and surrounds its own centre.
std::vector<Candidate> Candidates(const cv::Mat& grey, const ButtonDetectorOptions& o) {
  cv::Mat blurred = grey;
  if (o.blur_sigma_px > 0) cv::GaussianBlur(grey, blurred, cv::Size(0, 0), o.blur_sigma_px);
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
    std::vector<cv::Point> hull;
    cv::convexHull(contour, hull);
    const cv::Moments m = cv::moments(hull);
    const double area = m.m00;
    if (area < o.min_area_px || area > max_area) continue;
    const cv::RotatedRect box = cv::minAreaRect(hull);
    const double lo = std::min(box.size.width, box.size.height);
    const double hi = std::max(box.size.width, box.size.height);
    if (lo <= 0 || hi / lo > o.max_aspect) continue;
    const cv::Point2d centroid(m.m10 / area, m.m01 / area);
    const double radius = std::sqrt(area / M_PI);
    if (AngularCoverage(contour, centroid, 0.5 * radius) < o.min_coverage) continue;
    Candidate c;
    c.centroid = centroid;
    c.area = area;
    c.contour = std::move(hull);
    out.push_back(std::move(c));
  }
  return out;
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
    if (IsGroup(c, candidates, on_tap)) continue;
    best = &c;
    best_score = score;
  }
  return best;
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
  cv::Mat work = grey;
  if (scale != 1.0) {
    cv::resize(grey, work, cv::Size(), scale, scale, scale < 1 ? cv::INTER_AREA : cv::INTER_LINEAR);
  }
  const std::vector<Candidate> candidates = Candidates(work, options_);
  const Candidate* best = Choose(candidates, tap * scale, options_.max_tap_distance_px);
  if (!best) {
    return NotFound("no button here: no compact outline within " +
                    std::to_string(int(options_.max_tap_distance_px)) + " px of the tap");
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
  return model;
}

StatusOr<std::shared_ptr<const ButtonModel>> ButtonDetector::Detect(const cv::Mat& image,
                                                                    cv::Point2d tap) const {
  StatusOr<ButtonModel> region = FindRegion(image, tap);
  if (!region.ok()) return region.status();
  auto model = std::make_shared<ButtonModel>(std::move(*region));
  const double keep =
      std::max(options_.sift_margin_px, options_.sift_margin_radius * model->RadiusPx());
  const int margin = int(std::ceil(keep)) + 16;  // + SIFT support.
  const cv::Rect crop =
      (model->box + cv::Size(2 * margin, 2 * margin) - cv::Point(margin, margin)) &
      cv::Rect(0, 0, image.cols, image.rows);
  const cv::Mat grey = ToGrey(image);
  cv::Ptr<cv::SIFT> sift = cv::SIFT::create(0, 3, options_.sift_contrast);
  std::vector<cv::KeyPoint> keypoints;
  cv::Mat descriptors;
  sift->detectAndCompute(grey(crop), cv::noArray(), keypoints, descriptors);
  for (size_t i = 0; i < keypoints.size(); ++i) {
    cv::KeyPoint k = keypoints[i];
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
