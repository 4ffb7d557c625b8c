// The frames of Sightline's synthetic OpenNI2 test device: known values the tests check.
#pragma once

#include <cstdint>

namespace sightline::synthetic_openni2 {

inline constexpr const char* kUri = "sightline-synthetic://0";
inline constexpr const char* kVendor = "Sightline";
inline constexpr const char* kName = "Synthetic RGB-D";
inline constexpr int kWidth = 160;
inline constexpr int kHeight = 120;
inline constexpr int kFps = 30;
inline constexpr float kHorizontalFovRad = 1.0f;
inline constexpr float kVerticalFovRad = 0.78f;
// Columns left of this have no depth reading (0).
inline constexpr int kInvalidColumns = 8;

// Environment variables read when the device is opened:
// frames after which the device stops (unset or 0 = never) ...
inline constexpr const char* kStopAfterEnv = "SIGHTLINE_SYNTHETIC_STOP_AFTER";
// ... and how: "stall" (stays attached, sends nothing) or "unplug" (reports a disconnect and is
// absent for kAbsentMsEnv milliseconds, default 1000, before it can be opened again).
inline constexpr const char* kStopModeEnv = "SIGHTLINE_SYNTHETIC_STOP_MODE";
inline constexpr const char* kAbsentMsEnv = "SIGHTLINE_SYNTHETIC_ABSENT_MS";

// Depth in millimetres at (x, y) of frame `frame_index` (1-based, as OpenNI counts).
inline uint16_t DepthMm(int x, int y, int frame_index) {
  if (x < kInvalidColumns) return 0;
  return static_cast<uint16_t>(500 + 10 * x + 2 * y + frame_index % 50);
}

// Colour (R, G, B) at (x, y) of frame `frame_index`.
inline void Rgb(int x, int y, int frame_index, uint8_t rgb[3]) {
  rgb[0] = static_cast<uint8_t>(x);
  rgb[1] = static_cast<uint8_t>(y);
  rgb[2] = static_cast<uint8_t>(frame_index % 256);
}

}  // namespace sightline::synthetic_openni2
