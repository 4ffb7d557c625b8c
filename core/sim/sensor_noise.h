// Sensor models applied to rendered views: the Kinect depth model and image noise. Seeded per
// call, so a frame's noise depends only on (seed, sensor, frame), never on rendering order.
#pragma once

#include <cstdint>
#include <opencv2/core.hpp>

#include "core/sim/renderer.h"
#include "core/sim/sensor_options.h"

namespace sightline::sim {

// Turns the exact z-buffer of `view` into what the depth sensor reports (CV_32FC1 metres, NaN
// = no reading): range limits and grazing dropout from `sensor`, then disparity noise and
// quantisation from `noise` (see NoiseOptions). The disparity focal length is
// sensor.focal_px at the native 640x480, whatever the output resolution.
void ApplyDepthModel(const RenderedView& view, const RgbdSensorOptions& sensor,
                     const NoiseModel& noise, uint64_t seed, cv::Mat* depth_m);

// Adds Gaussian noise of `sigma` grey levels to every channel of an 8-bit image, rounding and
// clamping to [0, 255]. No-op for sigma <= 0.
void AddImageNoise(double sigma, uint64_t seed, cv::Mat* image);

}  // namespace sightline::sim
