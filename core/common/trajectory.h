// Timestamped poses and their TUM / KITTI file formats.
#pragma once

#include <Eigen/Geometry>
#include <optional>
#include <string>
#include <vector>

#include "core/common/status.h"

namespace sightline {

// One pose of a sensor in a fixed world frame at a time.
struct TimedPose {
  double time_s = 0;
  Eigen::Isometry3d world_from_sensor = Eigen::Isometry3d::Identity();
};

// A sequence of poses in increasing time. Copyable value type.
class Trajectory {
 public:
  Trajectory() = default;
  explicit Trajectory(std::vector<TimedPose> poses) : poses_(std::move(poses)) {}

  const std::vector<TimedPose>& poses() const { return poses_; }
  std::vector<TimedPose>& mutable_poses() { return poses_; }
  void Add(double time_s, const Eigen::Isometry3d& world_from_sensor) {
    poses_.push_back({time_s, world_from_sensor});
  }
  size_t size() const { return poses_.size(); }
  bool empty() const { return poses_.empty(); }

  // Index of the pose nearest in time to t, if within tolerance_s. Needs sorted times.
  std::optional<size_t> Nearest(double t, double tolerance_s) const;
  // Total path length in metres.
  double LengthM() const;
  // Time span in seconds (0 when fewer than two poses).
  double DurationS() const;

 private:
  std::vector<TimedPose> poses_;
};

// Pose files print rotations with a few digits: a 3x3 block is a rotation when every entry of
// R^T R - I is within this and det R within it of +1. A wrong matrix is off by far more.
inline constexpr double kPoseFileRotationTolerance = 1e-3;
// A pose file's quaternion is normalised when its length is within this of 1, else rejected.
inline constexpr double kPoseFileQuaternionTolerance = 0.1;

// Why `r` is not a rotation (a value not finite, R^T R off the identity by more than
// `tolerance`, det R not within `tolerance` of +1, a reflection), or nothing when it is one.
std::optional<std::string> RotationProblem(const Eigen::Matrix3d& r, double tolerance);

// The unit quaternion (w, x, y, z) of line `line` of pose file `path`: ParseError naming both
// when its length is not within kPoseFileQuaternionTolerance of 1 (a zero quaternion included).
StatusOr<Eigen::Quaterniond> PoseFileQuaternion(double w, double x, double y, double z,
                                                const std::string& path, int line);

// Reads "timestamp tx ty tz qx qy qz qw" lines ('#' comments). Errors name file and line: a
// value that is not a finite number, a quaternion that is not of unit length, a timestamp
// before the previous one.
StatusOr<Trajectory> ReadTumTrajectory(const std::string& path);
Status WriteTumTrajectory(const Trajectory& trajectory, const std::string& path);

// Reads KITTI poses (12 numbers per line: the top 3x4 of world_from_camera); a line whose 3x3
// block is not a rotation (kPoseFileRotationTolerance) or holds a value that is not finite is a
// ParseError naming file and line. Times are taken
// from `times_s` (which must then have one entry per pose), else set to index * period_s.
StatusOr<Trajectory> ReadKittiTrajectory(const std::string& path,
                                         const std::vector<double>& times_s = {},
                                         double period_s = 0.1);
Status WriteKittiTrajectory(const Trajectory& trajectory, const std::string& path);

}  // namespace sightline
