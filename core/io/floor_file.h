// The floor file: the floor calibration (FloorCalibration, core/common/floor.h) as
// `sightline-cli floor`, the mapping pipeline (floor.yaml) and the GUI's mapping view write it,
// and as mapping.run.floor_file and mobility.run.floor_file read it. Plain YAML, one key per line:
//
//   a: 0.01                  # required: normal (a, b, c) of a x + b y + c z + d = 0 in the
//   b: -0.96                 #   camera frame, pointing up; within 1 % of unit length (it is
//   c: -0.27                 #   then normalised, d with it), otherwise rejected
//   d: 1.2                   # required: the camera height [m], finite and positive
//   epsilon_m: 0.035         # optional (0.035): floor tolerance [m], positive
//   camera_height_m: 1.2     # optional, derived (= d), for people; checked to be a number only
//   pitch_down_deg: 15.6     # optional, derived, for people; checked to be a number only
//   inlier_ratio: 0.62       # optional: of the fit, in [0, 1]
//   frames: 10               # optional: frames the fit used, a whole number >= 0
//   source: "recording"      # optional: where the fit came from, text
//
// Unknown and repeated keys are errors. A "%YAML:1.0" first line is accepted.
#pragma once

#include <string>

#include "core/common/floor.h"
#include "core/common/status.h"

namespace sightline {

// Writes the format above. InvalidArgument (nothing written) when the plane is not valid
// (FloorPlane::IsValid) or a figure is out of range; Unavailable when the file cannot be written.
Status WriteFloorCalibration(const FloorCalibration& calibration, const std::string& path);

// Reads and validates a floor file. NotFound when missing; other file problems as
// CheckReadableFile says; ParseError naming the file, the line and the key.
StatusOr<FloorCalibration> ReadFloorCalibration(const std::string& path);

}  // namespace sightline
