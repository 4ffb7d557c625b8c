#include "core/pipeline/mobility_outputs.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <opencv2/imgcodecs.hpp>

#include "core/common/text_file.h"
#include "core/mobility/mobility_map.h"
#include "core/pipeline/mobility_run.h"

namespace sightline {

Status WriteScoredCloud(const MobilityResult& result, const std::string& format,
                        const std::string& path) {
  std::ofstream out(path);
  if (!out) return NotFound("cannot write " + path);
  const size_t n = result.points.size();
  if (format == "ply") {
    out << "ply\nformat ascii 1.0\ncomment Sightline mobility map\nelement vertex " << n
        << "\nproperty float x\nproperty float y\nproperty float z\nproperty uchar red\n"
           "property uchar green\nproperty uchar blue\nproperty float score\nproperty int segment\n"
           "end_header\n";
  } else {
    out << "# .PCD v0.7 - Sightline mobility map\nVERSION 0.7\nFIELDS x y z rgb score segment\n"
           "SIZE 4 4 4 4 4 4\nTYPE F F F U F I\nCOUNT 1 1 1 1 1 1\nWIDTH "
        << n << "\nHEIGHT 1\nVIEWPOINT 0 0 0 1 0 0 0\nPOINTS " << n << "\nDATA ascii\n";
  }
  char line[160];
  for (size_t i = 0; i < n; ++i) {
    const Eigen::Vector3f& p = result.points[i];
    const float score = result.PointScore(i);
    const cv::Vec3b bgr = ScoreColorBgr(score);
    if (format == "ply") {
      std::snprintf(line, sizeof(line), "%.4f %.4f %.4f %d %d %d %.4f %d\n", p.x(), p.y(), p.z(),
                    bgr[2], bgr[1], bgr[0], std::isfinite(score) ? score : -1.f, result.segment[i]);
    } else {
      const unsigned rgb =
          (static_cast<unsigned>(bgr[2]) << 16) | (static_cast<unsigned>(bgr[1]) << 8) | bgr[0];
      std::snprintf(line, sizeof(line), "%.4f %.4f %.4f %u %s %d\n", p.x(), p.y(), p.z(), rgb,
                    std::isfinite(score) ? std::to_string(score).c_str() : "nan",
                    result.segment[i]);
    }
    out << line;
  }
  out.flush();
  if (!out) return Unavailable("write to " + path + " failed (disk full?)");
  return Status::Ok();
}

std::string SegmentsCsvHeader() {
  return "frame,segment,is_ground,points,slope_deg,roughness,area_m2,height_m,score_rule,"
         "score_gpr\n";
}

std::string SegmentsCsvRows(int64_t frame, const MobilityResult& result) {
  std::string rows;
  char line[256];
  for (size_t s = 0; s < result.segments.size(); ++s) {
    const SegmentProperties& p = result.segments[s];
    std::snprintf(line, sizeof(line), "%lld,%zu,%d,%d,%.3f,%.4f,%.4f,%.4f,%.4f,%.4f\n",
                  static_cast<long long>(frame), s, p.is_ground ? 1 : 0, p.points, p.slope_deg,
                  p.roughness, p.area_m2, p.height_m, p.score_rule, p.score_gpr);
    rows += line;
  }
  return rows;
}

namespace {

double Median(std::vector<double> v) {
  if (v.empty()) return std::nan("");
  std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
  return v[v.size() / 2];
}

// The cloud and images of frame `index`, named NNNNNN_cloud.pcd and so on.
Status WriteFrameFiles(int64_t index, const MobilityResult& r, const MobilityRunOptions& run,
                       const std::string& out_dir, std::vector<std::string>* outputs) {
  char name[64];
  if (run.cloud_format != "none" && !r.points.empty()) {
    std::snprintf(name, sizeof(name), "%06lld_cloud.%s", static_cast<long long>(index),
                  run.cloud_format.c_str());
    SIGHTLINE_RETURN_IF_ERROR(WriteScoredCloud(r, run.cloud_format, JoinPath(out_dir, name)));
    outputs->push_back(name);
  }
  if (run.write_images && !r.projection.empty()) {
    std::snprintf(name, sizeof(name), "%06lld_projection.png", static_cast<long long>(index));
    if (!cv::imwrite(JoinPath(out_dir, name), r.projection)) {
      return Unavailable("cannot write " + JoinPath(out_dir, name));
    }
    outputs->push_back(name);
  }
  if (run.write_images && r.ground.found) {
    std::snprintf(name, sizeof(name), "%06lld_topview.png", static_cast<long long>(index));
    if (!cv::imwrite(JoinPath(out_dir, name), RenderTopView(r.map))) {
      return Unavailable("cannot write " + JoinPath(out_dir, name));
    }
    outputs->push_back(name);
  }
  return Status::Ok();
}

Status WriteTextFile(const std::string& path, const std::string& text) {
  std::ofstream out(path);
  if (!out) return NotFound("cannot write " + path);
  out << text;
  out.flush();
  if (!out) return Unavailable("write to " + path + " failed (disk full?)");
  return Status::Ok();
}

// Accuracy and counts from the frames' statistics and the terrain's truth.
void AddFigures(const MobilityRunRecord& record, RunResult* result, std::vector<std::string>* log) {
  const std::vector<double> heights = record.stats.Values("mobility/ground_height_m");
  if (!heights.empty()) result->accuracy.emplace_back("ground_height_m", Median(heights));
  const MobilityTerrainAccuracy& terrain = record.terrain;
  if (terrain.slopes > 0) {
    result->accuracy.emplace_back("slope_error_deg_max", terrain.slope_error_max);
    log->push_back("largest slope error: " + terrain.worst);
  }
  if (!terrain.flat_roughness.empty()) {
    result->accuracy.emplace_back("flat_roughness", Median(terrain.flat_roughness));
  }
  std::vector<std::string> stages = MobilityStages();
  std::sort(stages.begin(), stages.end());
  for (const std::string& stage : stages) {
    const std::vector<double> points = record.stats.Values("mobility/" + stage + "_points");
    if (!points.empty()) result->counts.emplace_back("points_" + stage, Median(points));
  }
  result->counts.emplace_back("frames_without_map", record.failed);
  result->counts.emplace_back("frames_with_ground", static_cast<double>(heights.size()));
}

}  // namespace

StatusOr<RunResult> FinishMobilityRun(const MobilityRunRecord& record,
                                      const MobilityRunOptions& run, const std::string& out_dir) {
  RunResult result;
  result.frames = record.frames;
  for (size_t index = 0; index < record.kept.size(); ++index) {
    if (record.kept[index] == nullptr) continue;
    SIGHTLINE_RETURN_IF_ERROR(WriteFrameFiles(static_cast<int64_t>(index), *record.kept[index], run,
                                              out_dir, &result.outputs));
  }
  SIGHTLINE_RETURN_IF_ERROR(
      WriteTextFile(JoinPath(out_dir, "segments.csv"), SegmentsCsvHeader() + record.segments_csv));
  result.outputs.push_back("segments.csv");
  std::vector<std::string> log = record.log;
  AddFigures(record, &result, &log);
  if (record.frames > 0 && record.stats.Values("mobility/ground_height_m").empty()) {
    result.nothing_achieved = "no ground found in any of the " + std::to_string(record.frames) +
                              " frame(s) (" + (record.log.empty() ? "" : record.log.front()) +
                              "): nothing is mapped relative to a ground";
    log.insert(log.begin(), result.nothing_achieved);
  }
  std::string log_text;
  for (const std::string& line : log) log_text += line + "\n";
  SIGHTLINE_RETURN_IF_ERROR(WriteTextFile(JoinPath(out_dir, "mobility_log.txt"), log_text));
  result.outputs.push_back("mobility_log.txt");
  return result;
}

}  // namespace sightline
