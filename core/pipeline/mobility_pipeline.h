// The "mobility" pipeline (seed 001): the mobility map of every frame of an RGB-D recording or
// of PCD clouds, headless or in the GUI.
//
// Writes per frame NNNNNN_cloud.pcd (or .ply: x y z rgb score segment; rgb = the score colour),
// NNNNNN_projection.png (scores on the colour image), NNNNNN_topview.png (the top-view grid),
// one segments.csv (frame, segment, is_ground, points, slope_deg, roughness, area_m2, height_m,
// score_rule, score_gpr), mobility_log.txt (per-frame status) and metrics.json with the timing
// of every stage (median, p95), counts.points_<stage> (median points entering each stage),
// accuracy.ground_height_m (median camera height above the found ground) and, on simulated
// terrain (regions.csv and ground truth beside the recording), accuracy.slope_error_deg_max
// (planar regions: floor, ramp, platform, step, box tops) and accuracy.flat_roughness (the
// ground's median roughness).
#pragma once

#include <memory>
#include <string>

#include "core/options/option_table.h"
#include "core/pipeline/mobility_result.h"
#include "core/pipeline/pipeline_registry.h"

namespace sightline {

// Run-level options of mobility. Keys "mobility.run.*".
struct MobilityRunOptions {
  int max_frames = 0;                // Frames to process; 0 = all.
  std::string floor_file;            // Floor calibration (sightline-cli floor): its normal is
                                     // the expected up direction; "" = the mount options.
  std::string cloud_format = "pcd";  // Scored cloud per frame: pcd, ply or none.
  bool write_images = true;          // Projection and top-view PNGs per frame.
  double gt_tolerance_s = 0.02;      // Ground-truth pose association [s].
  double min_match_fraction = 0.8;   // A segment counts for accuracy when this fraction of
                                     // its points lies in one true region.

  bool IsValid(std::string* error) const;
  static OptionTable<MobilityRunOptions> Describe();
};

// The mobility pipeline: the mapper on every frame (its expected up direction from
// mobility.run.floor_file when given), the run's files and figures. The one object
// `sightline-cli run mobility` and the GUI run. Frames are independent: a re-run is a run.
class MobilityPipeline : public Pipeline {
 public:
  MobilityPipeline();
  ~MobilityPipeline() override;

  Status Configure(const OptionSet& options) override;
  Status Open(const PipelineSource& source) override;
  int64_t FrameLimit() const override;
  StatusOr<std::shared_ptr<const PipelineResult>> Process(const Frame& frame) override;
  // Frames are independent: the frame again with the current options, the run's record kept.
  StatusOr<std::shared_ptr<const PipelineResult>> Reprocess(const Frame& frame) override;
  void Reset() override;
  StatusOr<RunResult> Finish(const std::string& out_dir) override;
  const StatisticTable& Statistics() const override { return MobilityStatistics(); }

  // The run's state (mobility_pipeline.cpp).
  struct State;

 private:
  std::unique_ptr<State> state_;
};

// The pipeline's registry entry.
PipelineInfo MobilityPipelineInfo();

}  // namespace sightline
