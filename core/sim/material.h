// Surface appearance for the simulator: a procedural texture evaluated in the surface's own
// (s, t) coordinates in metres, so a texture point is a fixed 3D point that real feature
// detectors (Shi-Tomasi, SIFT, KLT) can track across views.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <opencv2/core.hpp>

namespace sightline::sim {

// The procedural patterns. All are deterministic functions of (s, t, seed).
enum class TextureKind {
  kPlain,    // Uniform colour (analytic tests).
  kSpeckle,  // Random rectangles of `accent` on `color` at scale_m, fine speckle, soft noise.
  kTiles,    // Square tiles of scale_m with grout lines in `accent`, per-tile shade, blotches.
  kChecker,  // Checkerboard of scale_m squares, `color` and `accent`.
  kBrushed,  // Brushed metal: fine stripes along s, low-contrast speckle.
  kImage,    // A baked image (posters, button labels), see image_size_m.
};

// "plain", "speckle", "tiles", "checker", "brushed", "image".
const char* TextureKindName(TextureKind kind);

// How a surface looks. Colours are linear RGB in [0, 1].
struct Material {
  TextureKind texture = TextureKind::kSpeckle;
  Eigen::Vector3f color{0.7f, 0.7f, 0.7f};   // Base colour.
  Eigen::Vector3f accent{0.3f, 0.3f, 0.3f};  // Second colour: blobs, grout, checker squares.
  float scale_m = 0.1f;                      // Pattern size: blob cell, tile or square, metres.
  uint32_t seed = 0;                         // Per-surface seed: equal materials still differ.
  float density = 0.6f;                      // kSpeckle: fraction of cells holding a blob.
  int image = -1;                            // kImage: index into Scene::images().
  // kImage: the image spans image_size_m with its bottom-left corner at image_offset_m in
  // (s, t); s runs along the image's columns, t up its rows (so a surface whose s points right
  // and t up, seen from its front side, shows the image upright and unmirrored).
  Eigen::Vector2f image_size_m{1.0f, 1.0f};
  Eigen::Vector2f image_offset_m{0.0f, 0.0f};
};

// A baked texture image (poster, button label), CV_8UC3 BGR.
struct TextureImage {
  cv::Mat bgr;
};

// The albedo (RGB in [0, 1]) of `material` at surface coordinates (s, t) in metres.
// `pixels_per_m` is how many image pixels one metre of the surface spans there (1 / the
// pixel's footprint): pattern details smaller than about two pixels fade to their mean, a cheap
// anti-aliasing that keeps distant surfaces from flickering. `image` must be the material's
// image for kImage, else may be null.
Eigen::Vector3f EvaluateAlbedo(const Material& material, const TextureImage* image, float s,
                               float t, float pixels_per_m);

}  // namespace sightline::sim
