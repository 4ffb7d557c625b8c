// Every setting of one simulated recording, as one typed Options struct with a Describe()
// table (keys "sim.*"), so the CLI's --set, YAML profiles and the GUI share them.
#pragma once

#include <string>
#include <vector>

#include "core/common/status.h"
#include "core/options/option_table.h"
#include "core/sim/corridor_scene.h"
#include "core/sim/motion.h"
#include "core/sim/odometry.h"
#include "core/sim/panel_scene.h"
#include "core/sim/sensor_options.h"
#include "core/sim/terrain_scene.h"

namespace sightline::sim {

// The built-in scenes.
inline const std::vector<std::string>& SceneNames() {
  static const std::vector<std::string> kNames = {"corridor", "terrain", "panel"};
  return kNames;
}

// A simulated recording: scene, length, seed, sensors, noise and motion.
//
//   SimulationOptions options = SimulationOptions::ForScene("terrain");
//   options.frames = 10;
//   options.terrain.ramp_slope_deg = 30;
//   auto summary = Simulate(options, "/tmp/terrain30");
struct SimulationOptions {
  std::string scene = "corridor";  // "corridor", "terrain" or "panel".
  int frames = 300;                // Frames per sensor, >= 1.
  int seed = 1;                    // Everything random derives from it; equal seed = equal bytes.
  double rate_hz = 30.0;           // Frames per second (all sensors are synchronous).
  std::string sensors = "auto";    // "auto" or a list of rgbd, stereo, mono ("rgbd,stereo").
  int png_compression = 1;         // zlib level of the PNGs (0-9): speed against size.

  CorridorOptions corridor;
  TerrainOptions terrain;
  PanelOptions panel;
  RgbdSensorOptions rgbd;
  StereoSensorOptions stereo;
  MonoSensorOptions mono;
  NoiseOptions noise;
  MotionOptions motion;
  ArmOptions arm;
  OdometryOptions odometry;

  // The defaults for a scene: corridor (300 frames, robot at 0.5 m/s with the Kinect at 0.8 m,
  // rgbd + stereo), terrain (60 frames, robot at 0.2 m/s with the camera at 1.0 m pitched down
  // 30 deg, rgbd), panel (150 frames, arm approach, mono).
  static SimulationOptions ForScene(const std::string& scene);

  // The sensors to render: the scene's defaults for "auto", else the listed ones (each once).
  StatusOr<std::vector<std::string>> SensorList() const;

  // Checks every field (including the nested ones); the message names the key.
  bool IsValid(std::string* error) const;
  static OptionTable<SimulationOptions> Describe();
};

}  // namespace sightline::sim
