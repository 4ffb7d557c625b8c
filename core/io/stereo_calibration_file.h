// The stereo calibration file: OpenCV's stereo layout, as `sightline-cli calibrate stereo`, the
// GUI's calibration dialog and OpenCV's own stereo samples write it, and as the Aravis stereo
// source and the stereo-vo pipeline read it:
//
//   %YAML:1.0
//   ---
//   image_width: 640                 # pixels, both cameras
//   image_height: 480
//   M1: !!opencv-matrix              # left intrinsic matrix [fx 0 cx; 0 fy cy; 0 0 1]
//     rows: 3
//     cols: 3
//     dt: d
//     data: [ ... ]
//   D1: !!opencv-matrix              # left distortion k1 k2 p1 p2 [k3] (1x4, 1x5, 4x1 or 5x1)
//   M2: ...   D2: ...                # the right camera
//   R: !!opencv-matrix               # 3x3, x_right = R x_left + T
//   T: !!opencv-matrix               # 3x1, metres
//   E F R1 R2 P1 P2 Q rms_* baseline_m board_* square_size_m ...   # anything else: not read
//
// Keys other than the ones read are allowed (OpenCV tools add their own), but no key may appear
// twice. Checks: image size positive, each camera as calibration_checks.h says, M1/M2 without
// skew and with last row 0 0 1, R a rotation (within 1e-6, det +1), T finite with a baseline of
// at least 0.1 mm. Plain lists ("M1: [fx, 0, cx, ...]") are accepted for every matrix.
#pragma once

#include <Eigen/Core>
#include <string>
#include <utility>
#include <vector>

#include "core/common/camera.h"
#include "core/common/status.h"
#include "core/io/yaml_writer.h"

namespace sightline {

// What a writer may add to a stereo calibration file beside the rig, for people and for OpenCV
// tools (E, F, R1, R2, P1, P2, Q, RMS errors, the board). The reader does not read them back.
struct StereoFileExtras {
  std::vector<std::pair<std::string, Eigen::MatrixXd>> matrices;
  std::vector<std::pair<std::string, double>> numbers;
  FileComments comments;
};

// Reads the rig (M1 D1 M2 D2 R T, image_width/height) of a stereo calibration file; `rectified`
// is false. NotFound when missing; other file problems as CheckReadableFile says; ParseError
// naming the file, the line and the missing or rejected key.
StatusOr<StereoRig> ReadStereoCalibration(const std::string& path);

// Writes `rig` (the left camera's size as image_width/height) and `extras` in the layout above.
// InvalidArgument (nothing written) when the reader would reject the rig; Unavailable when the
// file cannot be written.
Status WriteStereoCalibration(const StereoRig& rig, const std::string& path,
                              const StereoFileExtras& extras = {});

}  // namespace sightline
