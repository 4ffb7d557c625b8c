#include "core/button/hand_eye.h"

#include <array>
#include <cmath>

#include "core/common/text_file.h"

namespace sightline {

namespace {

struct Partial {
  std::optional<Eigen::Vector3d> translation;
  std::optional<Eigen::Quaterniond> rotation;
};

// "key: [a, b, c]" -> the numbers (brackets and commas removed).
StatusOr<std::vector<double>> Numbers(const DataLine& line, size_t count, const std::string& path) {
  std::string text = line.text.substr(line.text.find(':') + 1);
  for (char& c : text) {
    if (c == '[' || c == ']') c = ' ';
  }
  auto numbers = ParseNumbers(DataLine{line.number, text}, count, path);
  if (numbers.ok() && numbers->size() != count) {
    return ParseError(path + " line " + std::to_string(line.number) + ": expected " +
                      std::to_string(count) + " numbers");
  }
  return numbers;
}

StatusOr<Eigen::Isometry3d> ToPose(const Partial& p, const std::string& key,
                                   const std::string& path) {
  if (!p.translation || !p.rotation) {
    return ParseError(path + ": '" + key + "' needs translation and quaternion_xyzw");
  }
  if (std::abs(p.rotation->norm() - 1.0) > 1e-3) {
    return ParseError(path + ": '" + key + "' quaternion is not unit length");
  }
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.linear() = p.rotation->normalized().toRotationMatrix();
  pose.translation() = *p.translation;
  return pose;
}

}  // namespace

StatusOr<HandEye> ReadHandEyeFile(const std::string& path) {
  if (!FileExists(path)) return NotFound("hand-eye file '" + path + "' not found");
  auto lines = ReadDataLines(path);
  if (!lines.ok()) return lines.status();
  std::optional<Partial> ee, base;
  Partial* current = nullptr;
  for (const DataLine& line : *lines) {
    const size_t start = line.text.find_first_not_of(' ');
    const std::string text = line.text.substr(start);
    if (text.rfind("end_effector_from_camera:", 0) == 0) {
      current = &ee.emplace();
    } else if (text.rfind("world_from_base:", 0) == 0) {
      current = &base.emplace();
    } else if (text.rfind("translation:", 0) == 0 && current) {
      auto n = Numbers(line, 3, path);
      if (!n.ok()) return n.status();
      current->translation = Eigen::Vector3d((*n)[0], (*n)[1], (*n)[2]);
    } else if (text.rfind("quaternion_xyzw:", 0) == 0 && current) {
      auto n = Numbers(line, 4, path);
      if (!n.ok()) return n.status();
      current->rotation = Eigen::Quaterniond((*n)[3], (*n)[0], (*n)[1], (*n)[2]);
    } else {
      return ParseError(path + " line " + std::to_string(line.number) + ": unexpected '" + text +
                        "'");
    }
  }
  if (!ee) return ParseError(path + ": no 'end_effector_from_camera'");
  HandEye out;
  auto camera = ToPose(*ee, "end_effector_from_camera", path);
  if (!camera.ok()) return camera.status();
  out.end_effector_from_camera = *camera;
  if (base) {
    auto world_from_base = ToPose(*base, "world_from_base", path);
    if (!world_from_base.ok()) return world_from_base.status();
    out.world_from_base = *world_from_base;
  }
  return out;
}

}  // namespace sightline
