// camera.yaml: the one camera file format Sightline reads beside image folders and TUM-style
// RGB-D folders, and that the simulator, the recorder and `calibrate mono` write. Plain YAML,
// one key per line:
//
//   model: pinhole                 # optional; only "pinhole" is supported
//   width: 640                     # pixels
//   height: 480                    # pixels
//   fx: 525.0                      # focal lengths, pixels
//   fy: 525.0
//   cx: 319.5                      # principal point, pixels
//   cy: 239.5
//   distortion: [0, 0, 0, 0, 0]    # optional: OpenCV radial-tangential k1 k2 p1 p2 [k3]
//   depth_scale: 5000              # optional, RGB-D: raw depth units per metre
//   max_depth_m: 10                # optional, RGB-D: readings beyond are invalid
//   rate_hz: 30                    # optional: nominal frame rate
//
// A first line "%YAML:1.0" (cv::FileStorage) is accepted and written, so OpenCV reads the file
// too. Unknown and repeated keys are errors, so a misspelt key never silently does nothing. The
// values are checked as calibration_checks.h says (sizes and focal lengths positive, principal
// point inside the image, |distortion| < 1e3, optional values positive).
#pragma once

#include <optional>
#include <string>

#include "core/common/camera.h"
#include "core/common/status.h"
#include "core/io/yaml_writer.h"

namespace sightline {

// The content of a camera.yaml.
struct CameraFile {
  PinholeCamera camera;
  std::optional<double> depth_scale;  // Raw depth units per metre.
  std::optional<double> max_depth_m;  // Metres.
  std::optional<double> rate_hz;      // Frames per second.
};

// The file name the readers look for beside a dataset.
inline constexpr const char* kCameraYamlName = "camera.yaml";

// Reads and validates a camera.yaml. NotFound when missing; other file problems as
// CheckReadableFile says; ParseError naming file, line and key for the content.
StatusOr<CameraFile> ReadCameraYaml(const std::string& path);

// Writes `file` in the format above (optional fields only when set), with `comments`.
// InvalidArgument (nothing written) when the reader would reject a value; Unavailable when the
// file cannot be written.
Status WriteCameraYaml(const CameraFile& file, const std::string& path,
                       const FileComments& comments = {});

}  // namespace sightline
