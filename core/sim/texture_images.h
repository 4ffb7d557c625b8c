// Baked texture images: posters with text-like print and button labels with printed numbers.
// Built once per scene from a seed (cv::putText and filled shapes), so they are deterministic.
#pragma once

#include <cstdint>
#include <string>

#include "core/sim/material.h"

namespace sightline::sim {

// A poster of `width_px` x `height_px`: a coloured title band with words, blocks of random
// colour (pictures) and lines of small text. Rich in corners and blobs for feature detectors.
TextureImage MakePosterImage(uint64_t seed, int width_px, int height_px);

// A button face of `size_px` square showing `label` in dark print on a light face with a ring
// (round buttons) or a border (square ones).
TextureImage MakeButtonLabelImage(const std::string& label, bool round, int size_px);

// A small dark display of `width_px` x `height_px` showing `text` in red segments-like print
// (the floor indicator above an elevator panel).
TextureImage MakeDisplayImage(const std::string& text, int width_px, int height_px);

}  // namespace sightline::sim
