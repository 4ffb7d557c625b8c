#include "core/sim/simulation_options.h"

#include <algorithm>

#include "core/common/text_file.h"

namespace sightline::sim {

SimulationOptions SimulationOptions::ForScene(const std::string& scene) {
  SimulationOptions o;
  o.scene = scene;
  if (scene == "terrain") {
    o.frames = 60;
    o.motion.speed_mps = 0.2;
    o.motion.camera_height_m = 1.0;
    o.motion.camera_tilt_deg = 30;
  } else if (scene == "panel") {
    o.frames = 150;
  }
  return o;
}

StatusOr<std::vector<std::string>> SimulationOptions::SensorList() const {
  if (sensors == "auto") {
    if (scene == "corridor") return std::vector<std::string>{"rgbd", "stereo"};
    if (scene == "panel") return std::vector<std::string>{"mono"};
    return std::vector<std::string>{"rgbd"};
  }
  std::vector<std::string> list;
  for (const std::string& name : SplitFields(sensors)) {
    if (name != "rgbd" && name != "stereo" && name != "mono") {
      return InvalidArgument("sim.sensors: unknown sensor '" + name +
                             "' (use rgbd, stereo, mono, separated by commas, or auto)");
    }
    if (std::find(list.begin(), list.end(), name) == list.end()) list.push_back(name);
  }
  if (list.empty()) return InvalidArgument("sim.sensors: no sensor given (rgbd, stereo, mono)");
  return list;
}

bool SimulationOptions::IsValid(std::string* error) const {
  auto fail = [&](const std::string& m) {
    if (error) *error = "sim." + m;
    return false;
  };
  if (std::find(SceneNames().begin(), SceneNames().end(), scene) == SceneNames().end()) {
    return fail("scene = '" + scene + "': must be corridor, terrain or panel");
  }
  if (frames < 1 || frames > 1000000) {
    return fail("frames = " + std::to_string(frames) + ": must lie in [1, 1000000]");
  }
  if (seed < 0) return fail("seed must be >= 0");
  if (!(rate_hz >= 0.1 && rate_hz <= 1000)) return fail("rate_hz must lie in [0.1, 1000] Hz");
  if (png_compression < 0 || png_compression > 9) return fail("png_compression must lie in [0, 9]");
  auto sensor_list = SensorList();
  if (!sensor_list.ok()) {
    if (error) *error = sensor_list.status().message();
    return false;
  }
  return corridor.IsValid(error) && terrain.IsValid(error) && panel.IsValid(error) &&
         rgbd.IsValid(error) && stereo.IsValid(error) && mono.IsValid(error) &&
         noise.IsValid(error) && motion.IsValid(error) && arm.IsValid(error) &&
         odometry.IsValid(error);
}

OptionTable<SimulationOptions> SimulationOptions::Describe() {
  using O = SimulationOptions;
  return OptionTable<O>("sim")
      .Choice("scene", &O::scene, SceneNames(), "The world to simulate.")
      .Int("frames", &O::frames, "frames", 1, 1000000, 1, "Frames per sensor.")
      .Int("seed", &O::seed, "", 0, 2147483647, 1,
           "Seed of everything random; the same seed writes byte-identical files.")
      .Double("rate_hz", &O::rate_hz, "Hz", 0.1, 1000, 1, "Frame rate of all sensors.")
      .String("sensors", &O::sensors,
              "auto (the scene's own) or a comma-separated list of rgbd, stereo, mono.")
      .Int("png_compression", &O::png_compression, "", 0, 9, 1,
           "zlib level of the written PNGs (0 = fastest, 9 = smallest).")
      .Nested(&O::corridor, CorridorOptions::Describe())
      .Nested(&O::terrain, TerrainOptions::Describe())
      .Nested(&O::panel, PanelOptions::Describe())
      .Nested(&O::rgbd, RgbdSensorOptions::Describe())
      .Nested(&O::stereo, StereoSensorOptions::Describe())
      .Nested(&O::mono, MonoSensorOptions::Describe())
      .Nested(&O::noise, NoiseOptions::Describe())
      .Nested(&O::motion, MotionOptions::Describe())
      .Nested(&O::arm, ArmOptions::Describe())
      .Nested(&O::odometry, OdometryOptions::Describe());
}

}  // namespace sightline::sim
