// Human and JSON descriptions of an open source, for `sightline-cli info PATH [--json]` and the
// GUI's source panel.
#pragma once

#include <string>

#include "core/io/source.h"

namespace sightline {

// "51 stereo pairs", "9 RGB-D frames", "1 point cloud", "38 images"; "live" for live sources.
std::string DescribeFrameCount(const SourceInfo& info);

// Key: value lines: format, path, kind, frames, resolution, duration, rate, camera (fx fy cx cy,
// distortion), stereo baseline, depth scale, ground truth (yes + poses and path length / no),
// notes. Example:
//
//   format: KITTI odometry
//   kind: stereo
//   frames: 51 stereo pairs
//   resolution: 1226x370
//   ...
//   ground truth: yes (51 poses, path length 59.86 m)
std::string DescribeSourceText(const Source& source);

// The same facts as one JSON object (numbers as numbers, absent facts as null).
std::string DescribeSourceJson(const Source& source);

}  // namespace sightline
