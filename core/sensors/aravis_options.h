// Settings of the Aravis (GigE Vision / USB3 Vision) camera sources, keys `sensors.aravis.*`.
// Compiled also without Aravis so that profiles stay valid in every build.
#pragma once

#include <string>

#include "core/options/option_table.h"
#include "core/sensors/live_source.h"

namespace sightline {

// One camera's settings; a stereo pair applies them to both cameras.
struct AravisOptions {
  std::string pixel_format;  // GenICam name ("Mono8", "Mono16", "BayerRG8", "RGB8"); "" = as is.
  int width = 0;             // Region of interest width [px]; 0 = as configured.
  int height = 0;            // Region of interest height [px]; 0 = as configured.
  double exposure_us = 0;    // Exposure time [us]; 0 = as configured.
  double gain_db = -1;       // Gain [dB]; negative = as configured.
  double frame_rate_hz = 0;  // Free-running rate, or software trigger rate [Hz]; 0 = as is.
  std::string trigger = "free";  // "free", "software" (host triggers at frame_rate_hz), "hardware".
  std::string trigger_line = "Line1";  // Input line for hardware triggering.
  int buffer_count = 8;                // Buffers in the stream's pool.
  int socket_buffer_bytes = 0;  // GigE receive socket buffer; 0 = sized automatically by Aravis.
  int packet_size = 0;          // GigE packet size [bytes]; 0 = largest that reaches the host.
  bool debayer = true;          // Bayer formats become BGR colour; off keeps the raw mosaic.
  bool fake_interface = false;  // Also offer Aravis' in-process simulated camera "Fake_1".
  LiveSourceOptions live;       // Queueing and reconnects.

  bool IsValid(std::string* error) const;
  static OptionTable<AravisOptions> Describe();
};

// How two cameras form a stereo pair, keys `sensors.aravis.stereo.*`.
struct AravisStereoOptions {
  double pair_tolerance_ms = 5;  // Largest timestamp difference of a left/right pair [ms].
  std::string pair_clock =
      "device";  // "device" timestamps (synchronised cameras) or "host" arrival.
  // OpenCV stereo YAML (as `sightline-cli calibrate stereo` writes) that the source attaches to
  // its SourceInfo, so stereo pipelines can rectify; "" = none. Also
  // aravis://L,R?calibration_file=F.
  std::string calibration_file;

  bool IsValid(std::string* error) const;
  static OptionTable<AravisStereoOptions> Describe();
};

}  // namespace sightline
