#include "core/pipeline/mapping_pipeline.h"

#include <cstdio>
#include <utility>

#include "core/io/floor_file.h"
#include "core/mapping/option_check.h"
#include "core/pipeline/mapping_run.h"

namespace sightline {

using mapping_internal::Invalid;

bool MappingRunOptions::IsValid(std::string* error) const {
  if (max_frames < 0) return Invalid(error, "mapping.run.max_frames must be >= 0");
  if (floor_frames < 1) return Invalid(error, "mapping.run.floor_frames must be >= 1");
  if (!(gt_tolerance_s >= 0)) return Invalid(error, "mapping.run.gt_tolerance_s must be >= 0");
  if (map_tolerance_cells < 0)
    return Invalid(error, "mapping.run.map_tolerance_cells must be >= 0");
  if (!(visible_wall_min_length_m >= 0)) {
    return Invalid(error, "mapping.run.visible_wall_min_length_m must be >= 0");
  }
  if (!(visible_wall_min_fraction >= 0 && visible_wall_min_fraction <= 1)) {
    return Invalid(error, "mapping.run.visible_wall_min_fraction must lie in [0, 1]");
  }
  return true;
}

OptionTable<MappingRunOptions> MappingRunOptions::Describe() {
  using O = MappingRunOptions;
  return OptionTable<O>("mapping.run")
      .Int("max_frames", &O::max_frames, "frames", 0, 1e9, 1, "Frames to process; 0 = all.")
      .String("floor_file", &O::floor_file,
              "Floor calibration file (sightline-cli floor); empty = calibrate from the first "
              "frames of the run.")
      .Int("floor_frames", &O::floor_frames, "frames", 1, 1000, 1,
           "Frames used to calibrate the floor when no floor_file is given.")
      .Double("gt_tolerance_s", &O::gt_tolerance_s, "s", 0, 1, 0.005,
              "A ground-truth or odometry pose belongs to a frame when this close in time.")
      .Bool("camera_offset_from_scene", &O::camera_offset_from_scene,
            "Take the camera's offset ahead of the odometry base from the recording's "
            "scene.yaml (simulator) when present.")
      .Double("camera_forward_m", &O::camera_forward_m, "m", -5, 5, 0.01,
              "Otherwise: the camera's optical centre this far ahead of the odometry base.")
      .Int("map_tolerance_cells", &O::map_tolerance_cells, "cells", 0, 20, 1,
           "Tolerance of accuracy.map_iou: a map cell within this many cells of a true wall "
           "counts as on it.")
      .Double("visible_wall_min_length_m", &O::visible_wall_min_length_m, "m", 0, 50, 0.1,
              "accuracy.wall_recall: a true wall is visible in a frame when at least this much "
              "of it is in view ...")
      .Double("visible_wall_min_fraction", &O::visible_wall_min_fraction, "", 0, 1, 0.01,
              "... and at least this fraction of the scan's rays hit it.");
}

namespace {

// The statistics of one mapped frame.
std::vector<std::pair<std::string, double>> FrameStatistics(const MappingFrameResult& r) {
  const MappingStageTimes& t = r.times;
  const bool rgbd = r.pose_source == "rgbd";
  std::vector<std::pair<std::string, double>> stats;
  if (t.people_ms > 0) stats.emplace_back("mapping/people_ms", t.people_ms);
  stats.insert(stats.end(), {{"mapping/occupancy_ms", t.occupancy_ms},
                             {"mapping/scan_ms", t.scan_ms},
                             {"mapping/lines_ms", t.lines_ms}});
  if (rgbd) stats.emplace_back("mapping/odometry_ms", t.odometry_ms);
  stats.insert(stats.end(), {{"mapping/rotation_ms", t.rotation_ms},
                             {"mapping/stitch_ms", t.stitch_ms},
                             {"mapping/scan_points", static_cast<double>(r.scan.points.size())},
                             {"mapping/lines", static_cast<double>(r.lines.lines.size())},
                             {"mapping/heading_deg", RadToDeg(r.pose.heading_rad)},
                             {"mapping/reset", r.reset ? 1.0 : 0.0}});
  if (rgbd) stats.emplace_back("mapping/odometry_failed", r.odometry_failure.empty() ? 0.0 : 1.0);
  return stats;
}

}  // namespace

const StatisticTable& MappingStatistics() {
  static const StatisticTable kTable = {
      {"mapping/people_ms", "ms", "Person detection (HOG; only when it runs)."},
      {"mapping/occupancy_ms", "ms", "Occupancy image from the depth frame."},
      {"mapping/scan_ms", "ms", "Polar scan of the occupancy image."},
      {"mapping/lines_ms", "ms", "Wall line extraction."},
      {"mapping/odometry_ms", "ms", "RGB-D odometry (only when it is the pose source)."},
      {"mapping/rotation_ms", "ms", "Manhattan rotation and dead reckoning."},
      {"mapping/stitch_ms", "ms", "Stitching the frame into the global map."},
      {"mapping/scan_points", "count", "Scan points (nearest occupied cell per ray)."},
      {"mapping/lines", "count", "Wall lines found."},
      {"mapping/heading_deg", "deg", "Estimated heading of the robot."},
      {"mapping/reset", "", "1 when the Manhattan reference was reset on this frame."},
      {"mapping/odometry_failed", "",
       "1 when the RGB-D odometry failed on this frame (the pose was held, the frame not mapped)."},
  };
  return kTable;
}

void MappingRunRecord::Add(const MappingFrameResult& r, const std::vector<std::string>& reset_log) {
  const FrameStamp& stamp = r.stamp;
  ++statuses[r.status];
  ++pose_sources[r.pose_source];
  std::pair<int, int>& people = people_sources[r.people_source];
  ++people.first;
  people.second += static_cast<int>(r.people.size());
  if (r.status != "ok" || !r.odometry_failure.empty()) {
    frame_log.push_back(
        "frame " + std::to_string(stamp.sequence_id) + ": " + r.status +
        (r.odometry_failure.empty() ? "" : " (odometry: " + r.odometry_failure + ")"));
  }
  if (r.reset && !reset_log.empty()) frame_log.push_back("reset at " + reset_log.back());
  for (size_t i = 0; i < r.lines.lines.size(); ++i) {
    const WallSegment& l = r.lines.lines[i];
    char row[256];
    std::snprintf(row, sizeof(row), "%lld,%.6f,%zu,%.4f,%.4f,%.4f,%.4f,%.3f,%d,%.4f,%d\n",
                  static_cast<long long>(stamp.sequence_id), stamp.sensor_time_s, i, l.start.x(),
                  l.start.y(), l.end.x(), l.end.y(), RadToDeg(l.angle_rad), l.inliers, l.length_m,
                  l.direction_class);
    lines_csv += row;
  }
  frames.push_back({stamp.sensor_time_s, r.lines.lines, r.scan.fov_min_rad, r.scan.fov_max_rad,
                    r.scan.resolution_rad, r.scan.rays_cast});
}

Status MappingPipeline::State::StartRun(bool keep_floor) {
  StatusOr<MappingRecording> loaded = LoadMappingRecording(*source, run, options.pose_source);
  if (!loaded.ok()) return loaded.status();
  std::optional<FloorCalibration> next_floor;
  std::string next_log;
  if (!run.floor_file.empty()) {
    StatusOr<FloorCalibration> read = ReadFloorCalibration(run.floor_file);
    if (!read.ok()) return read.status();
    next_floor = *read;
    next_log = "floor: " + run.floor_file;
  } else if (keep_floor && floor && floor_log.rfind("floor: calibrated", 0) == 0) {
    next_floor = floor;
    next_log = floor_log;
  }
  recording = std::move(*loaded);
  floor = std::move(next_floor);
  floor_log = std::move(next_log);
  calibrator = std::make_unique<FloorCalibrator>(options.floor, run.floor_frames);
  pending.clear();
  floor_failure.clear();
  floorless_frames = 0;
  if (!floor) {
    chain.reset();
    record.Clear();
    return Status::Ok();
  }
  return StartChain();
}

Status MappingPipeline::State::StartChain() {
  record.Clear();
  MappingOptions chain_options = options;
  chain_options.pose_source = recording.pose_source;  // The recording's odometry, if it is used.
  chain = std::make_unique<MappingFrameProcessor>(chain_options);
  Status configured = chain->Configure(floor->plane, recording.camera);
  if (!configured.ok()) ForgetFloor();  // The next frames calibrate a usable one.
  return configured;
}

void MappingPipeline::State::ForgetFloor() {
  floor.reset();
  floor_log.clear();
  chain.reset();
  record.Clear();
  pending.clear();
  calibrator = std::make_unique<FloorCalibrator>(options.floor, run.floor_frames);
}

size_t MappingPipeline::State::FloorFramesWanted() const {
  int64_t wanted = run.floor_frames;
  int64_t total = source->info.frame_count;
  if (run.max_frames > 0 && (total < 0 || total > run.max_frames)) total = run.max_frames;
  if (total > 0 && total < wanted) wanted = total;
  return static_cast<size_t>(wanted);
}

void MappingPipeline::State::TakeRequests() {
  if (!requests) return;
  const int asked = requests->floor_calibrations.load();
  if (asked == requests_seen) return;
  requests_seen = asked;  // The operator asked for a new floor calibration.
  ForgetFloor();
}

StatusOr<std::shared_ptr<const MappingResult>> MappingPipeline::State::CalibrateWith(
    const RgbdFrame& frame) {
  pending.push_back(frame);
  calibrator->AddDepth(frame.depth_m, recording.camera);
  if (pending.size() >= FloorFramesWanted()) return CalibrateAndMapPending();
  auto result = std::make_shared<MappingResult>();
  result->stamp = frame.stamp;
  char note[96];
  std::snprintf(note, sizeof(note), "calibrating the floor (%zu of %zu frames)", pending.size(),
                FloorFramesWanted());
  result->note = note;
  return std::shared_ptr<const MappingResult>(std::move(result));
}

StatusOr<std::shared_ptr<const MappingResult>> MappingPipeline::State::CalibrateAndMapPending() {
  StatusOr<FloorCalibration> fitted = calibrator->Calibrate(recording.root);
  const std::vector<RgbdFrame> frames = std::move(pending);
  ForgetFloor();
  if (!fitted.ok() && fitted.status().code() == StatusCode::kFailedPrecondition) {
    return NoFloorIn(frames, fitted.status().message());
  }
  if (!fitted.ok()) {
    return fitted.status().WithContext("calibrating the floor from the first " +
                                       std::to_string(frames.size()) + " frames of " +
                                       recording.root);
  }
  floor = *fitted;
  floor_log = "floor: " + DescribeFloorCalibration(*floor);
  SIGHTLINE_RETURN_IF_ERROR(StartChain());
  std::shared_ptr<const MappingResult> last;
  for (const RgbdFrame& frame : frames) {
    StatusOr<std::shared_ptr<const MappingResult>> mapped = MapFrame(frame);
    if (!mapped.ok()) return mapped.status();
    last = *mapped;
  }
  auto result = std::make_shared<MappingResult>(*last);
  char note[128];
  std::snprintf(note, sizeof(note), "floor: camera %.3f m above it, pitched %.1f deg down",
                floor->plane.CameraHeightM(), floor->plane.PitchDownDeg());
  result->note = note;
  return std::shared_ptr<const MappingResult>(std::move(result));
}

std::shared_ptr<const MappingResult> MappingPipeline::State::NoFloorIn(
    const std::vector<RgbdFrame>& frames, const std::string& why) {
  floorless_frames += static_cast<int64_t>(frames.size());
  floor_failure = why;
  auto result = std::make_shared<MappingResult>();
  result->stamp = frames.back().stamp;
  result->note = "no floor in " + std::to_string(frames.size()) +
                 " frame(s), calibrating on the next ones: " + why;
  return result;
}

StatusOr<std::shared_ptr<const MappingResult>> MappingPipeline::State::MapFrame(
    const RgbdFrame& frame) {
  StatusOr<std::shared_ptr<const MappingFrameResult>> mapped =
      chain->Process(recording.MakeInput(frame, run.gt_tolerance_s));
  if (!mapped.ok()) {
    return mapped.status().WithContext("frame " + std::to_string(frame.stamp.sequence_id));
  }
  record.Add(**mapped, chain->reset_log());
  auto result = std::make_shared<MappingResult>();
  result->stamp = frame.stamp;
  result->mapping = *mapped;
  result->floor = floor->plane;
  result->base_from_camera = chain->base_from_camera();
  result->stats = FrameStatistics(**mapped);
  record.stats.Add(*result);
  return std::shared_ptr<const MappingResult>(std::move(result));
}

MappingPipeline::MappingPipeline(std::shared_ptr<const MappingRequests> requests)
    : state_(std::make_unique<State>()) {
  state_->requests = std::move(requests);
  if (state_->requests) state_->requests_seen = state_->requests->floor_calibrations.load();
}

MappingPipeline::~MappingPipeline() = default;

Status MappingPipeline::Configure(const OptionSet& options) {
  MappingOptions mapping = options.Extract(MappingOptions::Describe());
  MappingRunOptions run = options.Extract(MappingRunOptions::Describe());
  std::string error;
  if (!mapping.IsValid(&error) || !run.IsValid(&error)) return InvalidArgument(error);
  State& s = *state_;
  std::swap(s.options, mapping);
  std::swap(s.run, run);
  s.configured = true;
  if (!s.source) return Status::Ok();
  Status started = s.StartRun(/*keep_floor=*/true);
  if (started.ok()) return started;
  std::swap(s.options, mapping);  // The previous options stay in force.
  std::swap(s.run, run);
  (void)s.StartRun(/*keep_floor=*/true);
  return started;
}

Status MappingPipeline::Open(const PipelineSource& source) {
  State& s = *state_;
  if (!s.configured) return FailedPrecondition("mapping: Configure() before Open()");
  if (source.info.kind != SourceKind::kRgbd) {
    return InvalidArgument(source.info.path + " is a " + SourceKindName(source.info.kind) +
                           " source; mapping needs RGB-D frames");
  }
  s.source = source;
  s.floor.reset();
  s.floor_log.clear();
  Status started = s.StartRun(/*keep_floor=*/false);
  if (!started.ok()) s.source.reset();
  return started;
}

int64_t MappingPipeline::FrameLimit() const { return state_->run.max_frames; }

StatusOr<std::shared_ptr<const PipelineResult>> MappingPipeline::Process(const Frame& frame) {
  State& s = *state_;
  if (!s.source) return FailedPrecondition("mapping: Open() before Process()");
  const auto* rgbd = std::get_if<RgbdFrame>(&frame);
  if (rgbd == nullptr) return InvalidArgument(s.source->info.path + " does not give RGB-D frames");
  s.TakeRequests();
  StatusOr<std::shared_ptr<const MappingResult>> result =
      s.floor ? s.MapFrame(*rgbd) : s.CalibrateWith(*rgbd);
  if (!result.ok()) return result.status();
  return std::shared_ptr<const PipelineResult>(*result);
}

void MappingPipeline::Reset() {
  State& s = *state_;
  s.pending.clear();
  if (s.calibrator) s.calibrator->Clear();
  s.record.Clear();
  s.floor_failure.clear();
  s.floorless_frames = 0;
  if (s.chain) s.chain->Restart();
}

StatusOr<RunResult> MappingPipeline::Finish(const std::string& out_dir) {
  State& s = *state_;
  if (!s.source) return FailedPrecondition("mapping: nothing to save before Open()");
  if (!s.floor && !s.pending.empty()) {
    // The run ended before floor_frames frames: calibrate on those there were.
    StatusOr<std::shared_ptr<const MappingResult>> mapped = s.CalibrateAndMapPending();
    if (!mapped.ok()) return mapped.status();
  }
  if (!s.floor && !s.floor_failure.empty()) return FinishFloorlessRun(s, out_dir);
  if (!s.floor || !s.chain) {
    return FailedPrecondition("mapping: no floor calibration yet, nothing to save");
  }
  return FinishMappingRun(s, out_dir);
}

Status DeclareMappingOptions(OptionSet* options) {
  // The map is rendered every 10 frames for views (the run's files do not depend on it).
  MappingOptions defaults;
  defaults.stitch.render_every_n = 10;
  SIGHTLINE_RETURN_IF_ERROR(options->Declare(MappingOptions::Describe(), defaults));
  return options->Declare(MappingRunOptions::Describe());
}

PipelineInfo MappingPipelineInfo(const std::shared_ptr<const MappingRequests>& requests) {
  PipelineInfo info;
  info.name = "mapping";
  info.title = "Indoor mapping (Manhattan walls)";
  info.summary =
      "indoor Manhattan mapping from RGB-D: floor, wall lines, heading, stitched occupancy map";
  info.accepts = {SourceKind::kRgbd};
  info.declare_options = DeclareMappingOptions;
  info.create = [requests]() -> std::unique_ptr<Pipeline> {
    return std::make_unique<MappingPipeline>(requests);
  };
  return info;
}

}  // namespace sightline
