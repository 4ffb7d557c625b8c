// The largest inputs the readers accept. Each is checked against what a file declares or
// occupies before anything of that size is allocated; an input above a limit is an error naming
// the file, the field and the limit. README's "Reliability" section lists them.
#pragma once

#include <cstddef>

namespace sightline {

// An image side (width or height) a calibration file may declare [px]: beyond every camera
// sold; a larger value is a corrupt field.
inline constexpr int kMaxImageSidePx = 32768;
// Pixels an image file may declare in its header (PNG, JPEG, PGM/PPM, BMP; checked before
// decoding): 100 megapixels, above every camera Sightline reads (a 4K frame is 8.3 Mpx).
inline constexpr double kMaxImagePixels = 100e6;
// A YAML file read whole (camera.yaml, stereo calibration, hand_eye.yaml, the floor file,
// EuRoC sensor.yaml) [bytes]: real ones are a few kB.
inline constexpr size_t kMaxCalibrationFileBytes = size_t{1} << 20;
// An index or pose list (rgb.txt, depth.txt, associations.txt, groundtruth.txt, times.txt,
// poses.txt, calib.txt, EuRoC data.csv) [bytes]: an hour of 1 kHz ground truth is ~60 MB.
inline constexpr size_t kMaxIndexFileBytes = size_t{256} << 20;
// Points a PCD header may declare: a 640x480 cloud is 307,200, an aggregated map a few million.
inline constexpr double kMaxPcdPoints = 50e6;

}  // namespace sightline
