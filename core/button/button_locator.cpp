#include "core/button/button_locator.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>

#include "core/button/option_check.h"
#include "core/button/plane_fit.h"

namespace sightline {

using button_internal::Invalid;

bool ButtonLocatorOptions::IsValid(std::string* error) const {
  if (!(button_radii >= 0)) return Invalid(error, "button.locate.button_radii must be >= 0");
  if (!(radius_px > 0)) return Invalid(error, "button.locate.radius_px must be > 0");
  if (min_points < 3) return Invalid(error, "button.locate.min_points must be >= 3");
  if (min_face_points < 1) return Invalid(error, "button.locate.min_face_points must be >= 1");
  if (!(panel_radii >= 0 && panel_radii <= 100))
    return Invalid(error, "button.locate.panel_radii must lie in [0, 100]");
  if (!(max_face_offset_m > 0))
    return Invalid(error, "button.locate.max_face_offset_m must be > 0");
  if (!(face_clip_sigmas >= 0 && face_clip_sigmas <= 100))
    return Invalid(error, "button.locate.face_clip_sigmas must lie in [0, 100]");
  if (good_points < min_points)
    return Invalid(error, "button.locate.good_points must be >= min_points");
  if (ransac_iterations < 1) return Invalid(error, "button.locate.ransac_iterations must be >= 1");
  if (!(ransac_threshold_m > 0))
    return Invalid(error, "button.locate.ransac_threshold_m must be > 0");
  if (!(max_plane_rms_m > 0)) return Invalid(error, "button.locate.max_plane_rms_m must be > 0");
  if (!(min_inlier_fraction > 0 && min_inlier_fraction <= 1)) {
    return Invalid(error, "button.locate.min_inlier_fraction must lie in (0, 1]");
  }
  if (!(min_incidence_cos > 0 && min_incidence_cos < 1)) {
    return Invalid(error, "button.locate.min_incidence_cos must lie in (0, 1)");
  }
  return true;
}

OptionTable<ButtonLocatorOptions> ButtonLocatorOptions::Describe() {
  using O = ButtonLocatorOptions;
  return OptionTable<O>("button.locate")
      .Double("button_radii", &O::button_radii, "radii", 0, 10, 0.05,
              "Map points within this many tracked button radii (the button's face) are used "
              "first; 0 = always use radius_px.")
      .Double("radius_px", &O::radius_px, "px", 1, 2000, 1,
              "Map points projecting within this distance of the button centre are used.")
      .Double("panel_radii", &O::panel_radii, "radii", 0, 100, 0.5,
              "The position's panel plane is fitted robustly to the map points within this many "
              "tracked button radii and moved onto the face by its points' median offset; 0 = "
              "the plane within radius_px (or the face's own).")
      .Int("min_points", &O::min_points, "", 3, 1000, 1, "Fewer points: no 3D position.")
      .Int("min_face_points", &O::min_face_points, "", 1, 1000, 1,
           "Points on the button's face that move the panel plane onto the face.")
      .Double("max_face_offset_m", &O::max_face_offset_m, "m", 0.001, 0.2, 0.001,
              "Larger median offset of the face points from the panel plane is not applied.")
      .Double("face_clip_sigmas", &O::face_clip_sigmas, "sigmas", 0, 100, 0.1,
              "The face's offset from the panel plane is the median of its points within this "
              "many robust sigmas of that median, until the set settles (points triangulated "
              "with little parallax leave a one-sided tail); 0 = the median of all.")
      .Int("good_points", &O::good_points, "", 3, 1000, 1,
           "Fewer points than this: the plane is not sound (no target is sent).")
      .Int("ransac_iterations", &O::ransac_iterations, "", 1, 100000, 10,
           "Plane RANSAC hypotheses.")
      .Double("ransac_threshold_m", &O::ransac_threshold_m, "m", 1e-5, 1, 0.0005,
              "Plane inlier distance.")
      .Double("max_plane_rms_m", &O::max_plane_rms_m, "m", 1e-5, 1, 0.0005,
              "Inlier RMS above this: the plane is not sound.")
      .Double("min_inlier_fraction", &O::min_inlier_fraction, "", 0.01, 1, 0.05,
              "Fewer inliers than this fraction of the points: the plane is not sound.")
      .Double("min_incidence_cos", &O::min_incidence_cos, "", 0.01, 0.99, 0.01,
              "Viewing ray closer to parallel with the plane than this |cos|: no position.");
}

Eigen::Isometry3d BaseFromCamera(const Eigen::Isometry3d& base_from_end_effector,
                                 const Eigen::Isometry3d& end_effector_from_camera) {
  return base_from_end_effector * end_effector_from_camera;
}

namespace {

struct Plane {
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();  // Unit.
  double offset = 0;                                  // normal . x + offset = 0.
  double Distance(const Eigen::Vector3d& x) const { return std::abs(normal.dot(x) + offset); }
};

// Least-squares plane: centroid and the smallest principal direction.
Plane FitPlane(const std::vector<Eigen::Vector3d>& points) {
  const LeastSquaresPlane fit = FitLeastSquaresPlane(points);
  Plane plane;
  plane.normal = fit.normal;
  plane.offset = fit.offset();
  return plane;
}

std::vector<int> Inliers(const Plane& plane, const std::vector<Eigen::Vector3d>& points, double t) {
  std::vector<int> in;
  for (int i = 0; i < int(points.size()); ++i) {
    if (plane.Distance(points[i]) <= t) in.push_back(i);
  }
  return in;
}

// RANSAC over 3-point planes; returns the largest inlier set (all points if none better).
// Hypotheses the viewing ray `ray` meets at a grazing angle (|cos| < min_incidence_cos) are not
// the panel the button is seen on: map points from a forward approach spread along the rays
// more than across, and such planes would otherwise win.
std::vector<int> RansacPlane(const std::vector<Eigen::Vector3d>& points, const Eigen::Vector3d& ray,
                             const ButtonLocatorOptions& o) {
  std::vector<int> best;
  std::mt19937_64 rng(o.seed);
  std::uniform_int_distribution<int> pick(0, int(points.size()) - 1);
  for (int it = 0; it < o.ransac_iterations; ++it) {
    const int a = pick(rng), b = pick(rng), c = pick(rng);
    if (a == b || b == c || a == c) continue;
    const Eigen::Vector3d n = (points[b] - points[a]).cross(points[c] - points[a]);
    if (n.norm() < 1e-12) continue;
    Plane plane;
    plane.normal = n.normalized();
    if (std::abs(plane.normal.dot(ray)) < o.min_incidence_cos) continue;
    plane.offset = -plane.normal.dot(points[a]);
    std::vector<int> in = Inliers(plane, points, o.ransac_threshold_m);
    if (in.size() > best.size()) best = std::move(in);
  }
  if (best.size() < 3) {
    best.resize(points.size());
    for (int i = 0; i < int(points.size()); ++i) best[i] = i;
  }
  return best;
}

// The median of `values` (reordered); 0 when empty.
double Median(std::vector<double>* values) {
  if (values->empty()) return 0;
  const auto mid = values->begin() + values->size() / 2;
  std::nth_element(values->begin(), mid, values->end());
  return *mid;
}

// The median of the `values` within `clip` robust sigmas (1.4826 x their median absolute
// deviation) of it, repeated until the kept set settles; `clip` 0 = the plain
// median. Monocular map points seen with little parallax scatter far to one side of a surface,
// which drags the plain median of a few dozen points by millimetres.
double ClippedMedian(const std::vector<double>& values, double clip) {
  std::vector<double> all = values;
  double centre = Median(&all);
  // The kept set follows from the centre: the same centre again means it has settled.
  for (int iteration = 0; clip > 0 && iteration < 20; ++iteration) {
    std::vector<double> deviation;
    deviation.reserve(values.size());
    for (double v : values) deviation.push_back(std::abs(v - centre));
    const double bound = clip * 1.4826 * Median(&deviation);
    std::vector<double> kept;
    kept.reserve(values.size());
    for (double v : values) {
      if (std::abs(v - centre) <= bound) kept.push_back(v);
    }
    if (kept.size() < 3) break;
    const double next = Median(&kept);
    if (next == centre) break;
    centre = next;
  }
  return centre;
}

// The panel plane over `points`: RANSAC's inliers, then least squares on the points within 2.5
// robust sigmas (1.4826 x the median absolute distance) until the set settles. A monocular map
// near the button is noisy by a centimetre (the button lies where the approach gives no
// parallax), so many points fitted loosely place the plane better than a tight slab of a few.
// False when fewer than `min_points` points are left.
bool RobustPanelPlane(const std::vector<Eigen::Vector3d>& points, const Eigen::Vector3d& ray,
                      const ButtonLocatorOptions& o, int min_points, Plane* plane, double* sigma,
                      int* used) {
  if (int(points.size()) < min_points) return false;
  std::vector<Eigen::Vector3d> kept;
  for (int i : RansacPlane(points, ray, o)) kept.push_back(points[i]);
  Plane fit = FitPlane(kept);
  double robust_sigma = 0;
  for (int iteration = 0; iteration < 10; ++iteration) {
    std::vector<double> distance;
    distance.reserve(points.size());
    for (const Eigen::Vector3d& x : points) distance.push_back(fit.Distance(x));
    std::vector<double> sorted = distance;
    robust_sigma = std::max(1e-6, 1.4826 * Median(&sorted));
    std::vector<Eigen::Vector3d> next;
    for (size_t i = 0; i < points.size(); ++i) {
      if (distance[i] <= 2.5 * robust_sigma) next.push_back(points[i]);
    }
    if (int(next.size()) < min_points) return false;
    const bool settled = next.size() == kept.size();
    kept = std::move(next);
    fit = FitPlane(kept);
    if (settled) break;
  }
  if (fit.normal.dot(ray) > 0) {  // Toward the camera: the face's offsets are then positive.
    fit.normal = -fit.normal;
    fit.offset = -fit.offset;
  }
  *plane = fit;
  *sigma = robust_sigma;
  *used = int(kept.size());
  return true;
}

}  // namespace

StatusOr<ButtonLocation> ButtonLocator::Locate(const LocatorInput& input) const {
  std::string error;
  if (!options_.IsValid(&error)) return InvalidArgument(error);
  SIGHTLINE_RETURN_IF_ERROR(input.camera.Validate());
  if (!input.points_in_world) return InvalidArgument("button locator: no map points given");
  if (!input.button_px.allFinite() || !input.camera_from_world.matrix().allFinite()) {
    return InvalidArgument("button locator: button pixel or camera pose not finite");
  }
  std::vector<Eigen::Vector3d> in_camera;
  std::vector<double> pixel_distance;
  for (const Eigen::Vector3d& x_in_world : *input.points_in_world) {
    const Eigen::Vector3d x = input.camera_from_world * x_in_world;
    if (!(x.z() > 1e-6) || !x.allFinite()) continue;
    in_camera.push_back(x);
    pixel_distance.push_back((input.camera.Project(x) - input.button_px).norm());
  }
  auto within = [&](double radius) {
    std::vector<Eigen::Vector3d> near;
    for (size_t i = 0; i < in_camera.size(); ++i) {
      if (pixel_distance[i] <= radius) near.push_back(in_camera[i]);
    }
    return near;
  };
  ButtonLocation out;
  std::vector<Eigen::Vector3d> face;  // Points on the button's own face.
  if (options_.button_radii > 0 && input.button_radius_px > 0) {
    face = within(options_.button_radii * input.button_radius_px);
  }
  // Enough points on the face: its own plane. Else the panel's plane around the button,
  // moved onto the face by the face points it has (a button stands out of its plate).
  const bool face_alone = int(face.size()) >= options_.good_points;
  const std::vector<Eigen::Vector3d> near = face_alone ? face : within(options_.radius_px);
  out.points_near = int(near.size());
  if (out.points_near < options_.min_points) {
    return NotFound("button locator: " + std::to_string(out.points_near) +
                    " map points near the button (needs " + std::to_string(options_.min_points) +
                    ")");
  }
  const Eigen::Vector3d ray =
      input.camera.Unproject(input.button_px.x(), input.button_px.y(), 1.0).normalized();
  const std::vector<int> inlier_ids = RansacPlane(near, ray, options_);
  std::vector<Eigen::Vector3d> inliers;
  inliers.reserve(inlier_ids.size());
  for (int i : inlier_ids) inliers.push_back(near[i]);
  Plane plane = FitPlane(inliers);
  double sum2 = 0;
  for (const auto& x : inliers) sum2 += std::pow(plane.Distance(x), 2);
  out.inliers = int(inliers.size());
  out.plane_rms_m = std::sqrt(sum2 / out.inliers);
  // The position's plane: the panel over panel_radii tracked radii (each face point is as noisy
  // as the rest: their median moves it onto the face, they make no plane of their own); else the
  // fit above. That fit still judges whether the panel around the button is sound.
  double offset_sigma = out.plane_rms_m / std::sqrt(double(out.inliers));
  Plane panel;
  double panel_sigma = 0;
  int panel_used = 0;
  const bool wide =
      options_.panel_radii > 0 && input.button_radius_px > 0 &&
      RobustPanelPlane(within(options_.panel_radii * input.button_radius_px), ray, options_,
                       options_.good_points, &panel, &panel_sigma, &panel_used);
  if (wide) {
    plane = panel;
    offset_sigma = panel_sigma / std::sqrt(double(panel_used));
  }
  out.on_button = face_alone && !wide;
  double face_sigma = 0;
  if ((wide || !face_alone) && int(face.size()) >= options_.min_face_points) {
    std::vector<double> offset;
    offset.reserve(face.size());
    for (const auto& x : face) offset.push_back(plane.normal.dot(x) + plane.offset);
    const double shift = ClippedMedian(offset, options_.face_clip_sigmas);
    if (std::abs(shift) <= options_.max_face_offset_m) {
      plane.offset -= shift;
      out.on_button = true;
      const double n = double(offset.size());
      if (wide) {
        std::vector<double> spread;
        spread.reserve(offset.size());
        for (double d : offset) spread.push_back(std::abs(d - shift));
        // The median's sigma: 1.2533 sigma / sqrt(n) for normal errors.
        face_sigma = 1.2533 * 1.4826 * Median(&spread) / std::sqrt(n);
      } else {
        face_sigma = out.plane_rms_m / std::sqrt(n);
      }
    }
  }

  const double denom = plane.normal.dot(ray);
  out.incidence_cos = std::abs(denom);
  if (out.incidence_cos < options_.min_incidence_cos) {
    char text[160];
    std::snprintf(text, sizeof(text),
                  "button locator: viewing ray nearly parallel to the panel (|cos| = %.3f < %.3f)",
                  out.incidence_cos, options_.min_incidence_cos);
    return FailedPrecondition(text);
  }
  const double t = -plane.offset / denom;
  if (!(t > 0)) return FailedPrecondition("button locator: the panel plane lies behind the camera");
  out.button_in_camera = t * ray;
  // The normal pointing out of the panel faces the camera: n . ray < 0.
  out.normal_in_camera = denom < 0 ? plane.normal : -plane.normal;
  out.approach_in_camera = -out.normal_in_camera;
  // Depth error from the fit, spread along the ray by the incidence, plus the scale error.
  const double fit_sigma = std::hypot(offset_sigma, face_sigma) / out.incidence_cos;
  const double scale_sigma = input.scale_sigma_rel * out.button_in_camera.norm();
  out.uncertainty_m = std::hypot(fit_sigma, scale_sigma);
  out.plane_sound = out.inliers >= options_.good_points &&
                    out.inliers >= options_.min_inlier_fraction * out.points_near &&
                    out.plane_rms_m <= options_.max_plane_rms_m;
  return out;
}

}  // namespace sightline
