// button.csv and the simulator's true buttons for the `button` pipeline.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>

#include "core/common/text_file.h"
#include "core/pipeline/button_pipeline.h"

namespace sightline {

StatusOr<std::vector<TrueButton>> ReadTrueButtons(const std::string& path) {
  if (!FileExists(path)) return NotFound("true buttons '" + path + "' not found");
  StatusOr<std::vector<DataLine>> lines = ReadDataLines(path);
  if (!lines.ok()) return lines.status();
  std::map<int, TrueButton> buttons;
  for (const DataLine& line : *lines) {
    const std::vector<std::string> f = SplitFields(line.text);
    if (f.size() < 8) {
      return ParseError(path + ":" + std::to_string(line.number) +
                        ": expected frame,button,u,v,x,y,z,visible");
    }
    double v[8];
    for (int i = 0; i < 8; ++i) {
      char* end = nullptr;
      v[i] = std::strtod(f[i].c_str(), &end);
      if (end == f[i].c_str()) {
        return ParseError(path + ":" + std::to_string(line.number) + ": field " +
                          std::to_string(i + 1) + " is not a number");
      }
    }
    if (v[0] < 0 || v[0] > 1e7)
      return ParseError(path + ":" + std::to_string(line.number) + ": bad frame");
    const size_t frame = static_cast<size_t>(v[0]);
    TrueButton& b = buttons[static_cast<int>(v[1])];
    b.id = static_cast<int>(v[1]);
    b.center_in_world = {v[4], v[5], v[6]};
    if (b.pixel.size() <= frame) {
      b.pixel.resize(frame + 1, Eigen::Vector2d::Constant(std::nan("")));
      b.visible.resize(frame + 1, false);
    }
    b.pixel[frame] = {v[2], v[3]};
    b.visible[frame] = v[7] != 0 && std::isfinite(v[2]) && std::isfinite(v[3]);
  }
  std::vector<TrueButton> out;
  out.reserve(buttons.size());
  for (auto& [id, b] : buttons) out.push_back(std::move(b));
  return out;
}

namespace {

// The tracked radius from the tap's own keypoints; NaN when unknown.
double AnchorRadiusPx(const ButtonTrack& t) {
  if (!t.found || !(t.scale > 0) || !(t.anchor_scale > 0)) return std::nan("");
  return t.radius_px / t.scale * t.anchor_scale;
}

// The three numbers of "[a, b, c]" after `key` in `text`; nullopt when absent or malformed.
std::optional<Eigen::Vector3d> YamlVector(const std::string& text, const std::string& key) {
  const size_t at = text.find(key + ": [");
  if (at == std::string::npos) return std::nullopt;
  Eigen::Vector3d v;
  const char* s = text.c_str() + at + key.size() + 3;
  for (int i = 0; i < 3; ++i) {
    char* end = nullptr;
    v[i] = std::strtod(s, &end);
    if (end == s || *end != (i < 2 ? ',' : ']')) return std::nullopt;
    s = end + 1;
  }
  if (!v.allFinite()) return std::nullopt;
  return v;
}

}  // namespace

Status AddTrueButtonNormals(const std::string& scene_yaml, std::vector<TrueButton>* buttons) {
  std::ifstream in(scene_yaml);
  if (!in) return NotFound("scene file '" + scene_yaml + "' not found");
  std::string line;
  int number = 0;
  while (std::getline(in, line)) {
    ++number;
    const size_t at = line.find("- {id: ");
    if (at == std::string::npos || line.find("normal: ") == std::string::npos) continue;
    const int id = std::atoi(line.c_str() + at + 7);
    const std::optional<Eigen::Vector3d> normal = YamlVector(line, "normal");
    if (!normal || normal->norm() < 1e-9) {
      return ParseError(scene_yaml + ":" + std::to_string(number) + ": button " +
                        std::to_string(id) + " has no valid normal: [x, y, z]");
    }
    for (TrueButton& b : *buttons) {
      if (b.id == id) b.normal_in_world = normal->normalized();
    }
  }
  return Status::Ok();
}

Status WriteButtonCsv(const std::vector<ButtonRunRow>& rows, const std::string& path) {
  std::ofstream out(path);
  if (!out) return Unavailable("cannot write " + path);
  // anchor_radius_px: the radius from the tap's own keypoints (ButtonTrack::anchor_scale); the
  // host timings stay the last columns.
  // *_m: metres (empty as nan without a metric scale); *_map_units: the SLAM's map frame,
  // unscaled (metric_scale = 0: tracking only, no arm motion). approach_*: the push direction
  // in the arm's base frame and its 1-sigma (nan before the first panel normal).
  out << "frame,time_s,state,gate,u_px,v_px,radius_px,confidence,cam_x_m,cam_y_m,cam_z_m,"
         "base_x_m,base_y_m,base_z_m,uncertainty_m,plane_sound,target_sent,slam_tracking,"
         "scale_converged,scale_ml,metric_scale,button_x_map_units,button_y_map_units,"
         "button_z_map_units,camera_x_map_units,camera_y_map_units,camera_z_map_units,"
         "anchor_radius_px,approach_x,approach_y,approach_z,approach_sigma_deg,tracking_ms,"
         "slam_ms\n";
  const double nan = std::nan("");
  char line[768];
  for (const ButtonRunRow& r : rows) {
    const PickerFrame& p = r.picker;
    const bool found = p.track.found;
    const Eigen::Vector3d cam =
        p.location && r.metric ? p.location->button_in_camera : Eigen::Vector3d::Constant(nan);
    const Eigen::Vector3d base = r.metric ? p.button_in_base : Eigen::Vector3d::Constant(nan);
    const double uncertainty = p.location && r.metric ? p.location->uncertainty_m : nan;
    const bool has_approach = r.metric && p.approach_in_base.allFinite();
    const Eigen::Vector3d approach =
        has_approach ? p.approach_in_base : Eigen::Vector3d::Constant(nan);
    const double approach_sigma = has_approach ? p.approach_sigma_deg : nan;
    const Eigen::Vector3d& b = r.button_in_map;
    const Eigen::Vector3d& c = r.camera_in_map;
    std::snprintf(line, sizeof(line),
                  "%lld,%.6f,%s,%s,%.2f,%.2f,%.2f,%.3f,%.5f,%.5f,%.5f,%.5f,%.5f,%.5f,%.5f,%d,%d,%d,"
                  "%d,%.6g,%d,"
                  "%.6f,%.6f,%.6f,%.6f,%.6f,%.6f,%.4f,%.6f,%.6f,%.6f,%.3f,%.3f,%.3f\n",
                  static_cast<long long>(p.frame_id), p.stamp_s, PickerStateKey(p.state),
                  GateReasonKey(p.verdict.reason), found ? p.track.center.x : nan,
                  found ? p.track.center.y : nan, found ? p.track.radius_px : nan,
                  p.track.confidence, cam.x(), cam.y(), cam.z(), base.x(), base.y(), base.z(),
                  uncertainty, p.location && p.location->plane_sound ? 1 : 0, p.target ? 1 : 0,
                  r.slam_tracking ? 1 : 0, r.scale_converged ? 1 : 0, r.lambda_ml, r.metric ? 1 : 0,
                  b.x(), b.y(), b.z(), c.x(), c.y(), c.z(), AnchorRadiusPx(p.track), approach.x(),
                  approach.y(), approach.z(), approach_sigma, p.tracking_ms, r.slam_ms);
    out << line;
  }
  out.flush();
  if (!out) return Unavailable("write to " + path + " failed (disk full?)");
  return Status::Ok();
}

}  // namespace sightline
