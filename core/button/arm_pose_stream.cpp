#include "core/button/arm_pose_stream.h"

#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <map>

#include "core/button/flat_json.h"
#include "core/button/option_check.h"

namespace sightline {

using button_internal::Invalid;

bool ArmPoseStreamOptions::IsValid(std::string* error) const {
  if (max_joints < 0) return Invalid(error, "button.arm_pose.max_joints must be >= 0");
  if (!(max_position_m > 0)) return Invalid(error, "button.arm_pose.max_position_m must be > 0");
  if (!(max_rate_hz > 0)) return Invalid(error, "button.arm_pose.max_rate_hz must be > 0");
  if (!std::isfinite(clock_offset_s))
    return Invalid(error, "button.arm_pose.clock_offset_s must be finite");
  if (!(max_gap_s > 0)) return Invalid(error, "button.arm_pose.max_gap_s must be > 0");
  if (!(keep_s > 0)) return Invalid(error, "button.arm_pose.keep_s must be > 0");
  if (!(wait_s >= 0 && wait_s <= 60))
    return Invalid(error, "button.arm_pose.wait_s must lie in [0, 60]");
  return true;
}

OptionTable<ArmPoseStreamOptions> ArmPoseStreamOptions::Describe() {
  using O = ArmPoseStreamOptions;
  return OptionTable<O>("button.arm_pose")
      .Int("max_joints", &O::max_joints, "", 0, 64, 1,
           "An arm_pose message with more joint positions is refused.")
      .Double("max_position_m", &O::max_position_m, "m", 0.1, 100, 0.1,
              "An arm_pose position farther than this from the base is refused.")
      .Double("max_rate_hz", &O::max_rate_hz, "Hz", 1, 10000, 10,
              "arm_pose messages closer than 1/this in the arm's time are dropped (counted).")
      .Double("clock_offset_s", &O::clock_offset_s, "s", -1e9, 1e9, 0.001,
              "The arm's clock minus the camera's (configured; arm stamp = frame stamp + this).")
      .Double("max_gap_s", &O::max_gap_s, "s", 0.001, 10, 0.005,
              "No pose is interpolated across a larger gap between two arm_pose messages.")
      .Double("keep_s", &O::keep_s, "s", 0.1, 600, 0.5,
              "arm_pose messages older than this behind the newest are forgotten.")
      .Double("wait_s", &O::wait_s, "s", 0, 60, 0.05,
              "A camera frame newer than the newest arm pose waits at most this long (host "
              "clock) for the pose that covers its stamp; then it has no arm pose.");
}

namespace {

using Value = FlatJsonValue;

// The finite numeric array `key` of `size` numbers (any size when `size` < 0).
StatusOr<std::vector<double>> Numbers(const std::map<std::string, Value>& m, const std::string& key,
                                      int size) {
  auto it = m.find(key);
  if (it == m.end() || it->second.kind != Value::kArray) {
    return InvalidArgument("arm_pose: \"" + key + "\" must be an array of numbers");
  }
  const std::vector<double>& a = it->second.array;
  if (size >= 0 && int(a.size()) != size) {
    return InvalidArgument("arm_pose: \"" + key + "\" needs " + std::to_string(size) + " numbers");
  }
  for (double x : a) {
    if (!std::isfinite(x)) return InvalidArgument("arm_pose: \"" + key + "\" is not finite");
  }
  return a;
}

}  // namespace

StatusOr<ArmPoseMessage> ParseArmPoseLine(const std::string& line,
                                          const ArmPoseStreamOptions& options) {
  std::map<std::string, Value> m;
  FlatJsonRules rules;
  rules.prefix = "arm_pose: ";
  rules.max_array = 64;
  rules.escapes = false;
  rules.not_object = "expected one JSON object";
  SIGHTLINE_RETURN_IF_ERROR(ReadFlatJson(line, rules, &m));
  auto type = m.find("type");
  if (type == m.end() || type->second.kind != Value::kString || type->second.text != "arm_pose")
    return InvalidArgument("arm_pose: \"type\" must be \"arm_pose\"");
  auto stamp = m.find("stamp");
  if (stamp == m.end() || stamp->second.kind != Value::kNumber ||
      !std::isfinite(stamp->second.number) || stamp->second.number < 0) {
    return InvalidArgument("arm_pose: \"stamp\" must be a finite number >= 0 (seconds)");
  }
  StatusOr<std::vector<double>> p = Numbers(m, "position_m", 3);
  if (!p.ok()) return p.status();
  StatusOr<std::vector<double>> q = Numbers(m, "quaternion_xyzw", 4);
  if (!q.ok()) return q.status();
  const Eigen::Vector3d position((*p)[0], (*p)[1], (*p)[2]);
  if (position.norm() > options.max_position_m)
    return InvalidArgument("arm_pose: \"position_m\" beyond button.arm_pose.max_position_m");
  Eigen::Quaterniond quaternion((*q)[3], (*q)[0], (*q)[1], (*q)[2]);
  if (std::abs(quaternion.norm() - 1) > 0.1)
    return InvalidArgument("arm_pose: \"quaternion_xyzw\" is not a unit quaternion");
  ArmPoseMessage out;
  out.stamp_s = stamp->second.number;
  out.base_from_end_effector = Eigen::Translation3d(position) * quaternion.normalized();
  if (m.count("joints")) {
    StatusOr<std::vector<double>> joints = Numbers(m, "joints", -1);
    if (!joints.ok()) return joints.status();
    if (int(joints->size()) > options.max_joints)
      return InvalidArgument("arm_pose: more \"joints\" than button.arm_pose.max_joints");
    out.joints = std::move(*joints);
  }
  return out;
}

bool KeepsRate(double previous_s, double stamp_s, double max_rate_hz) {
  return stamp_s >= previous_s + 1.0 / max_rate_hz - kStampResolutionS;
}

std::string ArmPoseLine(const ArmPoseMessage& pose) {
  const Eigen::Vector3d p = pose.base_from_end_effector.translation();
  const Eigen::Quaterniond q(pose.base_from_end_effector.linear());
  char text[320];
  std::snprintf(text, sizeof(text),
                "{\"type\":\"arm_pose\",\"stamp\":%.6f,\"position_m\":[%.9f,%.9f,%.9f],"
                "\"quaternion_xyzw\":[%.9f,%.9f,%.9f,%.9f]",
                pose.stamp_s, p.x(), p.y(), p.z(), q.x(), q.y(), q.z(), q.w());
  std::string line = text;
  if (!pose.joints.empty()) {
    line += ",\"joints\":[";
    for (size_t i = 0; i < pose.joints.size(); ++i) {
      std::snprintf(text, sizeof(text), "%s%.9g", i ? "," : "", pose.joints[i]);
      line += text;
    }
    line += "]";
  }
  return line + "}";
}

bool ArmPoseBuffer::Add(const ArmPoseMessage& pose) {
  if (!poses_.empty() && !KeepsRate(poses_.back().stamp_s, pose.stamp_s, options_.max_rate_hz)) {
    ++dropped_;
    return false;
  }
  poses_.push_back(pose);
  while (poses_.front().stamp_s < pose.stamp_s - options_.keep_s) poses_.pop_front();
  return true;
}

std::optional<Eigen::Isometry3d> ArmPoseBuffer::At(double camera_stamp_s) const {
  double t = camera_stamp_s + options_.clock_offset_s;
  if (poses_.empty()) return std::nullopt;
  // Up to a microsecond (the stamps' resolution) outside the span counts as its end.
  if (t < poses_.front().stamp_s && t >= poses_.front().stamp_s - kStampResolutionS)
    t = poses_.front().stamp_s;
  if (t > poses_.back().stamp_s && t <= poses_.back().stamp_s + kStampResolutionS)
    t = poses_.back().stamp_s;
  if (t < poses_.front().stamp_s || t > poses_.back().stamp_s) return std::nullopt;
  size_t hi = 0;
  while (poses_[hi].stamp_s < t) ++hi;
  if (poses_[hi].stamp_s == t) return poses_[hi].base_from_end_effector;
  const ArmPoseMessage& a = poses_[hi - 1];
  const ArmPoseMessage& b = poses_[hi];
  if (b.stamp_s - a.stamp_s > options_.max_gap_s) return std::nullopt;
  const double w = (t - a.stamp_s) / (b.stamp_s - a.stamp_s);
  const Eigen::Quaterniond qa(a.base_from_end_effector.linear());
  const Eigen::Quaterniond qb(b.base_from_end_effector.linear());
  const Eigen::Vector3d p =
      (1 - w) * a.base_from_end_effector.translation() + w * b.base_from_end_effector.translation();
  return Eigen::Isometry3d(Eigen::Translation3d(p) * qa.slerp(w, qb));
}

}  // namespace sightline
