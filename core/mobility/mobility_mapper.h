// The mobility map of one RGB-D frame or point cloud, end to end (seed 001), with per-stage
// timing and point counts as in the seed's Table II.
#pragma once

#include <Eigen/Core>
#include <memory>
#include <opencv2/core.hpp>
#include <optional>

#include "core/common/camera.h"
#include "core/common/frame.h"
#include "core/common/status.h"
#include "core/mobility/mobility_options.h"
#include "core/mobility/mobility_score.h"
#include "core/mobility/mobility_types.h"

namespace sightline {

// One frame for the mapper.
struct MobilityInput {
  FrameStamp stamp;
  std::shared_ptr<const PointCloud> cloud;      // Camera frame (x right, y down, z forward).
  cv::Mat color;                                // BGR image for the projection; may be empty.
  std::optional<PinholeCamera> camera;          // Colour camera; else recovered from the cloud.
  std::optional<Eigen::Vector3d> up_in_camera;  // E.g. from a floor calibration; else the mount.
};

// An RGB-D frame as mapper input (the organized cloud at full resolution).
MobilityInput MobilityInputFromRgbd(const RgbdFrame& frame, const PinholeCamera& camera);
// A point cloud as mapper input (colours of an organized cloud become the image).
MobilityInput MobilityInputFromCloud(const CloudFrame& frame);

// Runs the stages: downsample, range cut, denoise, normals, RGB-N coding, ground, region
// growing, surface properties, mobility scores, maps. Stateless between frames; construct once
// (the Gaussian process is trained here), call Process per frame, from one thread at a time.
//
//   MobilityMapper mapper(options);
//   std::shared_ptr<const MobilityResult> r = mapper.Process(MobilityInputFromCloud(frame));
//   if (!r->status.ok()) report(r->status);   // partial results (e.g. no ground) remain
class MobilityMapper {
 public:
  explicit MobilityMapper(MobilityOptions options = {});

  // Replaces the options (keeps the trained Gaussian process). InvalidArgument when invalid.
  Status Configure(const MobilityOptions& options);
  const MobilityOptions& options() const { return options_; }
  const GprScore& gpr() const { return gpr_; }

  // Never null. result->status says why a frame has no map: empty cloud, every point beyond
  // the range cut, too few points, no ground plane (the segments are still measured against
  // the expected up direction, and scored 0).
  std::shared_ptr<const MobilityResult> Process(const MobilityInput& input) const;

 private:
  MobilityOptions options_;
  GprScore gpr_;
};

}  // namespace sightline
