// Helpers of the ROS tests: simulated recordings made with sightline-cli, map_server files.
#pragma once

#include <Eigen/Core>
#include <map>
#include <opencv2/core.hpp>
#include <string>

#include "tests/app/process.h"
#include "tests/support/test_data.h"

namespace sightline::testing {

inline const std::string& CliPath() {
  static const std::string path = std::string(SIGHTLINE_BIN_DIR) + "/sightline-cli";
  return path;
}
inline const std::string& NodePath() {
  static const std::string path = std::string(SIGHTLINE_BIN_DIR) + "/sightline-node";
  return path;
}

// A 30-frame corridor drive (RGB-D 320x240 at 5 Hz), made once per process; "" on failure.
std::string CorridorRgbd();
// A 30-frame corridor drive seen by a 376x240 stereo rig at 10 Hz, made once per process.
std::string CorridorStereo();

// A map_server map: the PGM image and the YAML's resolution, origin and thresholds.
struct MapServerMap {
  cv::Mat gray;
  double resolution = 0;
  Eigen::Vector2d origin = Eigen::Vector2d::Zero();
  double occupied_thresh = 0, free_thresh = 0;
};
// Reads DIR/map.pgm and DIR/map.yaml; an empty gray image when either is missing.
MapServerMap ReadMapServerMap(const std::string& dir);

// TUM trajectory rows (timestamp -> tx ty tz qx qy qz qw) of a trajectory.txt.
std::map<double, Eigen::Matrix<double, 7, 1>> ReadTumTrajectory(const std::string& path);

}  // namespace sightline::testing
