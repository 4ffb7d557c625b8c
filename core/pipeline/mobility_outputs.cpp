#include "core/pipeline/mobility_outputs.h"

#include <cmath>
#include <cstdio>
#include <fstream>

#include "core/mobility/mobility_map.h"

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

}  // namespace sightline
