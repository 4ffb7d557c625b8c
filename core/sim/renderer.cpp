#include "core/sim/renderer.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace sightline::sim {
namespace {

// Surface point, unit normal (facing the camera) and texture coordinates of a hit.
struct Hit {
  Eigen::Vector3d normal;
  float s = 0, t = 0;
};

Hit Surface(const ViewItem& item, const Eigen::Vector3d& p) {
  Hit hit;
  switch (item.kind) {
    case ViewItem::kPlane:
    case ViewItem::kDisc:
      hit.normal = item.normal;
      hit.s = static_cast<float>(item.axis_s.dot(p) - item.s0);
      hit.t = static_cast<float>(item.axis_t.dot(p) - item.t0);
      break;
    case ViewItem::kCylinder: {
      const Eigen::Vector3d w = p - item.base;
      const double h = w.dot(item.axis);
      const Eigen::Vector3d radial = w - h * item.axis;
      hit.normal = radial.normalized();
      const double angle = std::atan2(radial.dot(item.ref_v), radial.dot(item.ref_u));
      hit.s = static_cast<float>(angle * item.radius);
      hit.t = static_cast<float>(h);
      break;
    }
    case ViewItem::kSphere: {
      const Eigen::Vector3d w = p - item.center;
      hit.normal = w / item.radius;
      const double lon = std::atan2(w.dot(item.ref_v), w.dot(item.ref_u));
      const double lat = std::asin(std::clamp(hit.normal.dot(item.axis), -1.0, 1.0));
      hit.s = static_cast<float>(lon * item.radius);
      hit.t = static_cast<float>(lat * item.radius);
      break;
    }
  }
  // Face the camera (two-sided planes seen from behind, insides of cylinders).
  if (hit.normal.dot(p) > 0) hit.normal = -hit.normal;
  return hit;
}

inline uint8_t ToByte(float v) {
  return static_cast<uint8_t>(std::clamp(v * 255.0f + 0.5f, 0.0f, 255.0f));
}

}  // namespace

Status Renderer::Render(const Scene& scene, const std::vector<Primitive>& dynamic,
                        const PinholeCamera& camera, const Eigen::Isometry3d& world_from_camera,
                        ImageKind kind, RenderedView* out) {
  SIGHTLINE_RETURN_IF_ERROR(camera.Validate().WithContext("simulated camera"));
  if (camera.HasDistortion()) {
    return InvalidArgument("simulated camera: lens distortion is not supported (rectified only)");
  }
  if (camera.width != rays_camera_.width || camera.height != rays_camera_.height ||
      camera.fx != rays_camera_.fx || camera.fy != rays_camera_.fy ||
      camera.cx != rays_camera_.cx || camera.cy != rays_camera_.cy) {
    MakeRayTable(camera, &rays_);
    rays_camera_ = camera;
  }
  const Eigen::Isometry3d camera_from_world = world_from_camera.inverse();
  PrepareView(scene, dynamic, camera_from_world, &view_);
  RasterizeVisibility(view_, camera, rays_, kNearM, &inverse_depth_, &item_index_);

  const int w = camera.width, h = camera.height;
  out->depth_m.create(h, w, CV_32FC1);
  out->object.create(h, w, CV_32SC1);
  out->incidence_cos.create(h, w, CV_32FC1);
  if (kind == ImageKind::kColor) {
    out->image.create(h, w, CV_8UC3);
  } else if (kind == ImageKind::kGrey) {
    out->image.create(h, w, CV_8UC1);
  } else {
    out->image.release();
  }
  const Eigen::Vector3d light = camera_from_world.linear() * scene.light_direction;
  const float ambient = scene.ambient;
  const float pixel_angle = static_cast<float>(1.0 / std::max(camera.fx, camera.fy));
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const Eigen::Vector3f& sky = scene.background;
  const std::vector<Material>& materials = scene.materials();
  const std::vector<TextureImage>& images = scene.images();
  if (!view_.items.empty()) {
    int max_material = 0;
    for (const ViewItem& item : view_.items) max_material = std::max(max_material, item.material);
    if (max_material >= static_cast<int>(materials.size())) {
      return InvalidArgument("scene '" + scene.name() + "': a primitive uses material " +
                             std::to_string(max_material) + " but the scene has " +
                             std::to_string(materials.size()));
    }
  }

  // Per item: the material, its image, and for planes the constant lighting.
  shading_.resize(view_.items.size());
  for (size_t i = 0; i < view_.items.size(); ++i) {
    const ViewItem& item = view_.items[i];
    ItemShading& s = shading_[i];
    s.material = &materials[item.material];
    s.image = s.material->image >= 0 && s.material->image < static_cast<int>(images.size())
                  ? &images[s.material->image]
                  : nullptr;
    s.planar = item.kind == ViewItem::kPlane || item.kind == ViewItem::kDisc;
    // The camera sees the side facing it: d < 0 means the normal already faces the camera.
    const Eigen::Vector3d facing = item.d < 0 ? item.normal : Eigen::Vector3d(-item.normal);
    s.light = ambient + (1.0f - ambient) * static_cast<float>(std::max(0.0, facing.dot(light)));
    s.inverse_d = 1.0 / item.d;
  }
  const float pixels_per_radian = static_cast<float>(1.0 / pixel_angle);

  for (int v = 0; v < h; ++v) {
    const size_t row_start = static_cast<size_t>(v) * w;
    float* depth = out->depth_m.ptr<float>(v);
    int32_t* object = out->object.ptr<int32_t>(v);
    float* incidence = out->incidence_cos.ptr<float>(v);
    uint8_t* pixel = kind == ImageKind::kNone ? nullptr : out->image.ptr<uint8_t>(v);
    const double ry = rays_.y[v];
    for (int u = 0; u < w; ++u) {
      const int32_t index = item_index_[row_start + u];
      Eigen::Vector3f rgb;
      if (index < 0) {
        depth[u] = nan;
        object[u] = -1;
        incidence[u] = 0;
        rgb = sky;
      } else {
        const ViewItem& item = view_.items[index];
        const ItemShading& shade = shading_[index];
        const double rx = rays_.x[u];
        float s, t, cos_incidence, light_factor, inverse_z;
        double z;
        if (shade.planar) {
          // Exact ray-plane intersection in double; texture coordinates are affine in z.
          const double nd = item.normal.x() * rx + item.normal.y() * ry + item.normal.z();
          z = item.d / nd;
          inverse_z = static_cast<float>(nd * shade.inverse_d);
          s = static_cast<float>(
              z * (item.axis_s.x() * rx + item.axis_s.y() * ry + item.axis_s.z()) - item.s0);
          t = static_cast<float>(
              z * (item.axis_t.x() * rx + item.axis_t.y() * ry + item.axis_t.z()) - item.t0);
          cos_incidence = static_cast<float>(std::abs(nd)) * rays_.inverse_length[row_start + u];
          light_factor = shade.light;
        } else {
          inverse_z = inverse_depth_[row_start + u];
          z = 1.0 / inverse_z;
          const Eigen::Vector3d dir(rx, ry, 1.0);
          const Hit hit = Surface(item, z * dir);
          s = hit.s, t = hit.t;
          cos_incidence = static_cast<float>(std::abs(hit.normal.dot(dir))) *
                          rays_.inverse_length[row_start + u];
          light_factor =
              ambient + (1.0f - ambient) * static_cast<float>(std::max(0.0, hit.normal.dot(light)));
        }
        depth[u] = static_cast<float>(z);
        object[u] = item.object;
        incidence[u] = cos_incidence;
        if (pixel == nullptr) continue;
        // Pixels per metre on the surface (the footprint grows with depth and obliquity).
        const float pixels_per_m = std::max(cos_incidence, 0.25f) * inverse_z * pixels_per_radian;
        rgb = EvaluateAlbedo(*shade.material, shade.image, s, t, pixels_per_m) * light_factor;
      }
      if (pixel == nullptr) continue;
      if (kind == ImageKind::kColor) {
        pixel[3 * u] = ToByte(rgb.z());
        pixel[3 * u + 1] = ToByte(rgb.y());
        pixel[3 * u + 2] = ToByte(rgb.x());
      } else {
        pixel[u] = ToByte(0.299f * rgb.x() + 0.587f * rgb.y() + 0.114f * rgb.z());
      }
    }
  }
  return Status::Ok();
}

}  // namespace sightline::sim
