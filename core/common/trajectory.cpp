#include "core/common/trajectory.h"

#include <algorithm>
#include <cmath>
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
    Eigen::Quaterniond q(v[7], v[4], v[5], v[6]);
    const double norm = q.norm();
    if (!(std::abs(norm - 1.0) < 0.1)) {
      return ParseError(path + " line " + std::to_string(line.number) + ": quaternion norm " +
                        std::to_string(norm) + " is not 1");
    }
    Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
    pose.linear() = q.normalized().toRotationMatrix();
    pose.translation() = Eigen::Vector3d(v[1], v[2], v[3]);
    if (!trajectory.empty() && v[0] < trajectory.poses().back().time_s) {
      return ParseError(path + " line " + std::to_string(line.number) +
                        ": timestamps must increase");
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
