// The ground-truth files in a simulated recording's top folder (see core/sim/README.md):
//
//   walls.csv    # wall,x1,y1,x2,y2,a,b,c   wall faces on the floor plan (map frame), with the
//                line a x + b y + c = 0, a^2 + b^2 = 1, (a, b) pointing into the free side
//   regions.csv  # region,kind,slope_deg,roughness,height_m,polygon   polygon = "x y x y ..."
//   buttons.csv  # frame,button,u,v,x,y,z,visible   button centres in every image of the
//                annotated camera and in the map frame
//   people.csv   # frame,person,u0,v0,u1,v1,pixels   bounding boxes in the annotated camera
//   scene.yaml   the scene, seed, sensors, frames, objects, buttons and every sim.* option
//   hand_eye.yaml  arm scenes: end_effector_from_camera and world_from_base
//
// CSV files start with a '#' header line (as EuRoC's do), so both CSV readers and Sightline's
// ReadDataLines + SplitFields read them.
#pragma once

#include <Eigen/Geometry>
#include <fstream>
#include <string>
#include <vector>

#include "core/common/status.h"
#include "core/sim/observations.h"
#include "core/sim/scene.h"
#include "core/sim/simulation_options.h"

namespace sightline::sim {

// Writes walls.csv.
Status WriteWallsCsv(const Scene& scene, const std::string& path);
// Writes regions.csv.
Status WriteRegionsCsv(const Scene& scene, const std::string& path);

// What scene.yaml records besides the options.
struct SceneRecord {
  std::vector<std::string> sensors;
  std::string annotated_camera;  // The sensor folder buttons.csv and people.csv refer to.
  std::string motion;            // Resolved motion kind.
  int frames_written = 0;
};

// Writes scene.yaml.
Status WriteSceneYaml(const SimulationOptions& options, const Scene& scene,
                      const SceneRecord& record, const std::string& path);

// Writes hand_eye.yaml (core/io/hand_eye_file.h): end_effector_from_camera and world_from_base
// (arm base in the map).
Status WriteHandEyeYaml(const Eigen::Isometry3d& end_effector_from_camera,
                        const Eigen::Isometry3d& world_from_base, const std::string& path);

// Appends per-frame observations to buttons.csv and people.csv, flushing after each frame.
class ObservationWriter {
 public:
  // Opens the files that apply (buttons.csv when `buttons`, people.csv when `people`).
  Status Open(const std::string& dir, bool buttons, bool people);
  Status Write(const std::vector<ButtonObservation>& buttons,
               const std::vector<PersonObservation>& people);
  Status Close();

 private:
  std::ofstream buttons_, people_;
  std::string dir_;
};

}  // namespace sightline::sim
