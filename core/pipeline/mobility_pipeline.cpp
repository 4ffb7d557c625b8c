#include "core/pipeline/mobility_pipeline.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <opencv2/imgcodecs.hpp>

#include "core/common/text_file.h"
#include "core/io/dataset.h"
#include "core/io/floor_file.h"
#include "core/mapping/floor_plane.h"
#include "core/mobility/mobility_map.h"
#include "core/mobility/terrain_truth.h"
#include "core/pipeline/mobility_outputs.h"
#include "core/sensors/driver_registry.h"

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

double Median(std::vector<double> v) {
  if (v.empty()) return std::nan("");
  std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
  return v[v.size() / 2];
}

// The recording folder holding regions.csv: the dataset path or its parent.
std::string FindRegionsFile(const std::string& dataset_path, const std::string& source_path) {
  for (const std::string& folder :
       {dataset_path, source_path, std::filesystem::path(source_path).parent_path().string()}) {
    const std::string path = JoinPath(folder, "regions.csv");
    if (FileExists(path)) return path;
  }
  return "";
}

// Accuracy figures gathered over the frames of a simulated terrain.
struct TerrainAccuracy {
  double slope_error_max = 0;
  std::string worst;  // Where the largest slope error was, for the log.
  int slopes = 0;
  std::vector<double> flat_roughness;
};

void AddTerrainAccuracy(int64_t frame, const MobilityResult& r,
                        const Eigen::Isometry3d& world_from_camera,
                        const std::vector<TrueRegion>& regions, double min_fraction,
                        TerrainAccuracy* acc) {
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

StatusOr<RunResult> RunMobility(const RunContext& context) {
  const MobilityOptions options = context.options.Extract(MobilityOptions::Describe());
  const MobilityRunOptions run = context.options.Extract(MobilityRunOptions::Describe());
  std::string error;
  if (!options.IsValid(&error) || !run.IsValid(&error)) return InvalidArgument(error);
  // Any RGB-D source: datasets, .oni recordings and sensor URIs (openni2://...).
  StatusOr<std::unique_ptr<Source>> opened = OpenSource(context.dataset_path);
  if (!opened.ok()) return opened.status();
  Source& source = **opened;
  const SourceInfo& info = source.info();
  if (info.kind != SourceKind::kRgbd && info.kind != SourceKind::kCloud) {
    return InvalidArgument(context.dataset_path + " is a " + SourceKindName(info.kind) +
                           " dataset; the mobility map needs RGB-D frames or point clouds");
  }
  std::optional<Eigen::Vector3d> up;
  if (!run.floor_file.empty()) {
    StatusOr<FloorCalibration> floor = ReadFloorCalibration(run.floor_file);
    if (!floor.ok()) return floor.status();
    up = floor->plane.normal;
  }
  std::vector<TrueRegion> regions;
  const std::string regions_path = FindRegionsFile(context.dataset_path, info.path);
  if (!regions_path.empty()) {
    StatusOr<std::vector<TrueRegion>> read = ReadTerrainRegions(regions_path);
    if (!read.ok()) return read.status();
    regions = std::move(*read);
  }
  MobilityMapper mapper(options);
  RunResult result;
  result.dataset_format = info.format;
  const std::string csv_path = JoinPath(context.out_dir, "segments.csv");
  std::ofstream csv(csv_path);
  if (!csv) return NotFound("cannot write " + csv_path);
  csv << SegmentsCsvHeader();
  std::vector<std::string> log;
  std::map<std::string, std::vector<double>> stage_points;
  std::vector<double> heights;
  TerrainAccuracy terrain;
  int64_t total = info.frame_count;
  if (run.max_frames > 0 && (total < 0 || total > run.max_frames)) total = run.max_frames;
  int failed = 0;
  while (total < 0 || result.frames < total) {
    if (context.Cancelled())
      return Cancelled("run cancelled after " + std::to_string(result.frames) + " frames");
    Status grabbed = source.Grab();
    if (grabbed.code() == StatusCode::kOutOfRange) break;
    if (!grabbed.ok()) return grabbed;
    StatusOr<Frame> frame = source.Retrieve();
    if (!frame.ok()) return frame.status();
    MobilityInput input;
    if (const auto* rgbd = std::get_if<RgbdFrame>(&*frame)) {
      if (!info.rgbd) return FailedPrecondition(info.path + ": the RGB-D source has no camera");
      input = MobilityInputFromRgbd(*rgbd, info.rgbd->color);
    } else if (const auto* cloud = std::get_if<CloudFrame>(&*frame)) {
      input = MobilityInputFromCloud(*cloud);
    } else {
      return InvalidArgument(context.dataset_path +
                             " gave a frame that is neither RGB-D nor a cloud");
    }
    input.up_in_camera = up;
    const std::shared_ptr<const MobilityResult> r = mapper.Process(input);
    const int64_t index = result.frames;
    double total_ms = 0;
    for (const StageReport& s : r->stages) {
      context.timing->Add(s.name, s.ms);
      stage_points[s.name].push_back(static_cast<double>(s.points));
      total_ms += s.ms;
    }
    context.timing->Add("total", total_ms);
    char name[64];
    if (!r->status.ok()) {
      ++failed;
      log.push_back("frame " + std::to_string(index) + ": " + r->status.message());
    } else {
      log.push_back("frame " + std::to_string(index) + ": ok, " +
                    std::to_string(r->segments.size()) + " segments");
    }
    if (r->ground.found) heights.push_back(r->ground.d);
    csv << SegmentsCsvRows(index, *r);
    if (run.cloud_format != "none" && !r->points.empty()) {
      std::snprintf(name, sizeof(name), "%06lld_cloud.%s", static_cast<long long>(index),
                    run.cloud_format.c_str());
      SIGHTLINE_RETURN_IF_ERROR(
          WriteScoredCloud(*r, run.cloud_format, JoinPath(context.out_dir, name)));
      result.outputs.push_back(name);
    }
    if (run.write_images && !r->projection.empty()) {
      std::snprintf(name, sizeof(name), "%06lld_projection.png", static_cast<long long>(index));
      if (!cv::imwrite(JoinPath(context.out_dir, name), r->projection)) {
        return Unavailable("cannot write " + JoinPath(context.out_dir, name));
      }
      result.outputs.push_back(name);
    }
    if (run.write_images && r->ground.found) {
      std::snprintf(name, sizeof(name), "%06lld_topview.png", static_cast<long long>(index));
      if (!cv::imwrite(JoinPath(context.out_dir, name), RenderTopView(r->map))) {
        return Unavailable("cannot write " + JoinPath(context.out_dir, name));
      }
      result.outputs.push_back(name);
    }
    const Trajectory* gt = source.ground_truth();
    if (!regions.empty() && gt != nullptr && r->ground.found) {
      if (auto k = gt->Nearest(r->stamp.sensor_time_s, run.gt_tolerance_s)) {
        AddTerrainAccuracy(index, *r, gt->poses()[*k].world_from_sensor, regions,
                           run.min_match_fraction, &terrain);
      }
    }
    ++result.frames;
    if (context.progress) context.progress(result.frames, total);
  }
  csv.flush();
  if (!csv) return Unavailable("write to " + csv_path + " failed (disk full?)");
  if (result.frames == 0) return OutOfRange(context.dataset_path + " holds no frames");
  result.outputs.push_back("segments.csv");
  if (!heights.empty()) result.accuracy.emplace_back("ground_height_m", Median(heights));
  if (terrain.slopes > 0) {
    result.accuracy.emplace_back("slope_error_deg_max", terrain.slope_error_max);
    log.push_back("largest slope error: " + terrain.worst);
  }
  if (!terrain.flat_roughness.empty()) {
    result.accuracy.emplace_back("flat_roughness", Median(terrain.flat_roughness));
  }
  for (const auto& [stage, points] : stage_points) {
    result.counts.emplace_back("points_" + stage, Median(points));
  }
  result.counts.emplace_back("frames_without_map", failed);
  result.counts.emplace_back("frames_with_ground", static_cast<double>(heights.size()));
  const std::string log_path = JoinPath(context.out_dir, "mobility_log.txt");
  std::ofstream log_file(log_path);
  if (!log_file) return NotFound("cannot write " + log_path);
  for (const std::string& line : log) log_file << line << "\n";
  result.outputs.push_back("mobility_log.txt");
  return result;
}

}  // namespace

PipelineInfo MobilityPipeline() {
  PipelineInfo info;
  info.name = "mobility";
  info.summary =
      "mobility map from RGB-D frames or point clouds: ground, segments, slope, "
      "roughness, rule and GPR scores (seed 001)";
  info.declare_options = [](OptionSet* set) {
    SIGHTLINE_RETURN_IF_ERROR(set->Declare(MobilityOptions::Describe()));
    return set->Declare(MobilityRunOptions::Describe());
  };
  info.run = RunMobility;
  return info;
}

}  // namespace sightline
