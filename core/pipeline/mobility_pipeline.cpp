#include "core/pipeline/mobility_pipeline.h"

#include <cmath>
#include <filesystem>
#include <limits>
#include <optional>

#include "core/common/text_file.h"
#include "core/io/floor_file.h"
#include "core/mobility/mobility_map.h"
#include "core/mobility/mobility_mapper.h"
#include "core/mobility/score_plot.h"
#include "core/mobility/terrain_truth.h"
#include "core/pipeline/mobility_outputs.h"
#include "core/pipeline/mobility_run.h"

namespace sightline {

bool MobilityRunOptions::IsValid(std::string* error) const {
  auto fail = [error](const std::string& m) {
    if (error != nullptr) *error = "mobility.run." + m;
    return false;
  };
  if (max_frames < 0) return fail("max_frames must be >= 0");
  if (cloud_format != "pcd" && cloud_format != "ply" && cloud_format != "none") {
    return fail("cloud_format must be pcd, ply or none");
  }
  if (!(gt_tolerance_s >= 0)) return fail("gt_tolerance_s must be >= 0");
  if (!(min_match_fraction > 0 && min_match_fraction <= 1)) {
    return fail("min_match_fraction must lie in (0, 1]");
  }
  return true;
}

OptionTable<MobilityRunOptions> MobilityRunOptions::Describe() {
  using O = MobilityRunOptions;
  return OptionTable<O>("mobility.run")
      .Int("max_frames", &O::max_frames, "frames", 0, 1e9, 1, "Frames to process; 0 = all.")
      .String("floor_file", &O::floor_file,
              "Floor calibration (sightline-cli floor) giving the expected up direction; empty = "
              "mobility.mount_pitch_deg / mount_roll_deg.")
      .Choice("cloud_format", &O::cloud_format, {"pcd", "ply", "none"},
              "Scored cloud written per frame.")
      .Bool("write_images", &O::write_images, "Write the projection and top-view PNGs per frame.")
      .Double("gt_tolerance_s", &O::gt_tolerance_s, "s", 0, 1, 0.005,
              "A ground-truth pose belongs to a frame when this close in time.")
      .Double("min_match_fraction", &O::min_match_fraction, "", 0.01, 1, 0.01,
              "Accuracy: a segment is compared with the true region holding this fraction of "
              "its points.");
}

namespace {

// The recording folder holding regions.csv: the source's folder or its parent.
std::string FindRegionsFile(const std::string& source_path) {
  for (const std::string& folder :
       {source_path, std::filesystem::path(source_path).parent_path().string()}) {
    std::string path = JoinPath(folder, "regions.csv");
    if (FileExists(path)) return path;
  }
  return "";
}

void AddTerrainAccuracy(int64_t frame, const MobilityResult& r,
                        const Eigen::Isometry3d& world_from_camera,
                        const std::vector<TrueRegion>& regions, double min_fraction,
                        MobilityTerrainAccuracy* acc) {
  for (const SegmentMatch& m : MatchSegmentsToRegions(r, world_from_camera, regions)) {
    if (m.region < 0 || m.fraction < min_fraction) continue;
    const TrueRegion& region = regions[m.region];
    const SegmentProperties& s = r.segments[m.segment];
    if (region.kind == "floor" && s.is_ground) acc->flat_roughness.push_back(s.roughness);
    const bool planar = region.kind == "floor" || region.kind == "ramp" ||
                        region.kind == "platform" || region.kind == "step" || region.kind == "box";
    if (!planar || s.points < 200) continue;
    const double error = std::abs(s.slope_deg - region.slope_deg);
    if (error >= acc->slope_error_max) {
      acc->slope_error_max = error;
      acc->worst = "frame " + std::to_string(frame) + ", segment " + std::to_string(m.segment) +
                   " on the " + region.kind + " (true " + std::to_string(region.slope_deg) +
                   " deg, measured " + std::to_string(s.slope_deg) + " deg)";
    }
    ++acc->slopes;
  }
}

// A colour per segment id (the ground grey-blue, unsegmented dark).
Eigen::Matrix<uint8_t, 3, 1> SegmentColor(const MobilityResult& r, int segment) {
  if (segment < 0) return {50, 50, 50};
  if (r.segments[segment].is_ground) return {110, 130, 170};
  const uint32_t h = static_cast<uint32_t>(segment) * 2654435761u;
  return {static_cast<uint8_t>(80 + (h >> 8) % 176), static_cast<uint8_t>(80 + (h >> 16) % 176),
          static_cast<uint8_t>(80 + (h >> 24) % 176)};
}

// The scored cloud coloured by rule score, GPR score and segment, for the 3D view.
void ColourClouds(const MobilityResult& r, MobilityFrameResult* out) {
  auto by_score = std::make_shared<PointCloud>();
  auto by_gpr = std::make_shared<PointCloud>();
  auto by_segment = std::make_shared<PointCloud>();
  for (PointCloud* cloud : {by_score.get(), by_gpr.get(), by_segment.get()}) {
    cloud->points = r.points;
    cloud->width = static_cast<int>(r.points.size());
  }
  const float nan = std::numeric_limits<float>::quiet_NaN();
  for (size_t i = 0; i < r.points.size(); ++i) {
    const int s = r.segment[i];
    const cv::Vec3b rule =
        ScoreColorBgr(s < 0 ? nan : static_cast<float>(r.segments[s].score_rule));
    const cv::Vec3b gpr = ScoreColorBgr(s < 0 ? nan : static_cast<float>(r.segments[s].score_gpr));
    by_score->colors.emplace_back(rule[2], rule[1], rule[0]);
    by_gpr->colors.emplace_back(gpr[2], gpr[1], gpr[0]);
    by_segment->colors.push_back(SegmentColor(r, s));
  }
  out->by_score = std::move(by_score);
  out->by_gpr = std::move(by_gpr);
  out->by_segment = std::move(by_segment);
}

// The statistics of one frame.
std::vector<std::pair<std::string, double>> FrameStatistics(const MobilityResult& r) {
  std::vector<std::pair<std::string, double>> stats;
  for (const StageReport& s : r.stages) {
    stats.emplace_back("mobility/" + s.name + "_ms", s.ms);
    stats.emplace_back("mobility/" + s.name + "_points", static_cast<double>(s.points));
  }
  stats.emplace_back("mobility/segments", static_cast<double>(r.segments.size()));
  if (r.ground.found) stats.emplace_back("mobility/ground_height_m", r.ground.d);
  return stats;
}

// The expected up direction of a floor calibration file ("" = none).
StatusOr<std::optional<Eigen::Vector3d>> UpFromFloorFile(const std::string& path) {
  if (path.empty()) return std::optional<Eigen::Vector3d>();
  StatusOr<FloorCalibration> floor = ReadFloorCalibration(path);
  if (!floor.ok()) return floor.status();
  return std::optional<Eigen::Vector3d>(floor->plane.normal);
}

}  // namespace

const std::vector<std::string>& MobilityStages() {
  static const std::vector<std::string> kStages = {
      "downsample", "range_cut",    "denoise", "normals",  "rgbn",
      "ground",     "segmentation", "surface", "mobility", "maps"};
  return kStages;
}

const StatisticTable& MobilityStatistics() {
  static const StatisticTable kTable = [] {
    StatisticTable table;
    for (const std::string& stage : MobilityStages()) {
      table.push_back({"mobility/" + stage + "_ms", "ms", "Time of the " + stage + " stage."});
    }
    for (const std::string& stage : MobilityStages()) {
      table.push_back({"mobility/" + stage + "_points", "count",
                       "Points (segments for mobility) entering the " + stage + " stage."});
    }
    table.push_back({"mobility/segments", "count", "Segments measured, the ground included."});
    table.push_back({"mobility/ground_height_m", "m",
                     "Camera height above the ground plane (when one was found)."});
    return table;
  }();
  return kTable;
}

cv::Mat MobilityScoreSurface() { return RenderScoreSurface(GprScore::TrainOnTable()); }

void MobilityRunRecord::Add(std::shared_ptr<const MobilityResult> r, bool keep_for_files) {
  const int64_t index = frames++;
  if (!r->status.ok()) {
    ++failed;
    log.push_back("frame " + std::to_string(index) + ": " + r->status.message());
  } else {
    log.push_back("frame " + std::to_string(index) + ": ok, " + std::to_string(r->segments.size()) +
                  " segments");
  }
  segments_csv += SegmentsCsvRows(index, *r);
  kept.push_back(keep_for_files ? std::move(r) : nullptr);
}

struct MobilityPipeline::State {
  MobilityOptions options;
  MobilityRunOptions run;
  bool configured = false;
  std::optional<PipelineSource> source;
  MobilityMapper mapper;
  std::optional<Eigen::Vector3d> up;  // From mobility.run.floor_file.
  std::vector<TrueRegion> regions;    // Simulated terrain's true regions, for accuracy.
  MobilityRunRecord record;

  // The mapper's input of a frame.
  StatusOr<MobilityInput> InputOf(const Frame& frame) const;
  // Maps one frame (the mapper is const: frames are independent).
  StatusOr<std::shared_ptr<const MobilityFrameResult>> Map(const Frame& frame) const;
  // Adds a mapped frame to the run's record.
  void Record(const MobilityFrameResult& result);
};

StatusOr<MobilityInput> MobilityPipeline::State::InputOf(const Frame& frame) const {
  const SourceInfo& info = source->info;
  MobilityInput input;
  if (const auto* rgbd = std::get_if<RgbdFrame>(&frame)) {
    if (!info.rgbd) return FailedPrecondition(info.path + ": the RGB-D source has no camera");
    input = MobilityInputFromRgbd(*rgbd, info.rgbd->color);
  } else if (const auto* cloud = std::get_if<CloudFrame>(&frame)) {
    input = MobilityInputFromCloud(*cloud);
  } else {
    return InvalidArgument(info.path + " gave a frame that is neither RGB-D nor a cloud");
  }
  input.up_in_camera = up;
  return input;
}

MobilityPipeline::MobilityPipeline() : state_(std::make_unique<State>()) {}
MobilityPipeline::~MobilityPipeline() = default;

Status MobilityPipeline::Configure(const OptionSet& options) {
  const MobilityOptions mobility = options.Extract(MobilityOptions::Describe());
  const MobilityRunOptions run = options.Extract(MobilityRunOptions::Describe());
  std::string error;
  if (!mobility.IsValid(&error) || !run.IsValid(&error)) return InvalidArgument(error);
  StatusOr<std::optional<Eigen::Vector3d>> up = UpFromFloorFile(run.floor_file);
  if (!up.ok()) return up.status();
  State& s = *state_;
  SIGHTLINE_RETURN_IF_ERROR(s.mapper.Configure(mobility));
  s.options = mobility;
  s.run = run;
  s.up = *up;
  s.configured = true;
  return Status::Ok();
}

Status MobilityPipeline::Open(const PipelineSource& source) {
  State& s = *state_;
  if (!s.configured) return FailedPrecondition("mobility: Configure() before Open()");
  const SourceInfo& info = source.info;
  if (info.kind != SourceKind::kRgbd && info.kind != SourceKind::kCloud) {
    return InvalidArgument(info.path + " is a " + SourceKindName(info.kind) +
                           " dataset; the mobility map needs RGB-D frames or point clouds");
  }
  std::vector<TrueRegion> regions;
  const std::string regions_path = FindRegionsFile(info.path);
  if (!regions_path.empty()) {
    StatusOr<std::vector<TrueRegion>> read = ReadTerrainRegions(regions_path);
    if (!read.ok()) return read.status();
    regions = std::move(*read);
  }
  s.source = source;
  s.regions = std::move(regions);
  s.record = MobilityRunRecord();
  return Status::Ok();
}

int64_t MobilityPipeline::FrameLimit() const { return state_->run.max_frames; }

StatusOr<std::shared_ptr<const MobilityFrameResult>> MobilityPipeline::State::Map(
    const Frame& frame) const {
  StatusOr<MobilityInput> input = InputOf(frame);
  if (!input.ok()) return input.status();
  auto result = std::make_shared<MobilityFrameResult>();
  result->stamp = StampOf(frame);
  result->mobility = mapper.Process(*input);
  result->status = result->mobility->status;
  result->stats = FrameStatistics(*result->mobility);
  ColourClouds(*result->mobility, result.get());
  return std::shared_ptr<const MobilityFrameResult>(std::move(result));
}

void MobilityPipeline::State::Record(const MobilityFrameResult& result) {
  const MobilityResult& r = *result.mobility;
  const int64_t index = record.frames;
  record.Add(result.mobility, run.cloud_format != "none" || run.write_images);
  record.stats.Add(result);
  const Trajectory* gt = source->ground_truth.get();
  if (regions.empty() || gt == nullptr || !r.ground.found) return;
  if (auto k = gt->Nearest(r.stamp.sensor_time_s, run.gt_tolerance_s)) {
    AddTerrainAccuracy(index, r, gt->poses()[*k].world_from_sensor, regions, run.min_match_fraction,
                       &record.terrain);
  }
}

StatusOr<std::shared_ptr<const PipelineResult>> MobilityPipeline::Process(const Frame& frame) {
  State& s = *state_;
  if (!s.source) return FailedPrecondition("mobility: Open() before Process()");
  StatusOr<std::shared_ptr<const MobilityFrameResult>> result = s.Map(frame);
  if (!result.ok()) return result.status();
  s.Record(**result);
  return std::shared_ptr<const PipelineResult>(*result);
}

StatusOr<std::shared_ptr<const PipelineResult>> MobilityPipeline::Reprocess(const Frame& frame) {
  if (!state_->source) return FailedPrecondition("mobility: Open() before Reprocess()");
  StatusOr<std::shared_ptr<const MobilityFrameResult>> result = state_->Map(frame);
  if (!result.ok()) return result.status();
  return std::shared_ptr<const PipelineResult>(*result);
}

void MobilityPipeline::Reset() { state_->record = MobilityRunRecord(); }

StatusOr<RunResult> MobilityPipeline::Finish(const std::string& out_dir) {
  const State& s = *state_;
  if (!s.source) return FailedPrecondition("mobility: nothing to save before Open()");
  return FinishMobilityRun(s.record, s.run, out_dir);
}

PipelineInfo MobilityPipelineInfo() {
  PipelineInfo info;
  info.name = "mobility";
  info.title = "Mobility map";
  info.summary =
      "mobility map from RGB-D frames or point clouds: ground, segments, slope, "
      "roughness, rule and GPR traversability scores";
  info.accepts = {SourceKind::kRgbd, SourceKind::kCloud};
  info.declare_options = [](OptionSet* set) {
    SIGHTLINE_RETURN_IF_ERROR(set->Declare(MobilityOptions::Describe()));
    return set->Declare(MobilityRunOptions::Describe());
  };
  info.create = [] { return std::unique_ptr<Pipeline>(std::make_unique<MobilityPipeline>()); };
  return info;
}

}  // namespace sightline
