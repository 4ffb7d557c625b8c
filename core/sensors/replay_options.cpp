#include "core/sensors/replay_source.h"

namespace sightline {

bool ReplayOptions::IsValid(std::string* error) const {
  if (fps < 0 || fps > 10000) {
    if (error) *error = "sensors.replay.fps must be in [0, 10000] (0 = recorded rate)";
    return false;
  }
  std::string live_error;
  if (!live.IsValid(&live_error)) {
    if (error) *error = "sensors.replay." + live_error;
    return false;
  }
  return true;
}

OptionTable<ReplayOptions> ReplayOptions::Describe() {
  return OptionTable<ReplayOptions>("sensors.replay")
      .Double("fps", &ReplayOptions::fps, "Hz", 0, 10000, 1,
              "Rate at which a replayed recording delivers frames; 0 follows its timestamps.")
      .Bool("loop", &ReplayOptions::loop,
            "Start again at the end (timestamps keep increasing) instead of ending the stream.")
      .Nested(&ReplayOptions::live, LiveSourceOptions::Describe());
}

}  // namespace sightline
