// Settings of the OpenNI2 RGB-D source, keys `sensors.openni2.*`. Compiled also without
// OpenNI2 so that profiles stay valid in every build.
#pragma once

#include <string>

#include "core/options/option_table.h"
#include "core/sensors/live_source.h"

namespace sightline {

// Device and playback settings. Resolution and rate apply to both streams; zero keeps the
// device's default mode.
struct OpenNi2Options {
  int width = 0;                  // Stream width [px]; 0 = device default.
  int height = 0;                 // Stream height [px]; 0 = device default.
  int fps = 0;                    // Stream rate [Hz]; 0 = device default.
  bool depth = true;              // Stream depth.
  bool color = true;              // Stream colour.
  bool registration = true;       // Register depth to colour when the device can.
  bool sync = true;               // Ask the device to synchronise depth and colour frames.
  bool mirror = false;            // Mirror images left-right (as a mirror, for people facing it).
  double pair_tolerance_ms = 20;  // Largest depth/colour timestamp difference of a pair [ms].
  double max_depth_m = 10;        // Readings beyond this are invalid (RgbdCalibration) [m].
  bool loop = false;              // Recordings: start again at the end instead of ending.
  double playback_speed = 0;      // Recordings: 0 = as fast as read, 1 = recorded rate.
  LiveSourceOptions live;         // Queueing and reconnects (devices).

  bool IsValid(std::string* error) const;
  static OptionTable<OpenNi2Options> Describe();
};

}  // namespace sightline
