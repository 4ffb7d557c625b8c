#include "core/sensors/aravis_options.h"

namespace sightline {
namespace {

bool Fail(std::string* error, const std::string& message) {
  if (error) *error = message;
  return false;
}

}  // namespace

bool AravisOptions::IsValid(std::string* error) const {
  if (width < 0 || height < 0) return Fail(error, "sensors.aravis.width/height must be >= 0");
  if (exposure_us < 0) return Fail(error, "sensors.aravis.exposure_us must be >= 0 (0 = as is)");
  if (frame_rate_hz < 0) return Fail(error, "sensors.aravis.frame_rate_hz must be >= 0");
  if (trigger != "free" && trigger != "software" && trigger != "hardware") {
    return Fail(error,
                "sensors.aravis.trigger must be free, software or hardware, not '" + trigger + "'");
  }
  if (trigger == "software" && frame_rate_hz <= 0) {
    return Fail(error,
                "sensors.aravis.trigger=software needs sensors.aravis.frame_rate_hz > 0 "
                "(the rate at which the host triggers)");
  }
  if (trigger == "hardware" && trigger_line.empty()) {
    return Fail(error, "sensors.aravis.trigger=hardware needs sensors.aravis.trigger_line");
  }
  if (buffer_count < 2) return Fail(error, "sensors.aravis.buffer_count must be >= 2");
  if (socket_buffer_bytes < 0 || packet_size < 0) {
    return Fail(error, "sensors.aravis.socket_buffer_bytes/packet_size must be >= 0 (0 = auto)");
  }
  std::string live_error;
  if (!live.IsValid(&live_error)) return Fail(error, "sensors.aravis." + live_error);
  return true;
}

OptionTable<AravisOptions> AravisOptions::Describe() {
  return OptionTable<AravisOptions>("sensors.aravis")
      .String("pixel_format", &AravisOptions::pixel_format,
              "GenICam pixel format to select (Mono8, Mono16, BayerRG8, RGB8, ...); empty keeps "
              "the camera's. 16-bit formats are scaled to 8 bits.")
      .Int("width", &AravisOptions::width, "px", 0, 65535, 1,
           "Region-of-interest width; 0 keeps the camera's.")
      .Int("height", &AravisOptions::height, "px", 0, 65535, 1,
           "Region-of-interest height; 0 keeps the camera's.")
      .Double("exposure_us", &AravisOptions::exposure_us, "us", 0, 1e8, 100,
              "Exposure time; 0 keeps the camera's. Out-of-range values are errors.")
      .Double("gain_db", &AravisOptions::gain_db, "dB", -1, 100, 0.5,
              "Analog gain; negative keeps the camera's. Out-of-range values are errors.")
      .Double("frame_rate_hz", &AravisOptions::frame_rate_hz, "Hz", 0, 10000, 1,
              "Free-running frame rate, or the host's rate with software triggering; 0 keeps "
              "the camera's. Rates the camera cannot reach are errors.")
      .Choice("trigger", &AravisOptions::trigger, {"free", "software", "hardware"},
              "free: the camera runs on its own clock; software: the host triggers each frame "
              "(both cameras of a pair together); hardware: an external pulse on trigger_line.")
      .String("trigger_line", &AravisOptions::trigger_line,
              "Input line used with hardware triggering, e.g. Line1.")
      .Int("buffer_count", &AravisOptions::buffer_count, "buffers", 2, 256, 1,
           "Image buffers in the stream's pool; more ride out longer consumer stalls.")
      .Int("socket_buffer_bytes", &AravisOptions::socket_buffer_bytes, "bytes", 0, 1 << 30, 65536,
           "GigE receive socket buffer; 0 lets Aravis size it to a whole frame (without it most "
           "packets of large frames are lost).")
      .Int("packet_size", &AravisOptions::packet_size, "bytes", 0, 16384, 4,
           "GigE stream packet size; 0 negotiates the largest packet that reaches the host.")
      .Bool("debayer", &AravisOptions::debayer,
            "Demosaic Bayer formats to BGR colour; off delivers the raw mosaic as grey.")
      .Bool("fake_interface", &AravisOptions::fake_interface,
            "Also list and open Aravis' in-process simulated camera Fake_1 (demos and tests).")
      .Nested(&AravisOptions::live, LiveSourceOptions::Describe());
}

bool AravisStereoOptions::IsValid(std::string* error) const {
  if (!(pair_tolerance_ms >= 0)) {
    return Fail(error, "sensors.aravis.stereo.pair_tolerance_ms must be >= 0");
  }
  if (pair_clock != "device" && pair_clock != "host") {
    return Fail(
        error, "sensors.aravis.stereo.pair_clock must be device or host, not '" + pair_clock + "'");
  }
  return true;
}

OptionTable<AravisStereoOptions> AravisStereoOptions::Describe() {
  return OptionTable<AravisStereoOptions>("sensors.aravis.stereo")
      .Double("pair_tolerance_ms", &AravisStereoOptions::pair_tolerance_ms, "ms", 0, 1000, 0.5,
              "Largest difference between the left and right timestamps of a pair; frames "
              "without a partner are dropped and counted.")
      .Choice("pair_clock", &AravisStereoOptions::pair_clock, {"device", "host"},
              "device: pair by camera timestamps (cameras on a common clock, e.g. PTP or a "
              "shared trigger); host: pair by arrival time at the host.")
      .String("calibration_file", &AravisStereoOptions::calibration_file,
              "Stereo calibration of the pair (OpenCV stereo YAML: M1 D1 M2 D2 R T, "
              "image_width/height, as `sightline-cli calibrate stereo` writes); the stereo "
              "odometry needs it. Also as aravis://LEFT,RIGHT?calibration_file=FILE.");
}

}  // namespace sightline
