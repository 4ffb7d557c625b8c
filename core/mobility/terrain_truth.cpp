#include "core/mobility/terrain_truth.h"

#include "core/common/text_file.h"

namespace sightline {

StatusOr<std::vector<TrueRegion>> ReadTerrainRegions(const std::string& path) {
  StatusOr<std::vector<DataLine>> lines = ReadDataLines(path);
  if (!lines.ok()) return lines.status();
  std::vector<TrueRegion> regions;
  for (const DataLine& line : *lines) {
    std::vector<std::string> fields;
    std::string field;
    for (char c : line.text) {
      if (c == ',') {
        fields.push_back(field);
        field.clear();
      } else {
        field += c;
      }
    }
    fields.push_back(field);
    const std::string where = path + ":" + std::to_string(line.number);
    if (fields.size() != 6) return ParseError(where + ": expected 6 comma-separated fields");
    TrueRegion r;
    try {
      r.id = std::stoi(fields[0]);
      r.kind = fields[1];
      r.slope_deg = std::stod(fields[2]);
      r.roughness = std::stod(fields[3]);
      r.height_m = std::stod(fields[4]);
    } catch (const std::exception&) {
      return ParseError(where + ": region, slope, roughness and height must be numbers");
    }
    const std::vector<std::string> xy = SplitFields(fields[5]);
    if (xy.size() < 6 || xy.size() % 2 != 0) return ParseError(where + ": polygon needs x y pairs");
    for (size_t k = 0; k < xy.size(); k += 2) {
      try {
        r.polygon.emplace_back(std::stod(xy[k]), std::stod(xy[k + 1]));
      } catch (const std::exception&) {
        return ParseError(where + ": polygon coordinate is not a number");
      }
    }
    regions.push_back(std::move(r));
  }
  return regions;
}

bool InsidePolygon(const std::vector<Eigen::Vector2d>& polygon, const Eigen::Vector2d& p) {
  bool inside = false;
  for (size_t i = 0, j = polygon.size() - 1; i < polygon.size(); j = i++) {
    const Eigen::Vector2d& a = polygon[i];
    const Eigen::Vector2d& b = polygon[j];
    if ((a.y() > p.y()) != (b.y() > p.y()) &&
        p.x() < (b.x() - a.x()) * (p.y() - a.y()) / (b.y() - a.y()) + a.x()) {
      inside = !inside;
    }
  }
  return inside;
}

std::vector<SegmentMatch> MatchSegmentsToRegions(const MobilityResult& result,
                                                 const Eigen::Isometry3d& world_from_camera,
                                                 const std::vector<TrueRegion>& regions) {
  const size_t segments = result.segments.size();
  std::vector<std::vector<int>> votes(segments, std::vector<int>(regions.size() + 1, 0));
  std::vector<int> totals(segments, 0);
  for (size_t i = 0; i < result.points.size(); ++i) {
    const int s = result.segment[i];
    if (s < 0) continue;
    const Eigen::Vector3d w = world_from_camera * result.points[i].cast<double>();
    ++totals[s];
    // Raised regions first (they lie on the floor's footprint), the floor last.
    int found = static_cast<int>(regions.size());
    for (size_t r = 0; r < regions.size(); ++r) {
      const TrueRegion& region = regions[r];
      if (region.kind == "floor") continue;
      const bool raised_kind = region.kind != "wall" && region.kind != "ramp";
      if (raised_kind && w.z() < 0.01) continue;
      if (InsidePolygon(region.polygon, w.head<2>())) {
        found = static_cast<int>(r);
        break;
      }
    }
    if (found == static_cast<int>(regions.size())) {
      for (size_t r = 0; r < regions.size(); ++r) {
        if (regions[r].kind == "floor" && std::abs(w.z()) < 0.05 &&
            InsidePolygon(regions[r].polygon, w.head<2>())) {
          found = static_cast<int>(r);
          break;
        }
      }
    }
    ++votes[s][found];
  }
  std::vector<SegmentMatch> matches;
  for (size_t s = 0; s < segments; ++s) {
    SegmentMatch m;
    m.segment = static_cast<int>(s);
    int best = 0;
    for (size_t r = 0; r < regions.size(); ++r) {
      if (votes[s][r] > best) best = votes[s][r], m.region = static_cast<int>(r);
    }
    m.fraction = totals[s] > 0 ? static_cast<double>(best) / totals[s] : 0;
    matches.push_back(m);
  }
  return matches;
}

}  // namespace sightline
