#include "core/sensors/openni2_options.h"

namespace sightline {
namespace {

bool Fail(std::string* error, const std::string& message) {
  if (error) *error = message;
  return false;
}

}  // namespace

bool OpenNi2Options::IsValid(std::string* error) const {
  if (width < 0 || height < 0 || fps < 0) {
    return Fail(error, "sensors.openni2.width/height/fps must be >= 0 (0 = device default)");
  }
  if ((width > 0) != (height > 0)) {
    return Fail(error, "sensors.openni2.width and height must be given together");
  }
  if (!depth && !color) return Fail(error, "sensors.openni2: enable depth, colour or both");
  if (!(pair_tolerance_ms >= 0)) {
    return Fail(error, "sensors.openni2.pair_tolerance_ms must be >= 0");
  }
  if (!(max_depth_m > 0)) return Fail(error, "sensors.openni2.max_depth_m must be positive");
  if (!(playback_speed >= 0)) return Fail(error, "sensors.openni2.playback_speed must be >= 0");
  std::string live_error;
  if (!live.IsValid(&live_error)) return Fail(error, "sensors.openni2." + live_error);
  return true;
}

OptionTable<OpenNi2Options> OpenNi2Options::Describe() {
  return OptionTable<OpenNi2Options>("sensors.openni2")
      .Int("width", &OpenNi2Options::width, "px", 0, 4096, 1,
           "Stream width for depth and colour; 0 keeps the device's default mode.")
      .Int("height", &OpenNi2Options::height, "px", 0, 4096, 1,
           "Stream height for depth and colour; 0 keeps the device's default mode.")
      .Int("fps", &OpenNi2Options::fps, "Hz", 0, 120, 1,
           "Stream rate; 0 keeps the device's default mode.")
      .Bool("depth", &OpenNi2Options::depth, "Stream depth.")
      .Bool("color", &OpenNi2Options::color, "Stream colour.")
      .Bool("registration", &OpenNi2Options::registration,
            "Register depth to the colour camera in the device when it supports it, so that "
            "depth and colour pixels correspond.")
      .Bool("sync", &OpenNi2Options::sync,
            "Ask the device to deliver depth and colour frames of the same instant.")
      .Bool("mirror", &OpenNi2Options::mirror,
            "Mirror images left-right, as OpenNI does by default for people facing the camera.")
      .Double("pair_tolerance_ms", &OpenNi2Options::pair_tolerance_ms, "ms", 0, 1000, 1,
              "Largest depth/colour timestamp difference of an RGB-D pair from a device; "
              "frames without a partner are dropped and counted.")
      .Double("max_depth_m", &OpenNi2Options::max_depth_m, "m", 0.1, 100, 0.5,
              "Depth readings beyond this are treated as invalid downstream.")
      .Bool("loop", &OpenNi2Options::loop,
            ".oni recordings start again at the first frame instead of ending.")
      .Double("playback_speed", &OpenNi2Options::playback_speed, "", 0, 100, 0.1,
              ".oni playback speed: 0 delivers frames as fast as they are read, nothing "
              "skipped; 1 paces at the recorded rate.")
      .Nested(&OpenNi2Options::live, LiveSourceOptions::Describe());
}

}  // namespace sightline
