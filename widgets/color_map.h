// The colour map shared by the depth image view, its legend and the scene view's scalar colouring,
// so that one colour means one distance everywhere in the GUI.
#pragma once

#include <array>
#include <cstdint>

namespace sightline {

// An RGB triple, 8 bits per channel.
struct Rgb8 {
  uint8_t r = 0;
  uint8_t g = 0;
  uint8_t b = 0;
};

// The 256-entry "turbo" colour map (blue = low, red = high), taken from OpenCV's
// COLORMAP_TURBO so that images coloured with cv::applyColorMap agree with the widgets.
const std::array<Rgb8, 256>& TurboColorMap();

// The turbo colour of `value` mapped linearly from [low, high] (clamped at both ends).
Rgb8 TurboColor(double value, double low, double high);

}  // namespace sightline
