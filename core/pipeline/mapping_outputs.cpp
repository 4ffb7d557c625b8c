// The files and figures of a mapping run (MappingPipeline::Finish): floor.yaml, lines.csv,
// trajectory.txt, the map, mapping_log.txt, counts and the accuracy against ground truth.
#include <algorithm>
#include <cmath>
#include <fstream>
#include <optional>

#include "core/common/text_file.h"
#include "core/eval/evaluation.h"
#include "core/io/floor_file.h"
#include "core/mapping/mapping_accuracy.h"
#include "core/pipeline/mapping_run.h"

namespace sightline {

namespace {

double Median(std::vector<double> v) {
  if (v.empty()) return 0;
  std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
  return v[v.size() / 2];
}

// What a finished run is measured from.
struct MappingRunView {
  const MappingPipeline::State& state;
  const MappingFrameProcessor& chain;
  const MappingRunRecord& record;
  Eigen::Isometry3d camera_from_base;
  Trajectory estimate;  // Camera poses (TUM).
};

Status WriteLinesCsv(const MappingRunRecord& record, const std::string& path) {
  std::ofstream csv(path);
  if (!csv) return NotFound("cannot write " + path);
  csv << "# frame,time_s,line,x1_m,y1_m,x2_m,y2_m,angle_deg,inliers,length_m,"
         "direction_class  (end points in the robot base frame: x forward, y left; "
         "angle from forward; direction_class 0/1 = Manhattan axes of the reference, -1 = "
         "neither)\n"
      << record.lines_csv;
  csv.flush();
  if (!csv) return Unavailable("write to " + path + " failed (disk full?)");
  return Status::Ok();
}

// trajectory.txt and the map (map.pgm, map.yaml, map.png).
Status WriteTrajectoryAndMap(const MappingRunView& run, const std::string& out_dir,
                             RunResult* result, std::vector<std::string>* log) {
  SIGHTLINE_RETURN_IF_ERROR(WriteTumTrajectory(run.estimate, JoinPath(out_dir, "trajectory.txt")));
  result->outputs.push_back("trajectory.txt");
  const OccupancyGridMap& map = run.chain.map();
  if (map.empty()) {
    log->push_back("map: empty (no frame saw floor or walls); map.pgm not written");
    return Status::Ok();
  }
  SIGHTLINE_RETURN_IF_ERROR(map.SaveRos(out_dir, "map"));
  SIGHTLINE_RETURN_IF_ERROR(map.SavePng(JoinPath(out_dir, "map.png"), run.chain.trajectory()));
  result->outputs.insert(result->outputs.end(), {"map.pgm", "map.yaml", "map.png"});
  return Status::Ok();
}

void AddCounts(const MappingRunView& run, RunResult* result) {
  const double frames = static_cast<double>(run.record.frames.size());
  result->counts.emplace_back("resets", static_cast<double>(run.chain.reset_log().size()));
  result->counts.emplace_back("scan_points_per_frame",
                              run.record.stats.Sum("mapping/scan_points") / frames);
  result->counts.emplace_back("lines_per_frame", run.record.stats.Sum("mapping/lines") / frames);
  for (const auto& [status, count] : run.record.statuses) {
    std::string key = "frames_" + status;
    std::replace(key.begin(), key.end(), ' ', '_');
    std::replace(key.begin(), key.end(), ':', '_');
    result->counts.emplace_back(key, count);
  }
  result->counts.emplace_back("camera_height_m", run.state.floor->plane.CameraHeightM());
}

// Which pose source moved the robot, in how many frames, and how often the RGB-D odometry
// failed: a log line ("pose source used: rgbd in 500 frame(s), 0 failed odometry step(s)
// (mapping.pose.source=auto)"), a note for metrics.json and the CLI, and counts.
void AddPoseSource(const MappingRunView& run, RunResult* result, std::vector<std::string>* log) {
  const std::string asked = "(mapping.pose.source=" + run.state.options.pose_source + ")";
  for (const auto& [source, frames] : run.record.pose_sources) {
    std::string line =
        "pose source used: " + source + " in " + std::to_string(frames) + " frame(s)";
    if (source == "rgbd") {
      line += ", " + std::to_string(run.chain.odometry_failures()) + " failed odometry step(s)";
    }
    log->push_back(line + " " + asked);
    result->notes.push_back(line + " " + asked);
    result->counts.emplace_back("frames_pose_" + source, frames);
  }
  if (run.record.pose_sources.count("rgbd") > 0) {
    result->counts.emplace_back("odometry_failures", run.chain.odometry_failures());
  }
}

// The true camera pose of each mapped frame (nullopt without one).
std::vector<std::optional<Eigen::Isometry3d>> TruthOfFrames(const MappingRunView& run,
                                                            const Trajectory& gt) {
  std::vector<std::optional<Eigen::Isometry3d>> truth(run.record.frames.size());
  for (size_t k = 0; k < truth.size(); ++k) {
    auto i = gt.Nearest(run.record.frames[k].time_s, run.state.run.gt_tolerance_s);
    if (i) truth[k] = gt.poses()[*i].world_from_sensor;
  }
  return truth;
}

// Heading errors and the ATE against the ground truth.
void AddTrajectoryAccuracy(const MappingRunView& run, const Trajectory& gt,
                           const std::vector<std::optional<Eigen::Isometry3d>>& truth,
                           RunResult* result, std::vector<std::string>* log) {
  std::vector<double> est_heading, true_heading;
  for (size_t k = 0; k < truth.size(); ++k) {
    if (!truth[k]) continue;
    est_heading.push_back(run.chain.trajectory()[k].heading_rad);
    true_heading.push_back(Pose2d::FromIsometry(*truth[k] * run.camera_from_base).heading_rad);
  }
  if (!est_heading.empty()) {
    const HeadingErrors heading = ComputeHeadingErrors(est_heading, true_heading);
    result->accuracy.emplace_back("heading_error_deg_mean", heading.mean_deg);
    result->accuracy.emplace_back("heading_error_deg_max", heading.max_deg);
    result->accuracy.emplace_back("heading_error_deg_final", heading.final_deg);
  }
  EvaluationOptions eval_options;
  eval_options.max_time_difference_s = run.state.run.gt_tolerance_s;
  StatusOr<TrajectoryErrors> errors = EvaluateTrajectory(run.estimate, gt, eval_options);
  if (errors.ok()) {
    result->accuracy.emplace_back("ate_rmse_m", errors->ate.rmse);
  } else {
    log->push_back("ate_rmse_m not computed: " + errors.status().message());
  }
}

// Matches one frame's lines with the true walls: angle errors, and which walls were found.
void MatchFrameLines(const MappedFrameLines& frame, const Eigen::Isometry3d& world_from_base,
                     const std::vector<TrueWall>& walls, std::vector<double>* angle_errors,
                     std::vector<int>* matched) {
  for (const WallSegment& line : frame.lines) {
    const Eigen::Vector3d a = world_from_base * Eigen::Vector3d(line.start.x(), line.start.y(), 0);
    const Eigen::Vector3d b = world_from_base * Eigen::Vector3d(line.end.x(), line.end.y(), 0);
    auto match = MatchSegmentToWalls(a.head<2>(), b.head<2>(), walls);
    if (!match) continue;
    angle_errors->push_back(match->angle_error_deg);
    matched->push_back(match->wall_index);
  }
}

// Wall angle errors and the recall of the walls in view.
void AddWallAccuracy(const MappingRunView& run, const std::vector<TrueWall>& walls,
                     const std::vector<std::optional<Eigen::Isometry3d>>& truth,
                     RunResult* result) {
  const MappingOptions& options = run.state.options;
  const MappingRunOptions& opts = run.state.run;
  const double max_range =
      std::min(4.5, options.occupancy.height_cells * options.occupancy.cell_size_m);
  std::vector<double> angle_errors;
  int visible = 0, found = 0;
  for (size_t k = 0; k < truth.size(); ++k) {
    if (!truth[k]) continue;
    const Eigen::Isometry3d world_from_base = *truth[k] * run.camera_from_base;
    const MappedFrameLines& f = run.record.frames[k];
    std::vector<int> matched;
    MatchFrameLines(f, world_from_base, walls, &angle_errors, &matched);
    for (const WallVisibility& v :
         VisibleWalls(Pose2d::FromIsometry(world_from_base), f.fov_min_rad, f.fov_max_rad,
                      f.resolution_rad, max_range, walls)) {
      if (v.visible_length_m < opts.visible_wall_min_length_m ||
          v.rays < opts.visible_wall_min_fraction * f.rays) {
        continue;
      }
      ++visible;
      found += std::find(matched.begin(), matched.end(), v.wall_index) != matched.end();
    }
  }
  if (!angle_errors.empty()) {
    result->accuracy.emplace_back("wall_angle_error_deg_median", Median(angle_errors));
    result->counts.emplace_back("lines_matched_to_walls", static_cast<double>(angle_errors.size()));
  }
  if (visible > 0) {
    result->accuracy.emplace_back("wall_recall", static_cast<double>(found) / visible);
    result->counts.emplace_back("visible_walls", visible);
  }
}

// The map's agreement with the true walls, the estimate aligned to the truth.
void AddMapAccuracy(const MappingRunView& run, const std::vector<TrueWall>& walls,
                    const std::vector<std::optional<Eigen::Isometry3d>>& truth, RunResult* result) {
  std::vector<Eigen::Vector2d> est_positions, true_positions;
  for (size_t k = 0; k < truth.size(); ++k) {
    if (!truth[k]) continue;
    est_positions.push_back(run.chain.trajectory()[k].position());
    true_positions.push_back(Pose2d::FromIsometry(*truth[k] * run.camera_from_base).position());
  }
  if (run.chain.map().empty() || est_positions.size() < 2) return;
  const Pose2d truth_from_estimate = AlignSe2(est_positions, true_positions);
  const MapAgreement agreement = CompareMapWithWalls(run.chain.map(), walls, truth_from_estimate,
                                                     run.state.run.map_tolerance_cells);
  result->accuracy.emplace_back("map_iou", agreement.iou);
  result->accuracy.emplace_back("map_precision", agreement.precision);
  result->accuracy.emplace_back("map_recall", agreement.recall);
}

void AddAccuracy(const MappingRunView& run, RunResult* result, std::vector<std::string>* log) {
  const Trajectory* gt = run.state.source->ground_truth.get();
  if (gt == nullptr || gt->empty()) return;
  const std::vector<std::optional<Eigen::Isometry3d>> truth = TruthOfFrames(run, *gt);
  AddTrajectoryAccuracy(run, *gt, truth, result, log);
  const std::optional<std::vector<TrueWall>>& walls = run.state.recording.walls;
  if (!walls || walls->empty()) return;
  AddWallAccuracy(run, *walls, truth, result);
  AddMapAccuracy(run, *walls, truth, result);
}

// The log: setup, degenerate frames, resets.
Status WriteLog(const MappingRunView& run, const std::vector<std::string>& lines,
                const std::string& path) {
  std::ofstream log(path);
  if (!log) return NotFound("cannot write " + path);
  for (const std::string& line : lines) log << line << "\n";
  log << run.chain.reset_log().size() << " reset(s)\n";
  for (const auto& [status, count] : run.record.statuses) {
    log << count << " frame(s): " << status << "\n";
  }
  if (!log) return Unavailable("write to " + path + " failed (disk full?)");
  return Status::Ok();
}

// Why a run mapped nothing: no frame had a wall line (so no heading, no map). Empty otherwise.
std::string NoWallFound(const MappingRunRecord& record) {
  for (const MappedFrameLines& frame : record.frames) {
    if (!frame.lines.empty()) return "";
  }
  std::string statuses;
  for (const auto& [status, count] : record.statuses) {
    statuses += (statuses.empty() ? "" : ", ") + std::to_string(count) + " " + status;
  }
  return "no wall line found in any of the " + std::to_string(record.frames.size()) +
         " mapped frame(s)" + (statuses.empty() ? std::string() : " (" + statuses + ")");
}

}  // namespace

StatusOr<RunResult> FinishMappingRun(const MappingPipeline::State& state,
                                     const std::string& out_dir) {
  MappingRunView run{state, *state.chain, state.record, state.chain->base_from_camera().inverse(),
                     Trajectory()};
  for (size_t k = 0; k < run.chain.camera_trajectory().size(); ++k) {
    run.estimate.Add(run.chain.trajectory_times()[k], run.chain.camera_trajectory()[k]);
  }
  RunResult result;
  result.frames = static_cast<int64_t>(state.record.frames.size());
  std::vector<std::string> log = state.recording.log_lines;
  for (const auto& [source, counts] : state.record.people_sources) {
    log.push_back("person boxes used: " + source + " in " + std::to_string(counts.first) +
                  " frame(s), " + std::to_string(counts.second) +
                  " box(es) (mapping.people.source=" + state.options.people.source + ")");
  }
  AddPoseSource(run, &result, &log);
  log.push_back(state.floor_log);
  log.insert(log.end(), state.record.frame_log.begin(), state.record.frame_log.end());

  SIGHTLINE_RETURN_IF_ERROR(WriteFloorCalibration(*state.floor, JoinPath(out_dir, "floor.yaml")));
  result.outputs.push_back("floor.yaml");
  SIGHTLINE_RETURN_IF_ERROR(WriteLinesCsv(state.record, JoinPath(out_dir, "lines.csv")));
  result.outputs.push_back("lines.csv");
  SIGHTLINE_RETURN_IF_ERROR(WriteTrajectoryAndMap(run, out_dir, &result, &log));
  AddCounts(run, &result);
  AddAccuracy(run, &result, &log);
  result.nothing_achieved = NoWallFound(state.record);
  if (!result.nothing_achieved.empty()) log.insert(log.begin(), result.nothing_achieved);
  SIGHTLINE_RETURN_IF_ERROR(WriteLog(run, log, JoinPath(out_dir, "mapping_log.txt")));
  result.outputs.push_back("mapping_log.txt");
  return result;
}

StatusOr<RunResult> FinishFloorlessRun(const MappingPipeline::State& state,
                                       const std::string& out_dir) {
  RunResult result;
  result.frames = 0;
  result.nothing_achieved = "no floor found in any of the " +
                            std::to_string(state.floorless_frames) +
                            " frame(s), nothing mapped (last fit: " + state.floor_failure + ")";
  std::vector<std::string> log = state.recording.log_lines;
  log.insert(log.begin(), result.nothing_achieved);
  const std::string path = JoinPath(out_dir, "mapping_log.txt");
  std::ofstream file(path);
  for (const std::string& line : log) file << line << "\n";
  if (!file) return Unavailable("write to " + path + " failed (disk full?)");
  result.outputs.push_back("mapping_log.txt");
  result.counts.emplace_back("floorless_frames", static_cast<double>(state.floorless_frames));
  return result;
}

}  // namespace sightline
