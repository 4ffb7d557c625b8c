#include "core/sim/ground_truth_files.h"

#include <cmath>
#include <cstdio>

#include "core/common/text_file.h"
#include "core/io/hand_eye_file.h"
#include "core/options/option_spec.h"

namespace sightline::sim {
namespace {

std::string Num(double v, const char* format = "%.6f") {
  char text[64];
  std::snprintf(text, sizeof(text), format, v);
  return text;
}

Status Finish(std::ofstream& out, const std::string& path) {
  out.flush();
  if (!out) return Unavailable("write to " + path + " failed (disk full?)");
  return Status::Ok();
}

std::string Vec(const Eigen::Vector3d& v) {
  char text[128];
  std::snprintf(text, sizeof(text), "[%.9f, %.9f, %.9f]", v.x(), v.y(), v.z());
  return text;
}

// YAML scalar for a string option value: quoted when it could be misread.
std::string YamlValue(const OptionValue& value) {
  if (const auto* s = std::get_if<std::string>(&value)) return "\"" + *s + "\"";
  return FormatOptionValue(value);
}

}  // namespace

Status WriteWallsCsv(const Scene& scene, const std::string& path) {
  std::ofstream out(path);
  if (!out) return Unavailable("cannot write " + path);
  out << "# wall,x1,y1,x2,y2,a,b,c  (map frame, metres; a x + b y + c = 0 on the wall face, "
         "a^2 + b^2 = 1, (a, b) points into the free side)\n";
  for (const WallLine& w : scene.walls) {
    const Eigen::Vector3d l = w.Line();
    out << w.id << "," << Num(w.start.x()) << "," << Num(w.start.y()) << "," << Num(w.end.x())
        << "," << Num(w.end.y()) << "," << Num(l.x(), "%.9f") << "," << Num(l.y(), "%.9f") << ","
        << Num(l.z(), "%.9f") << "\n";
  }
  return Finish(out, path);
}

Status WriteRegionsCsv(const Scene& scene, const std::string& path) {
  std::ofstream out(path);
  if (!out) return Unavailable("cannot write " + path);
  out << "# region,kind,slope_deg,roughness,height_m,polygon  (polygon: footprint on the floor "
         "plan, \"x y x y ...\" in metres, map frame)\n";
  for (const TerrainRegion& r : scene.regions) {
    out << r.id << "," << r.kind << "," << Num(r.slope_deg) << "," << Num(r.roughness, "%.9f")
        << "," << Num(r.height_m) << ",";
    for (size_t i = 0; i < r.polygon.size(); ++i) {
      out << (i ? " " : "") << Num(r.polygon[i].x()) << " " << Num(r.polygon[i].y());
    }
    out << "\n";
  }
  return Finish(out, path);
}

Status WriteSceneYaml(const SimulationOptions& options, const Scene& scene,
                      const SceneRecord& record, const std::string& path) {
  std::ofstream out(path);
  if (!out) return Unavailable("cannot write " + path);
  out << "# Sightline simulated recording (see core/sim/README.md). The sim.* options under\n"
         "# `options`, given as --set key=value (or as a profile), reproduce it byte for byte\n"
         "# with the same build.\n";
  out << "scene: " << scene.name() << "\nseed: " << options.seed
      << "\nframes: " << record.frames_written << "\nrate_hz: " << options.rate_hz
      << "\nnoise: " << options.noise.profile << "\nmotion: " << record.motion << "\nsensors: [";
  for (size_t i = 0; i < record.sensors.size(); ++i) out << (i ? ", " : "") << record.sensors[i];
  out << "]\nannotated_camera: " << record.annotated_camera
      << "\nmap_frame: \"z up, floor at z = 0, metres\"\n"
      << "camera_frame: \"optical: z forward, x right, y down\"\n"
      << "primitives: " << scene.primitives().size() << "\nobjects:\n";
  for (size_t i = 0; i < scene.objects().size(); ++i) {
    const SceneObject& o = scene.objects()[i];
    out << "  - {index: " << i << ", kind: " << ObjectKindName(o.kind) << ", label: " << o.label
        << ", name: \"" << o.name << "\"}\n";
  }
  if (!scene.buttons.empty()) {
    out << "buttons:\n";
    for (const ButtonSpec& b : scene.buttons) {
      out << "  - {id: " << b.id << ", label: \"" << b.label << "\", center: " << Vec(b.center)
          << ", normal: " << Vec(b.normal) << ", radius_m: " << Num(b.radius_m) << "}\n";
    }
    out << "target_button: " << scene.hints.target_button << "\n";
  }
  out << "options:\n";
  for (const auto& [key, value] : SimulationOptions::Describe().Values(options)) {
    out << "  " << key << ": " << YamlValue(value) << "\n";
  }
  return Finish(out, path);
}

Status WriteHandEyeYaml(const Eigen::Isometry3d& end_effector_from_camera,
                        const Eigen::Isometry3d& world_from_base, const std::string& path) {
  HandEye file;
  file.end_effector_from_camera = end_effector_from_camera;
  file.world_from_base = world_from_base;
  FileComments comments;
  comments.header = {
      "Hand-eye calibration of the simulated arm (metres). end_effector_from_camera: the",
      "camera's optical frame (z forward, x right, y down) in the end-effector frame, as",
      "arm_poses.txt (base_from_end_effector) needs it; world_from_base: the arm's base in",
      "the map frame of buttons.csv."};
  return WriteHandEyeFile(file, path, comments);
}

Status ObservationWriter::Open(const std::string& dir, bool buttons, bool people) {
  dir_ = dir;
  if (buttons) {
    buttons_.open(JoinPath(dir, "buttons.csv"), std::ios::trunc);
    if (!buttons_) return Unavailable("cannot write " + JoinPath(dir, "buttons.csv"));
    buttons_ << "# frame,button,u,v,x,y,z,visible  (u, v: pixels in the annotated camera, "
                "nan when behind it; x, y, z: map frame, metres; visible: 1 when in the image "
                "and not occluded)\n";
  }
  if (people) {
    people_.open(JoinPath(dir, "people.csv"), std::ios::trunc);
    if (!people_) return Unavailable("cannot write " + JoinPath(dir, "people.csv"));
    people_ << "# frame,person,u0,v0,u1,v1,pixels  (inclusive pixel box in the annotated "
               "camera; pixels = 0 and an empty box when the person is not visible)\n";
  }
  return Status::Ok();
}

Status ObservationWriter::Write(const std::vector<ButtonObservation>& buttons,
                                const std::vector<PersonObservation>& people) {
  if (buttons_.is_open()) {
    for (const ButtonObservation& b : buttons) {
      buttons_ << b.frame << "," << b.button << "," << Num(b.pixel.x(), "%.4f") << ","
               << Num(b.pixel.y(), "%.4f") << "," << Num(b.center_in_world.x(), "%.9f") << ","
               << Num(b.center_in_world.y(), "%.9f") << "," << Num(b.center_in_world.z(), "%.9f")
               << "," << (b.visible ? 1 : 0) << "\n";
    }
    SIGHTLINE_RETURN_IF_ERROR(Finish(buttons_, JoinPath(dir_, "buttons.csv")));
  }
  if (people_.is_open()) {
    for (const PersonObservation& p : people) {
      people_ << p.frame << "," << p.person << "," << p.u0 << "," << p.v0 << "," << p.u1 << ","
              << p.v1 << "," << p.pixels << "\n";
    }
    SIGHTLINE_RETURN_IF_ERROR(Finish(people_, JoinPath(dir_, "people.csv")));
  }
  return Status::Ok();
}

Status ObservationWriter::Close() {
  if (buttons_.is_open()) buttons_.close();
  if (people_.is_open()) people_.close();
  return Status::Ok();
}

}  // namespace sightline::sim
