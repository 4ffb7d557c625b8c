#include "core/common/trajectory.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iomanip>
#include <sstream>

#include "core/common/text_file.h"

namespace sightline {

std::optional<size_t> Trajectory::Nearest(double t, double tolerance_s) const {
  if (poses_.empty()) return std::nullopt;
  auto it = std::lower_bound(poses_.begin(), poses_.end(), t,
                             [](const TimedPose& p, double time) { return p.time_s < time; });
  size_t best = poses_.size();
  double best_dt = tolerance_s;
  auto consider = [&](std::vector<TimedPose>::const_iterator c) {
    const double dt = std::abs(c->time_s - t);
    if (dt <= best_dt) {
      best_dt = dt;
      best = static_cast<size_t>(c - poses_.begin());
    }
  };
  if (it != poses_.end()) consider(it);
  if (it != poses_.begin()) consider(std::prev(it));
  if (best == poses_.size()) return std::nullopt;
  return best;
}

double Trajectory::LengthM() const {
  double length = 0;
  for (size_t i = 1; i < poses_.size(); ++i) {
    length +=
        (poses_[i].world_from_sensor.translation() - poses_[i - 1].world_from_sensor.translation())
            .norm();
  }
  return length;
}

double Trajectory::DurationS() const {
  return poses_.size() < 2 ? 0.0 : poses_.back().time_s - poses_.front().time_s;
}

std::optional<std::string> RotationProblem(const Eigen::Matrix3d& r, double tolerance) {
  char text[160];
  if (!r.allFinite()) return std::string("is not a rotation: it holds a value that is not finite");
  const double off = (r.transpose() * r - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff();
  if (!(off <= tolerance)) {
    std::snprintf(text, sizeof(text),
                  "is not a rotation: R^T R differs from the identity by %.10g (limit %.10g)", off,
                  tolerance);
    return std::string(text);
  }
  const double det = r.determinant();
  if (!(std::abs(det - 1) <= tolerance)) {
    std::snprintf(text, sizeof(text), "is not a rotation: its determinant is %.10g, not +1%s", det,
                  det < 0 ? " (a reflection)" : "");
    return std::string(text);
  }
  return std::nullopt;
}

StatusOr<Eigen::Quaterniond> PoseFileQuaternion(double w, double x, double y, double z,
                                                const std::string& path, int line) {
  const Eigen::Quaterniond q(w, x, y, z);
  const double norm = q.norm();
  if (!(std::abs(norm - 1.0) <= kPoseFileQuaternionTolerance)) {
    char text[160];
    std::snprintf(text, sizeof(text),
                  ": quaternion (qx qy qz qw) = (%.6g %.6g %.6g %.6g) has length %.6g, not 1 "
                  "(a rotation needs a unit quaternion)",
                  x, y, z, w, norm);
    return ParseError(path + " line " + std::to_string(line) + text);
  }
  return q.normalized();
}

StatusOr<Trajectory> ReadTumTrajectory(const std::string& path) {
  auto lines = ReadDataLines(path);
  if (!lines.ok()) return lines.status();
  Trajectory trajectory;
  for (const DataLine& line : *lines) {
    auto numbers = ParseNumbers(line, 8, path);
    if (!numbers.ok()) return numbers.status();
    if (numbers->size() != 8) {
      return ParseError(path + " line " + std::to_string(line.number) +
                        ": expected 8 numbers (t tx ty tz qx qy qz qw), found " +
                        std::to_string(numbers->size()));
    }
    const std::vector<double>& v = *numbers;
    StatusOr<Eigen::Quaterniond> q = PoseFileQuaternion(v[7], v[4], v[5], v[6], path, line.number);
    if (!q.ok()) return q.status();
    Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
    pose.linear() = q->toRotationMatrix();
    pose.translation() = Eigen::Vector3d(v[1], v[2], v[3]);
    if (!trajectory.empty()) {
      SIGHTLINE_RETURN_IF_ERROR(
          CheckTimeIncreases(trajectory.poses().back().time_s, v[0], path, line.number));
    }
    trajectory.Add(v[0], pose);
  }
  return trajectory;
}

Status WriteTumTrajectory(const Trajectory& trajectory, const std::string& path) {
  std::ofstream out(path);
  if (!out) return NotFound("cannot write " + path);
  out << "# timestamp tx ty tz qx qy qz qw\n" << std::fixed;
  for (const TimedPose& p : trajectory.poses()) {
    const Eigen::Quaterniond q(p.world_from_sensor.linear());
    const Eigen::Vector3d t = p.world_from_sensor.translation();
    out << std::setprecision(6) << p.time_s << std::setprecision(9) << ' ' << t.x() << ' ' << t.y()
        << ' ' << t.z() << ' ' << q.x() << ' ' << q.y() << ' ' << q.z() << ' ' << q.w() << '\n';
  }
  out.flush();
  if (!out) return Unavailable("write to " + path + " failed (disk full?)");
  return Status::Ok();
}

StatusOr<Trajectory> ReadKittiTrajectory(const std::string& path,
                                         const std::vector<double>& times_s, double period_s) {
  auto lines = ReadDataLines(path);
  if (!lines.ok()) return lines.status();
  if (!times_s.empty() && times_s.size() != lines->size()) {
    return InvalidArgument(path + " has " + std::to_string(lines->size()) + " poses but " +
                           std::to_string(times_s.size()) + " timestamps were given");
  }
  const bool use_times = !times_s.empty();
  Trajectory trajectory;
  for (size_t i = 0; i < lines->size(); ++i) {
    auto numbers = ParseNumbers((*lines)[i], 12, path);
    if (!numbers.ok()) return numbers.status();
    if (numbers->size() != 12) {
      return ParseError(path + " line " + std::to_string((*lines)[i].number) +
                        ": expected 12 numbers (3x4 pose), found " +
                        std::to_string(numbers->size()));
    }
    const std::vector<double>& v = *numbers;
    Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
    for (int r = 0; r < 3; ++r) {
      for (int c = 0; c < 3; ++c) pose.linear()(r, c) = v[r * 4 + c];
      pose.translation()(r) = v[r * 4 + 3];
    }
    if (std::optional<std::string> problem =
            RotationProblem(pose.linear(), kPoseFileRotationTolerance)) {
      return ParseError(path + " line " + std::to_string((*lines)[i].number) +
                        ": the 3x3 block (numbers 1-3, 5-7, 9-11) " + *problem);
    }
    trajectory.Add(use_times ? times_s[i] : static_cast<double>(i) * period_s, pose);
  }
  return trajectory;
}

Status WriteKittiTrajectory(const Trajectory& trajectory, const std::string& path) {
  std::ofstream out(path);
  if (!out) return NotFound("cannot write " + path);
  out << std::scientific << std::setprecision(9);
  for (const TimedPose& p : trajectory.poses()) {
    const Eigen::Matrix4d m = p.world_from_sensor.matrix();
    for (int r = 0; r < 3; ++r) {
      for (int c = 0; c < 4; ++c) out << (r == 0 && c == 0 ? "" : " ") << m(r, c);
    }
    out << '\n';
  }
  out.flush();
  if (!out) return Unavailable("write to " + path + " failed (disk full?)");
  return Status::Ok();
}

}  // namespace sightline
