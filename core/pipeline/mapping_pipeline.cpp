#include "core/pipeline/mapping_pipeline.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <deque>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>

#include "core/common/text_file.h"
#include "core/common/timing.h"
#include "core/eval/evaluation.h"
#include "core/io/dataset.h"
#include "core/io/floor_file.h"
#include "core/mapping/mapping_accuracy.h"
#include "core/mapping/mapping_frame_processor.h"
#include "core/mapping/option_check.h"
#include "core/pipeline/mapping_recording.h"

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

RgbdFrame* AsRgbd(Frame* frame) { return std::get_if<RgbdFrame>(frame); }

// Camera of an RGB-D source.
StatusOr<PinholeCamera> SourceCamera(const Source& source) {
  const SourceInfo& info = source.info();
  if (info.rgbd) return info.rgbd->color;
  if (info.camera) return *info.camera;
  return FailedPrecondition(info.path + ": the RGB-D source has no camera intrinsics");
}

double Median(std::vector<double> v) {
  if (v.empty()) return 0;
  std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
  return v[v.size() / 2];
}

// One frame's lines kept for the accuracy figures.
struct FrameLines {
  double time_s = 0;
  std::vector<WallSegment> lines;
  double fov_min_rad = 0, fov_max_rad = 0, resolution_rad = 0;
  int rays = 0;
};

StatusOr<RunResult> RunMapping(const RunContext& context) {
  MappingOptions options = context.options.Extract(MappingOptions::Describe());
  const MappingRunOptions run = context.options.Extract(MappingRunOptions::Describe());
  std::string error;
  if (!options.IsValid(&error) || !run.IsValid(&error)) return InvalidArgument(error);

  StatusOr<std::unique_ptr<Source>> opened = OpenDataset(context.dataset_path, SourceKind::kRgbd);
  if (!opened.ok()) return opened.status();
  Source& source = **opened;
  // The recording's extra files: odometry, person boxes, true walls, camera offset.
  StatusOr<MappingRecording> recording = LoadMappingRecording(source.info(), run);
  if (!recording.ok()) return recording.status();
  const PinholeCamera* camera = &recording->camera;
  std::vector<std::string> log_lines = recording->log_lines;
  const std::optional<std::vector<TrueWall>>& walls = recording->walls;

  int64_t total = source.info().frame_count;
  if (run.max_frames > 0 && (total < 0 || total > run.max_frames)) total = run.max_frames;
  RunResult result;
  result.dataset_format = source.info().format;

  // Frames, buffered while the floor is calibrated from the first ones.
  std::deque<RgbdFrame> pending;
  auto read_frame = [&]() -> StatusOr<bool> {
    ScopedTimer timer(context.timing, "read");
    Status grabbed = source.Grab();
    if (grabbed.code() == StatusCode::kOutOfRange) return false;
    if (!grabbed.ok()) return grabbed;
    StatusOr<Frame> frame = source.Retrieve();
    if (!frame.ok()) return frame.status();
    RgbdFrame* rgbd = AsRgbd(&*frame);
    if (rgbd == nullptr)
      return InvalidArgument(context.dataset_path + " does not give RGB-D frames");
    pending.push_back(std::move(*rgbd));
    return true;
  };

  FloorCalibration floor;
  if (!run.floor_file.empty()) {
    StatusOr<FloorCalibration> read = ReadFloorCalibration(run.floor_file);
    if (!read.ok()) return read.status();
    floor = *read;
    log_lines.push_back("floor: " + run.floor_file);
  } else {
    std::vector<Eigen::Vector3f> points;
    while (static_cast<int>(pending.size()) < run.floor_frames &&
           (total < 0 || static_cast<int64_t>(pending.size()) < total)) {
      StatusOr<bool> more = read_frame();
      if (!more.ok()) return more.status();
      if (!*more) break;
      AppendDepthPoints(pending.back().depth_m, *camera, options.floor.max_depth_m, 2, &points);
    }
    if (pending.empty()) return OutOfRange(context.dataset_path + " holds no frames");
    StatusOr<FloorFitResult> fit = FloorPlaneEstimator(options.floor).Fit(points);
    if (!fit.ok()) {
      return fit.status().WithContext("calibrating the floor from the first " +
                                      std::to_string(pending.size()) + " frames of " +
                                      context.dataset_path);
    }
    floor.plane = fit->plane;
    floor.inlier_ratio = fit->inlier_ratio;
    floor.frames = static_cast<int>(pending.size());
    floor.source = context.dataset_path;
    char text[160];
    std::snprintf(text, sizeof(text),
                  "floor: calibrated from %d frames: camera %.3f m above the floor, pitched "
                  "%.1f deg down, %.0f %% inliers",
                  floor.frames, floor.plane.CameraHeightM(), floor.plane.PitchDownDeg(),
                  100 * fit->inlier_ratio);
    log_lines.push_back(text);
  }
  SIGHTLINE_RETURN_IF_ERROR(WriteFloorCalibration(floor, JoinPath(context.out_dir, "floor.yaml")));
  result.outputs.push_back("floor.yaml");

  MappingFrameProcessor processor(options);
  SIGHTLINE_RETURN_IF_ERROR(processor.Configure(floor.plane, *camera));
  const Eigen::Isometry3d camera_from_base = processor.base_from_camera().inverse();

  const std::string lines_path = JoinPath(context.out_dir, "lines.csv");
  std::ofstream lines_csv(lines_path);
  if (!lines_csv) return NotFound("cannot write " + lines_path);
  lines_csv << "# frame,time_s,line,x1_m,y1_m,x2_m,y2_m,angle_deg,inliers,length_m,"
               "direction_class  (end points in the robot base frame: x forward, y left; "
               "angle from forward; direction_class 0/1 = Manhattan axes of the reference, -1 = "
               "neither)\n";

  std::vector<FrameLines> frame_lines;
  std::map<std::string, int> statuses;
  int64_t scan_points = 0, line_count = 0;
  while (total < 0 || result.frames < total) {
    if (context.Cancelled()) {
      return Cancelled("run cancelled after " + std::to_string(result.frames) + " frames");
    }
    ScopedTimer frame_timer(context.timing, "total");
    if (pending.empty()) {
      StatusOr<bool> more = read_frame();
      if (!more.ok()) return more.status();
      if (!*more) break;
    }
    RgbdFrame frame = std::move(pending.front());
    pending.pop_front();

    const MappingInput input = recording->MakeInput(frame, run.gt_tolerance_s);
    StatusOr<std::shared_ptr<const MappingFrameResult>> processed =
        processor.Process(input, context.timing);
    if (!processed.ok()) {
      return processed.status().WithContext("frame " + std::to_string(frame.stamp.sequence_id));
    }
    const MappingFrameResult& r = **processed;
    ++statuses[r.status];
    if (r.status != "ok") {
      log_lines.push_back("frame " + std::to_string(frame.stamp.sequence_id) + ": " + r.status);
    }
    if (r.reset) log_lines.push_back("reset at " + processor.reset_log().back());
    scan_points += static_cast<int64_t>(r.scan.points.size());
    line_count += static_cast<int64_t>(r.lines.lines.size());
    for (size_t i = 0; i < r.lines.lines.size(); ++i) {
      const WallSegment& l = r.lines.lines[i];
      char row[256];
      std::snprintf(row, sizeof(row), "%lld,%.6f,%zu,%.4f,%.4f,%.4f,%.4f,%.3f,%d,%.4f,%d\n",
                    static_cast<long long>(frame.stamp.sequence_id), frame.stamp.sensor_time_s, i,
                    l.start.x(), l.start.y(), l.end.x(), l.end.y(), RadToDeg(l.angle_rad),
                    l.inliers, l.length_m, l.direction_class);
      lines_csv << row;
    }
    frame_lines.push_back({frame.stamp.sensor_time_s, r.lines.lines, r.scan.fov_min_rad,
                           r.scan.fov_max_rad, r.scan.resolution_rad, r.scan.rays_cast});
    ++result.frames;
    if (context.progress) context.progress(result.frames, total);
  }
  lines_csv.flush();
  if (!lines_csv) return Unavailable("write to " + lines_path + " failed (disk full?)");
  if (result.frames == 0) return OutOfRange(context.dataset_path + " holds no frames");
  result.outputs.push_back("lines.csv");

  // Trajectory of the camera (TUM) and the map.
  Trajectory estimate;
  for (size_t k = 0; k < processor.camera_trajectory().size(); ++k) {
    estimate.Add(processor.trajectory_times()[k], processor.camera_trajectory()[k]);
  }
  SIGHTLINE_RETURN_IF_ERROR(
      WriteTumTrajectory(estimate, JoinPath(context.out_dir, "trajectory.txt")));
  result.outputs.push_back("trajectory.txt");
  if (!processor.map().empty()) {
    SIGHTLINE_RETURN_IF_ERROR(processor.map().SaveRos(context.out_dir, "map"));
    SIGHTLINE_RETURN_IF_ERROR(
        processor.map().SavePng(JoinPath(context.out_dir, "map.png"), processor.trajectory()));
    result.outputs.insert(result.outputs.end(), {"map.pgm", "map.yaml", "map.png"});
  } else {
    log_lines.push_back("map: empty (no frame saw floor or walls); map.pgm not written");
  }

  // Counts.
  result.counts.emplace_back("resets", static_cast<double>(processor.reset_log().size()));
  result.counts.emplace_back("scan_points_per_frame",
                             static_cast<double>(scan_points) / result.frames);
  result.counts.emplace_back("lines_per_frame", static_cast<double>(line_count) / result.frames);
  for (const auto& [status, count] : statuses) {
    std::string key = "frames_" + status;
    std::replace(key.begin(), key.end(), ' ', '_');
    std::replace(key.begin(), key.end(), ':', '_');
    result.counts.emplace_back(key, count);
  }
  result.counts.emplace_back("camera_height_m", floor.plane.CameraHeightM());

  // Accuracy against ground truth.
  const Trajectory* gt = source.ground_truth();
  if (gt != nullptr && !gt->empty()) {
    std::vector<double> est_heading, true_heading;
    std::vector<Eigen::Vector2d> est_positions, true_positions;
    std::vector<std::optional<Eigen::Isometry3d>> truth_of_frame(frame_lines.size());
    for (size_t k = 0; k < frame_lines.size(); ++k) {
      auto i = gt->Nearest(frame_lines[k].time_s, run.gt_tolerance_s);
      if (!i) continue;
      const Eigen::Isometry3d& world_from_camera = gt->poses()[*i].world_from_sensor;
      truth_of_frame[k] = world_from_camera;
      const Pose2d true_base = Pose2d::FromIsometry(world_from_camera * camera_from_base);
      est_heading.push_back(processor.trajectory()[k].heading_rad);
      true_heading.push_back(true_base.heading_rad);
      est_positions.push_back(processor.trajectory()[k].position());
      true_positions.push_back(true_base.position());
    }
    if (!est_heading.empty()) {
      const HeadingErrors heading = ComputeHeadingErrors(est_heading, true_heading);
      result.accuracy.emplace_back("heading_error_deg_mean", heading.mean_deg);
      result.accuracy.emplace_back("heading_error_deg_max", heading.max_deg);
      result.accuracy.emplace_back("heading_error_deg_final", heading.final_deg);
    }
    EvaluationOptions eval_options;
    eval_options.max_time_difference_s = run.gt_tolerance_s;
    StatusOr<TrajectoryErrors> errors = EvaluateTrajectory(estimate, *gt, eval_options);
    if (errors.ok()) {
      result.accuracy.emplace_back("ate_rmse_m", errors->ate.rmse);
    } else {
      log_lines.push_back("ate_rmse_m not computed: " + errors.status().message());
    }
    if (walls && !walls->empty()) {
      std::vector<double> angle_errors;
      int visible = 0, found = 0;
      const double max_range =
          std::min(4.5, options.occupancy.height_cells * options.occupancy.cell_size_m);
      for (size_t k = 0; k < frame_lines.size(); ++k) {
        if (!truth_of_frame[k]) continue;
        const Eigen::Isometry3d world_from_base = *truth_of_frame[k] * camera_from_base;
        std::vector<int> matched;
        for (const WallSegment& line : frame_lines[k].lines) {
          const Eigen::Vector3d a =
              world_from_base * Eigen::Vector3d(line.start.x(), line.start.y(), 0);
          const Eigen::Vector3d b =
              world_from_base * Eigen::Vector3d(line.end.x(), line.end.y(), 0);
          auto match = MatchSegmentToWalls(a.head<2>(), b.head<2>(), *walls);
          if (!match) continue;
          angle_errors.push_back(match->angle_error_deg);
          matched.push_back(match->wall_index);
        }
        const FrameLines& f = frame_lines[k];
        for (const WallVisibility& v :
             VisibleWalls(Pose2d::FromIsometry(world_from_base), f.fov_min_rad, f.fov_max_rad,
                          f.resolution_rad, max_range, *walls)) {
          if (v.visible_length_m < run.visible_wall_min_length_m ||
              v.rays < run.visible_wall_min_fraction * f.rays) {
            continue;
          }
          ++visible;
          found += std::find(matched.begin(), matched.end(), v.wall_index) != matched.end();
        }
      }
      if (!angle_errors.empty()) {
        result.accuracy.emplace_back("wall_angle_error_deg_median", Median(angle_errors));
        result.counts.emplace_back("lines_matched_to_walls",
                                   static_cast<double>(angle_errors.size()));
      }
      if (visible > 0) {
        result.accuracy.emplace_back("wall_recall", static_cast<double>(found) / visible);
        result.counts.emplace_back("visible_walls", visible);
      }
      if (!processor.map().empty() && est_positions.size() >= 2) {
        const Pose2d truth_from_estimate = AlignSe2(est_positions, true_positions);
        const MapAgreement agreement = CompareMapWithWalls(
            processor.map(), *walls, truth_from_estimate, run.map_tolerance_cells);
        result.accuracy.emplace_back("map_iou", agreement.iou);
        result.accuracy.emplace_back("map_precision", agreement.precision);
        result.accuracy.emplace_back("map_recall", agreement.recall);
      }
    }
  }

  // The log: setup, degenerate frames, resets.
  const std::string log_path = JoinPath(context.out_dir, "mapping_log.txt");
  std::ofstream log(log_path);
  if (!log) return NotFound("cannot write " + log_path);
  for (const std::string& line : log_lines) log << line << "\n";
  log << processor.reset_log().size() << " reset(s)\n";
  for (const auto& [status, count] : statuses) log << count << " frame(s): " << status << "\n";
  if (!log) return Unavailable("write to " + log_path + " failed (disk full?)");
  result.outputs.push_back("mapping_log.txt");
  return result;
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
    StatusOr<PinholeCamera> c = SourceCamera(source);
    if (!c.ok()) return c.status();
    camera = *c;
  } else if (source.info().kind != SourceKind::kCloud) {
    return InvalidArgument(path + " is a " + SourceKindName(source.info().kind) +
                           " dataset; the floor needs depth (RGB-D) or point clouds");
  }
  std::vector<Eigen::Vector3f> points;
  int read = 0;
  while (read < frames) {
    Status grabbed = source.Grab();
    if (grabbed.code() == StatusCode::kOutOfRange) break;
    if (!grabbed.ok()) return grabbed;
    StatusOr<Frame> frame = source.Retrieve();
    if (!frame.ok()) return frame.status();
    if (const auto* rgbd = std::get_if<RgbdFrame>(&*frame)) {
      AppendDepthPoints(rgbd->depth_m, *camera, options.max_depth_m, 2, &points);
    } else if (const auto* cloud = std::get_if<CloudFrame>(&*frame)) {
      if (cloud->cloud)
        points.insert(points.end(), cloud->cloud->points.begin(), cloud->cloud->points.end());
    }
    ++read;
  }
  if (used_frames != nullptr) *used_frames = read;
  if (read == 0) return OutOfRange(path + " holds no frames");
  return FloorPlaneEstimator(options).Fit(points);
}

PipelineInfo MappingPipeline() {
  PipelineInfo info;
  info.name = "mapping";
  info.summary = "indoor Manhattan mapping from a Kinect: walls, heading, stitched map (seed 000)";
  info.declare_options = [](OptionSet* set) {
    SIGHTLINE_RETURN_IF_ERROR(set->Declare(MappingOptions::Describe()));
    return set->Declare(MappingRunOptions::Describe());
  };
  info.run = RunMapping;
  return info;
}

}  // namespace sightline
