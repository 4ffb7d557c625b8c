// Renders a simulated scene from a pinhole camera: exact per-pixel depth (z along the optical
// axis, as a Kinect reports it), the object seen at each pixel, the viewing incidence and a
// lit, procedurally textured colour or grey image. Noise-free; sensor models add noise.
#pragma once

#include <Eigen/Geometry>
#include <opencv2/core.hpp>
#include <vector>

#include "core/common/camera.h"
#include "core/common/status.h"
#include "core/sim/scene.h"
#include "core/sim/visibility.h"

namespace sightline::sim {

// Which image to shade.
enum class ImageKind { kNone, kColor, kGrey };

// One rendered view. Buffers are reused when the next view has the same size.
struct RenderedView {
  cv::Mat depth_m;        // CV_32FC1: z in metres along the optical axis; NaN where nothing is hit.
  cv::Mat object;         // CV_32SC1: Scene::objects() index seen at the pixel, -1 = nothing.
  cv::Mat incidence_cos;  // CV_32FC1: |cos| of the angle between the ray and the surface normal.
  cv::Mat image;          // CV_8UC3 BGR (kColor), CV_8UC1 (kGrey), empty (kNone).
};

// Renders views of scenes. Keeps scratch buffers, so one Renderer per thread; cheap to create.
//
//   Renderer renderer;
//   RenderedView view;
//   SIGHTLINE_RETURN_IF_ERROR(renderer.Render(scene, scene.DynamicPrimitives(t), camera,
//                                             world_from_camera, ImageKind::kColor, &view));
class Renderer {
 public:
  // Nearest depth a surface is rendered at, metres (closer surfaces are clipped).
  static constexpr double kNearM = 0.02;

  // Renders `scene` plus `dynamic` primitives seen by `camera` (distortion-free pinhole, pixel
  // centres at integer coordinates) at pose `world_from_camera` (optical frame: z forward,
  // x right, y down). InvalidArgument for a camera that fails Validate() or has distortion.
  Status Render(const Scene& scene, const std::vector<Primitive>& dynamic,
                const PinholeCamera& camera, const Eigen::Isometry3d& world_from_camera,
                ImageKind kind, RenderedView* out);

 private:
  // Per-view constants of an item's shading.
  struct ItemShading {
    const Material* material = nullptr;
    const TextureImage* image = nullptr;
    bool planar = false;
    float light = 1;  // Planes: ambient + diffuse (constant over the plane).
    double inverse_d = 0;
  };

  RayTable rays_;
  PreparedView view_;
  std::vector<ItemShading> shading_;
  std::vector<float> inverse_depth_;
  std::vector<int32_t> item_index_;
  PinholeCamera rays_camera_;
};

}  // namespace sightline::sim
