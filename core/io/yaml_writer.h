// Writing the calibration files (camera.yaml, stereo calibration, hand_eye.yaml, the floor file)
// as YAML that both Sightline's readers and OpenCV's cv::FileStorage read: an optional
// "%YAML:1.0" first line, '#' comments, flow lists and OpenCV matrices (!!opencv-matrix maps).
// Numbers are written with the fewest of 15 to 17 significant digits that read back exactly.
#pragma once

#include <Eigen/Core>
#include <sstream>
#include <string>
#include <vector>

#include "core/common/status.h"

namespace sightline {

// Comment lines a writer puts before the content (header) and after it (footer), for people;
// the readers skip them.
struct FileComments {
  std::vector<std::string> header;
  std::vector<std::string> footer;
};

// Builds the text of a YAML file, then writes it in one go.
class YamlWriter {
 public:
  // `opencv_header`: start with "%YAML:1.0" and "---", which cv::FileStorage needs.
  explicit YamlWriter(bool opencv_header);

  void Comments(const std::vector<std::string>& lines);
  // "key: value" at the given indentation (two spaces per level).
  void Number(const std::string& key, double value, int indent = 0);
  void Integer(const std::string& key, long long value, int indent = 0);
  void Text(const std::string& key, const std::string& value, int indent = 0);
  // "key:" opening a nested map.
  void Map(const std::string& key, int indent = 0);
  // "key: [a, b, c]".
  void List(const std::string& key, const std::vector<double>& values, int indent = 0);
  // An OpenCV matrix (rows, cols, dt: d, data).
  void Matrix(const std::string& key, const Eigen::MatrixXd& m);

  // Writes the text to `path`. Unavailable naming the file when it cannot be written.
  Status WriteTo(const std::string& path) const;

  // A number that reads back exactly, always with a '.' or an exponent (a float to OpenCV).
  static std::string Format(double value);

 private:
  std::ostringstream text_;
};

}  // namespace sightline
