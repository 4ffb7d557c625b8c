#include "core/sensors/v4l2_source.h"

namespace sightline {
namespace {

bool Fail(std::string* error, const std::string& message) {
  if (error) *error = message;
  return false;
}

}  // namespace

bool V4l2Options::IsValid(std::string* error) const {
  if (width < 0 || height < 0) return Fail(error, "sensors.v4l2.width/height must be >= 0");
  if (fps < 0) return Fail(error, "sensors.v4l2.fps must be >= 0");
  if (!fourcc.empty() && fourcc.size() != 4) {
    return Fail(error,
                "sensors.v4l2.fourcc must have 4 characters, e.g. MJPG, not '" + fourcc + "'");
  }
  std::string live_error;
  if (!live.IsValid(&live_error)) return Fail(error, "sensors.v4l2." + live_error);
  return true;
}

OptionTable<V4l2Options> V4l2Options::Describe() {
  return OptionTable<V4l2Options>("sensors.v4l2")
      .Int("width", &V4l2Options::width, "px", 0, 16384, 1,
           "Requested image width; 0 keeps the camera's. V4L2 picks the nearest mode.")
      .Int("height", &V4l2Options::height, "px", 0, 16384, 1,
           "Requested image height; 0 keeps the camera's.")
      .Double("fps", &V4l2Options::fps, "Hz", 0, 1000, 1,
              "Requested frame rate; 0 keeps the camera's.")
      .String("fourcc", &V4l2Options::fourcc,
              "Pixel format as a FOURCC, e.g. MJPG for high resolutions over USB 2; empty "
              "keeps the camera's.")
      .Nested(&V4l2Options::live, LiveSourceOptions::Describe());
}

}  // namespace sightline
