#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/pipeline/mono_slam_pipeline.h"

namespace sightline {

namespace fs = std::filesystem;

namespace {

Status WriteFile(const std::string& path, const std::string& text) {
  std::ofstream out(path);
  if (!out) return Unavailable("cannot write " + path);
  out << text;
  out.flush();
  if (!out) return Unavailable("write to " + path + " failed (disk full?)");
  return Status::Ok();
}

// A colour per keyframe (golden-angle hues), so points show which keyframe made them.
Eigen::Vector3i KeyFrameColour(int64_t keyframe) {
  const double h = std::fmod(keyframe * 137.508, 360.0) / 60.0;
  const double x = 1 - std::abs(std::fmod(h, 2.0) - 1);
  double r = 0, g = 0, b = 0;
  switch (static_cast<int>(h)) {
    case 0:
      r = 1;
      g = x;
      break;
    case 1:
      r = x;
      g = 1;
      break;
    case 2:
      g = 1;
      b = x;
      break;
    case 3:
      g = x;
      b = 1;
      break;
    case 4:
      r = x;
      b = 1;
      break;
    default:
      r = 1;
      b = x;
      break;
  }
  return Eigen::Vector3i(static_cast<int>(55 + 200 * r), static_cast<int>(55 + 200 * g),
                         static_cast<int>(55 + 200 * b));
}

}  // namespace

Status WriteMonoSlamOutputs(const MonoSlamRun& run, const std::string& dir, RunResult* result) {
  const double divide = run.lambda() > 0 ? run.lambda() : 1.0;
  SIGHTLINE_RETURN_IF_ERROR(
      WriteTumTrajectory(run.MetricEstimate(), (fs::path(dir) / "trajectory.txt").string()));
  SIGHTLINE_RETURN_IF_ERROR(
      WriteTumTrajectory(run.estimate, (fs::path(dir) / "trajectory_map.txt").string()));
  std::ostringstream ply;
  ply << "ply\nformat ascii 1.0\ncomment Sightline mono-slam map points ("
      << (run.lambda() > 0 ? "metres" : "map units") << "), coloured by creating keyframe\n"
      << "element vertex " << run.map->points.size()
      << "\nproperty float x\nproperty float y\nproperty float z\n"
         "property uchar red\nproperty uchar green\nproperty uchar blue\nend_header\n";
  for (const MapSnapshot::Point& p : run.map->points) {
    const Eigen::Vector3d x = p.position / divide;
    const Eigen::Vector3i c = KeyFrameColour(p.first_keyframe);
    ply << x.x() << ' ' << x.y() << ' ' << x.z() << ' ' << c.x() << ' ' << c.y() << ' ' << c.z()
        << '\n';
  }
  SIGHTLINE_RETURN_IF_ERROR(WriteFile((fs::path(dir) / "map.ply").string(), ply.str()));
  std::ostringstream kf;
  kf << "# keyframe frame timestamp tx ty tz qx qy qz qw points  (map_from_camera, "
     << (run.lambda() > 0 ? "metres" : "map units") << ")\n";
  for (const MapSnapshot::Frame& k : run.map->keyframes) {
    const Eigen::Vector3d t = k.map_from_camera.translation() / divide;
    const Eigen::Quaterniond q(k.map_from_camera.rotation());
    char line[256];
    std::snprintf(line, sizeof(line), "%lld %lld %.6f %.6f %.6f %.6f %.6f %.6f %.6f %.6f %d\n",
                  static_cast<long long>(k.id), static_cast<long long>(k.frame_index), k.time_s,
                  t.x(), t.y(), t.z(), q.x(), q.y(), q.z(), q.w(), k.points);
    kf << line;
  }
  SIGHTLINE_RETURN_IF_ERROR(WriteFile((fs::path(dir) / "keyframes.txt").string(), kf.str()));
  std::ostringstream scale;
  scale << "sample,single_ratio,ml_estimate,pair_ratio,pairs_used\n";
  for (const ScaleSample& s : run.scale.history()) {
    scale << s.index << ',' << s.single_ratio << ',' << s.max_likelihood << ',' << s.pair_ratio
          << ',' << s.pairs_used << '\n';
  }
  SIGHTLINE_RETURN_IF_ERROR(WriteFile((fs::path(dir) / "scale.csv").string(), scale.str()));
  std::ostringstream frames;
  frames << "frame,time_s,quality,tracked,keypoints,predicted,matches,inliers,rms_px,map_points,"
            "keyframes,"
            "new_keyframe,relocalised,tracking_ms,status\n";
  for (const MonoRunFrame& f : run.frames) {
    std::string status = f.stats.status;
    for (char& c : status) {
      if (c == '"' || c == ',') c = ';';
    }
    frames << f.frame << ',' << f.time_s << ',' << TrackingQualityName(f.quality) << ','
           << f.tracked << ',' << f.stats.keypoints << ',' << f.stats.predicted << ','
           << f.stats.matches << ',' << f.stats.inliers << ',' << f.stats.rms_px << ','
           << f.stats.map_points << ',' << f.stats.keyframes << ',' << f.stats.new_keyframe << ','
           << f.stats.relocalised << ',' << f.stats.tracking_ms << ",\"" << status << "\"\n";
  }
  SIGHTLINE_RETURN_IF_ERROR(WriteFile((fs::path(dir) / "frames.csv").string(), frames.str()));
  result->outputs = {"trajectory.txt", "trajectory_map.txt", "map.ply",
                     "keyframes.txt",  "scale.csv",          "frames.csv"};
  return Status::Ok();
}
}  // namespace sightline
