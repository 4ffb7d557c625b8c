#include "core/pipeline/floor_calibration.h"

#include <optional>

#include "core/io/dataset.h"
#include "core/mapping/floor_plane.h"

namespace sightline {

namespace {

// The depth camera of an RGB-D source.
StatusOr<PinholeCamera> SourceCamera(const SourceInfo& info) {
  if (info.rgbd) return info.rgbd->color;
  if (info.camera) return *info.camera;
  return FailedPrecondition(info.path + ": the RGB-D source has no camera intrinsics");
}

}  // namespace

StatusOr<FloorFitResult> CalibrateFloorFromDataset(const std::string& path, int frames,
                                                   const FloorPlaneOptions& options,
                                                   int* used_frames) {
  StatusOr<std::unique_ptr<Source>> opened = OpenDataset(path);
  if (!opened.ok()) return opened.status();
  Source& source = **opened;
  std::optional<PinholeCamera> camera;
  if (source.info().kind == SourceKind::kRgbd) {
    StatusOr<PinholeCamera> c = SourceCamera(source.info());
    if (!c.ok()) return c.status();
    camera = *c;
  } else if (source.info().kind != SourceKind::kCloud) {
    return InvalidArgument(path + " is a " + SourceKindName(source.info().kind) +
                           " dataset; the floor needs depth (RGB-D) or point clouds");
  }
  FloorCalibrator calibrator(options, frames);
  while (!calibrator.Full()) {
    Status grabbed = source.Grab();
    if (grabbed.code() == StatusCode::kOutOfRange) break;
    if (!grabbed.ok()) return grabbed;
    StatusOr<Frame> frame = source.Retrieve();
    if (!frame.ok()) return frame.status();
    if (const auto* rgbd = std::get_if<RgbdFrame>(&*frame)) {
      calibrator.AddDepth(rgbd->depth_m, *camera);
    } else if (const auto* cloud = std::get_if<CloudFrame>(&*frame)) {
      calibrator.AddCloud(cloud->cloud ? cloud->cloud->points : std::vector<Eigen::Vector3f>());
    }
  }
  if (used_frames != nullptr) *used_frames = calibrator.frames();
  if (calibrator.frames() == 0) return OutOfRange(path + " holds no frames");
  return calibrator.Fit();
}

}  // namespace sightline
