#include "core/stereo/track_anchor.h"

#include <Eigen/Dense>
#include <array>
#include <cmath>
#include <unordered_map>

#include "core/stereo/option_check.h"

namespace sightline {

using stereo_internal::Invalid;

bool TrackAnchorOptions::IsValid(std::string* error) const {
  if (patch_px < 3 || patch_px > 31 || patch_px % 2 == 0) {
    return Invalid(error, "stereo.anchor.patch_px must be odd and lie in [3, 31]");
  }
  if (max_frames < 1 || max_frames > 100) {
    return Invalid(error, "stereo.anchor.max_frames must lie in [1, 100]");
  }
  if (!(max_scale_change > 0 && max_scale_change < 1)) {
    return Invalid(error, "stereo.anchor.max_scale_change must lie in (0, 1)");
  }
  if (!(max_correction_px > 0))
    return Invalid(error, "stereo.anchor.max_correction_px must be > 0");
  if (!(min_zncc >= -1 && min_zncc <= 1)) {
    return Invalid(error, "stereo.anchor.min_zncc must lie in [-1, 1]");
  }
  if (max_iterations < 1 || max_iterations > 100) {
    return Invalid(error, "stereo.anchor.max_iterations must lie in [1, 100]");
  }
  if (!(normal_radius_px >= 0 && normal_radius_px <= 500)) {
    return Invalid(error, "stereo.anchor.normal_radius_px must lie in [0, 500]");
  }
  if (normal_min_points < 3 || normal_min_points > 1000) {
    return Invalid(error, "stereo.anchor.normal_min_points must lie in [3, 1000]");
  }
  if (!(max_view_change_deg > 0 && max_view_change_deg <= 90)) {
    return Invalid(error, "stereo.anchor.max_view_change_deg must lie in (0, 90]");
  }
  return true;
}

OptionTable<TrackAnchorOptions> TrackAnchorOptions::Describe() {
  using O = TrackAnchorOptions;
  return OptionTable<O>("stereo.anchor")
      .Bool("enabled", &O::enabled,
            "Refine every tracked position against the track's anchor (where it was first seen), "
            "its patch warped by the motion since, so tracks do not drift frame by frame.")
      .Int("patch_px", &O::patch_px, "px", 3, 31, 2, "Side of the aligned patch (odd).")
      .Int("max_frames", &O::max_frames, "frames", 1, 100, 1,
           "An anchor is used for at most this many frames; then the track is anchored anew.")
      .Double("max_scale_change", &O::max_scale_change, "", 0.01, 0.99, 0.01,
              "A track whose patch would be scaled by more than this fraction since its anchor "
              "(the camera came close) is anchored anew.")
      .Double("max_correction_px", &O::max_correction_px, "px", 0.05, 20, 0.05,
              "An alignment that moves the tracked position further than this failed (the KLT "
              "position is kept and the track anchored anew).")
      .Double("min_zncc", &O::min_zncc, "", -1, 1, 0.05,
              "An aligned patch whose zero-mean normalised correlation with the warped anchor "
              "patch is lower failed (occlusion, reflection).")
      .Int("max_iterations", &O::max_iterations, "", 1, 100, 1,
           "Gauss-Newton iterations of the alignment.")
      .Double("max_view_change_deg", &O::max_view_change_deg, "deg", 0.1, 90, 0.5,
              "A track seen from a direction differing more than this from its anchor's is "
              "anchored anew: the further aside, the more a wrongly fitted or assumed surface "
              "(the road taken as facing the camera) misleads the warp; 3 suits subsampled "
              "driving.")
      .Double("normal_radius_px", &O::normal_radius_px, "px", 0, 500, 5,
              "A track's surface is fitted as a plane to the tracks within this radius at a "
              "similar depth, so the anchor's patch is warped as that plane; 0 = every patch is "
              "taken as facing the camera.")
      .Int("normal_min_points", &O::normal_min_points, "points", 3, 1000, 1,
           "Fewest tracks (the track included) a surface is fitted to.");
}

namespace {

// Bilinear sample of a CV_8UC1 image at (x, y); the caller keeps (x, y) inside [0, w-1) x [0, h-1).
inline float Sample(const cv::Mat& image, float x, float y) {
  const int x0 = static_cast<int>(x), y0 = static_cast<int>(y);
  const float a = x - static_cast<float>(x0), b = y - static_cast<float>(y0);
  const uchar* r0 = image.ptr<uchar>(y0) + x0;
  const uchar* r1 = r0 + image.step[0];
  return (1 - b) * ((1 - a) * r0[0] + a * r0[1]) + b * ((1 - a) * r1[0] + a * r1[1]);
}

// The side x side patch of `image` whose top-left sample is at (x, y), bilinear; one set of
// weights serves every sample (they share the sub-pixel offset). The patch must lie inside.
void SamplePatch(const cv::Mat& image, float x, float y, int side, float* out) {
  const int x0 = static_cast<int>(std::floor(x)), y0 = static_cast<int>(std::floor(y));
  const float a = x - static_cast<float>(x0), b = y - static_cast<float>(y0);
  const float w00 = (1 - a) * (1 - b), w01 = a * (1 - b), w10 = (1 - a) * b, w11 = a * b;
  for (int j = 0; j < side; ++j) {
    const uchar* r0 = image.ptr<uchar>(y0 + j) + x0;
    const uchar* r1 = r0 + image.step[0];
    for (int i = 0; i < side; ++i) {
      out[j * side + i] = w00 * r0[i] + w01 * r0[i + 1] + w10 * r1[i] + w11 * r1[i + 1];
    }
  }
}

inline bool Inside(const cv::Mat& image, float x, float y) {
  return x >= 0 && y >= 0 && x < static_cast<float>(image.cols - 1) &&
         y < static_cast<float>(image.rows - 1);
}

// The anchor patch's warp into the current image: the Jacobian at the anchor of "back-project
// at the anchor's depth, move, project". False when the anchor cannot be aligned from here
// (behind the camera, seen from too far aside, too much change of scale).
bool PatchWarp(const RectifiedStereoCamera& camera, const TrackAnchor& anchor,
               const Eigen::Isometry3d& current_from_anchor, const TrackAnchorOptions& options,
               Eigen::Matrix2d* warp) {
  const Eigen::Vector3d x_anchor =
      camera.Triangulate(anchor.left.x, anchor.left.y, anchor.disparity_px);
  const Eigen::Vector3d y = current_from_anchor * x_anchor;
  if (y.z() < 0.05) return false;
  // Seen from too far aside for the warp (a surface guessed or fitted wrongly shows it most).
  const Eigen::Vector3d centre = current_from_anchor.inverse().translation();
  if (x_anchor.normalized().dot((x_anchor - centre).normalized()) <
      std::cos(options.max_view_change_deg * M_PI / 180)) {
    return false;
  }
  // How the anchor's surface point moves with its pixel: on the fitted plane, or on a plane
  // facing the camera at the anchor's depth.
  const Eigen::Vector3d ray((anchor.left.x - camera.cx) / camera.f,
                            (anchor.left.y - camera.cy) / camera.f, 1.0);
  Eigen::Vector3d normal(0, 0, 1);
  if (anchor.normal.squaredNorm() > 0.5 &&
      std::abs(anchor.normal.cast<double>().dot(ray.normalized())) > 0.15) {
    normal = anchor.normal.cast<double>();  // Not seen too close to edge-on.
  }
  const double along = normal.dot(ray);
  Eigen::Matrix<double, 3, 2> surface;  // d(point) / d(u, v) at the anchor.
  surface.col(0) =
      (x_anchor.z() / camera.f) * (Eigen::Vector3d::UnitX() - ray * normal.x() / along);
  surface.col(1) =
      (x_anchor.z() / camera.f) * (Eigen::Vector3d::UnitY() - ray * normal.y() / along);
  Eigen::Matrix<double, 2, 3> projection;
  projection << 1, 0, -y.x() / y.z(), 0, 1, -y.y() / y.z();
  *warp = (camera.f / y.z()) * projection * current_from_anchor.linear() * surface;
  const double det = warp->determinant();
  return det > 0 && !(std::abs(std::sqrt(det) - 1) > options.max_scale_change);
}

// The anchor's patch (half-size h) resampled through `inverse` (current to anchor pixels) into
// the current image's pixel grid, with one pixel of border for the gradients: (2h + 3)^2 values
// into *templ. False when it leaves the anchor image.
// Index of offset (i, j) in a template of half-size h with a one-pixel border (side 2h + 3).
size_t TemplateIndex(int i, int j, int h) {
  const size_t side = 2 * static_cast<size_t>(h) + 3;
  return static_cast<size_t>(j + h + 1) * side + static_cast<size_t>(i + h + 1);
}

bool ResampleTemplate(const cv::Mat& anchor_image, const cv::Point2f& at,
                      const Eigen::Matrix2d& inverse, int h, std::vector<float>* templ) {
  const int side = 2 * h + 3;
  templ->assign(static_cast<size_t>(side) * static_cast<size_t>(side), 0.f);
  for (int j = -h - 1; j <= h + 1; ++j) {
    for (int i = -h - 1; i <= h + 1; ++i) {
      const float sx = at.x + static_cast<float>(inverse(0, 0) * i + inverse(0, 1) * j);
      const float sy = at.y + static_cast<float>(inverse(1, 0) * i + inverse(1, 1) * j);
      if (!Inside(anchor_image, sx, sy)) return false;
      (*templ)[TemplateIndex(i, j, h)] = Sample(anchor_image, sx, sy);
    }
  }
  return true;
}

// The template's inner values, the residual's Jacobian by (dx, dy, bias) at each, and the
// Gauss-Newton matrix they make.
Eigen::Matrix3d TemplateJacobian(const std::vector<float>& templ, int h,
                                 std::vector<std::array<float, 3>>* jac,
                                 std::vector<float>* values) {
  const int side = 2 * h + 3;
  const int n = (2 * h + 1) * (2 * h + 1);
  jac->resize(static_cast<size_t>(n));
  values->resize(static_cast<size_t>(n));
  Eigen::Matrix3d H = Eigen::Matrix3d::Zero();
  int k = 0;
  for (int j = -h; j <= h; ++j) {
    for (int i = -h; i <= h; ++i, ++k) {
      const size_t c = TemplateIndex(i, j, h);
      const float gx = 0.5f * (templ[c + 1] - templ[c - 1]);
      const float gy =
          0.5f * (templ[c + static_cast<size_t>(side)] - templ[c - static_cast<size_t>(side)]);
      (*jac)[static_cast<size_t>(k)] = {gx, gy, -1.f};
      (*values)[static_cast<size_t>(k)] = templ[c];
      const Eigen::Vector3d g(gx, gy, -1.0);
      H.noalias() += g * g.transpose();
    }
  }
  return H;
}

// Whether the patch of half-size h centred at (cx, cy) lies inside `image`.
bool PatchInside(const cv::Mat& image, float cx, float cy, int h) {
  return Inside(image, cx - static_cast<float>(h), cy - static_cast<float>(h)) &&
         Inside(image, cx + static_cast<float>(h), cy + static_cast<float>(h));
}

// Gauss-Newton on the translation (*cx, *cy) and a brightness offset; `patch` is scratch space.
// False when the patch leaves the current image.
bool AlignTranslation(const cv::Mat& current, int h, const std::vector<float>& values,
                      const std::vector<std::array<float, 3>>& jac, const Eigen::Matrix3d& H_inv,
                      int max_iterations, float* cx, float* cy, std::vector<float>* patch) {
  const int n = (2 * h + 1) * (2 * h + 1);
  float bias = 0;
  for (int iteration = 0; iteration < max_iterations; ++iteration) {
    if (!PatchInside(current, *cx, *cy, h)) return false;
    SamplePatch(current, *cx - static_cast<float>(h), *cy - static_cast<float>(h), 2 * h + 1,
                patch->data());
    float bx = 0, by = 0, bz = 0;
    for (int q = 0; q < n; ++q) {
      const float e = (*patch)[static_cast<size_t>(q)] - values[static_cast<size_t>(q)] - bias;
      const std::array<float, 3>& g = jac[static_cast<size_t>(q)];
      bx += g[0] * e;
      by += g[1] * e;
      bz += g[2] * e;
    }
    const Eigen::Vector3d b(bx, by, bz);
    const Eigen::Vector3d step = -H_inv * b;
    *cx += static_cast<float>(step.x());
    *cy += static_cast<float>(step.y());
    bias -= static_cast<float>(step.z());
    if (step.head<2>().squaredNorm() < 1e-4) break;
  }
  return true;
}

// Zero-mean normalised correlation of the template values with `patch` (n values each);
// false for a flat patch.
bool Correlation(const std::vector<float>& values, const std::vector<float>& patch, int n,
                 double* zncc) {
  double st = 0, sc = 0, stt = 0, scc = 0, stc = 0;
  for (int q = 0; q < n; ++q) {
    const double t = values[static_cast<size_t>(q)], c = patch[static_cast<size_t>(q)];
    st += t;
    sc += c;
    stt += t * t;
    scc += c * c;
    stc += t * c;
  }
  const double vt = stt - st * st / n, vc = scc - sc * sc / n;
  if (!(vt > 0 && vc > 0)) return false;
  *zncc = (stc - st * sc / n) / std::sqrt(vt * vc);
  return true;
}

}  // namespace

std::vector<Eigen::Vector3f> SurfaceNormals(const std::vector<Eigen::Vector3d>& points,
                                            const std::vector<cv::Point2f>& pixels,
                                            const std::vector<size_t>& which,
                                            const TrackAnchorOptions& options) {
  std::vector<Eigen::Vector3f> normals(which.size(), Eigen::Vector3f::Zero());
  const double radius = options.normal_radius_px;
  if (radius <= 0 || points.empty()) return normals;
  // Tracks by grid cell of the radius' size: neighbours lie in the 3 x 3 cells around.
  std::unordered_map<int64_t, std::vector<size_t>> cells;
  auto cell_of = [&](const cv::Point2f& p, int dx, int dy) {
    const int64_t cx = static_cast<int64_t>(std::floor(p.x / radius)) + dx;
    const int64_t cy = static_cast<int64_t>(std::floor(p.y / radius)) + dy;
    return cy * 1000003 + cx;
  };
  for (size_t i = 0; i < pixels.size(); ++i) cells[cell_of(pixels[i], 0, 0)].push_back(i);
  std::vector<Eigen::Vector3d> near;
  for (size_t w = 0; w < which.size(); ++w) {
    const size_t t = which[w];
    const Eigen::Vector3d& centre = points[t];
    near.clear();
    for (int dy = -1; dy <= 1; ++dy) {
      for (int dx = -1; dx <= 1; ++dx) {
        auto it = cells.find(cell_of(pixels[t], dx, dy));
        if (it == cells.end()) continue;
        for (size_t j : it->second) {
          const cv::Point2f d = pixels[j] - pixels[t];
          if (d.x * d.x + d.y * d.y > radius * radius) continue;
          // The same surface: a similar depth (not across an occluding edge).
          if (std::abs(points[j].z() - centre.z()) > 0.2 * centre.z()) continue;
          near.push_back(points[j]);
        }
      }
    }
    if (static_cast<int>(near.size()) < options.normal_min_points) continue;
    Eigen::Vector3d mean = Eigen::Vector3d::Zero();
    for (const Eigen::Vector3d& p : near) mean += p;
    mean /= static_cast<double>(near.size());
    Eigen::Matrix3d scatter = Eigen::Matrix3d::Zero();
    for (const Eigen::Vector3d& p : near) scatter += (p - mean) * (p - mean).transpose();
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(scatter);
    const Eigen::Vector3d& values = eigen.eigenvalues();  // Ascending.
    // A plane: thin across, spread along both of its directions.
    if (!(values(0) < 0.05 * values(1)) || !(values(1) > 0)) continue;
    normals[w] = eigen.eigenvectors().col(0).normalized().cast<float>();
  }
  return normals;
}

void TrackAnchors::AddFrame(int64_t frame, const cv::Mat& left,
                            const Eigen::Isometry3d& world_from_camera) {
  // A copy: a source may reuse its image buffers for the next frames.
  frames_.push_back({frame, left.clone(), world_from_camera});
  // Frame `frame + 1` is the next to be aligned; older anchors than max_frames before it are
  // renewed, so their images are not needed.
  while (!frames_.empty() && !Usable(frames_.front().frame, frame + 1)) frames_.pop_front();
}

const TrackAnchors::Frame* TrackAnchors::Find(int64_t frame) const {
  for (const Frame& f : frames_) {
    if (f.frame == frame) return &f;
  }
  return nullptr;
}

AnchorAlignment TrackAnchors::Align(const RectifiedStereoCamera& camera, const TrackAnchor& anchor,
                                    int64_t frame, const cv::Mat& current,
                                    const Eigen::Isometry3d& world_from_current,
                                    cv::Point2f* position) const {
  if (anchor.frame < 0 || anchor.frame >= frame - 1) return AnchorAlignment::kUnchanged;
  if (!Usable(anchor.frame, frame) || !(anchor.disparity_px > 0)) return AnchorAlignment::kRenew;
  const Frame* ref = Find(anchor.frame);
  if (!ref) return AnchorAlignment::kRenew;

  const Eigen::Isometry3d current_from_anchor =
      world_from_current.inverse() * ref->world_from_camera;
  Eigen::Matrix2d warp;
  if (!PatchWarp(camera, anchor, current_from_anchor, options_, &warp)) {
    return AnchorAlignment::kRenew;
  }
  const Eigen::Matrix2d inverse = warp.inverse();

  const int h = options_.patch_px / 2;
  thread_local std::vector<float> templ;
  if (!ResampleTemplate(ref->left, anchor.left, inverse, h, &templ)) {
    return AnchorAlignment::kRenew;
  }
  const int n = (2 * h + 1) * (2 * h + 1);
  thread_local std::vector<std::array<float, 3>> jac;  // d residual / (dx, dy, bias).
  thread_local std::vector<float> values, patch;
  const Eigen::Matrix3d H = TemplateJacobian(templ, h, &jac, &values);
  patch.resize(static_cast<size_t>(n));
  if (!(H.topLeftCorner<2, 2>().determinant() > 1e-6)) return AnchorAlignment::kRenew;
  const Eigen::Matrix3d H_inv = H.inverse();

  // Gauss-Newton on the translation and a brightness offset, from the KLT position.
  const cv::Point2f start = *position;
  float cx = start.x, cy = start.y;
  if (!AlignTranslation(current, h, values, jac, H_inv, options_.max_iterations, &cx, &cy,
                        &patch) ||
      std::hypot(cx - start.x, cy - start.y) > options_.max_correction_px ||
      !PatchInside(current, cx, cy, h)) {
    return AnchorAlignment::kRenew;
  }

  // Zero-mean normalised correlation of the aligned patches.
  SamplePatch(current, cx - static_cast<float>(h), cy - static_cast<float>(h), 2 * h + 1,
              patch.data());
  double zncc = 0;
  if (!Correlation(values, patch, n, &zncc) || zncc < options_.min_zncc) {
    return AnchorAlignment::kRenew;
  }
  *position = cv::Point2f(cx, cy);
  return AnchorAlignment::kAligned;
}

}  // namespace sightline
