#include "tests/ros/ros_test_util.h"

#include <filesystem>
#include <fstream>
#include <sstream>

namespace sightline::testing {

namespace {

std::string Simulate(const std::string& name, const std::string& args) {
  const std::string dir = TempDir("ros_" + name) + "/rec";
  if (std::filesystem::exists(dir + "/scene.yaml")) return dir;
  const ProcessResult r = RunProcess(CliPath() + " simulate corridor --out " + dir + " " + args);
  return r.exit_code == 0 ? dir : "";
}

}  // namespace

std::string CorridorRgbd() {
  static const std::string dir =
      Simulate("corridor_rgbd",
               "--frames 30 --seed 3 --sensors rgbd --quiet --set sim.rgbd.resolution=320x240"
               " --set sim.rate_hz=5 --set sim.motion.speed_mps=1");
  return dir;
}

std::string CorridorStereo() {
  static const std::string dir = Simulate(
      "corridor_stereo",
      "--frames 30 --seed 2 --sensors stereo --quiet --set sim.rate_hz=10"
      " --set sim.stereo.width=376 --set sim.stereo.height=240 --set sim.stereo.focal_px=229");
  return dir;
}

MapServerMap ReadMapServerMap(const std::string& dir) {
  MapServerMap map;
  std::ifstream pgm(dir + "/map.pgm", std::ios::binary);
  std::string magic;
  pgm >> magic;
  if (magic != "P5") return map;
  pgm >> std::ws;
  while (pgm.peek() == '#') {
    std::string comment;
    std::getline(pgm, comment);
  }
  int width = 0, height = 0, maxval = 0;
  pgm >> width >> height >> maxval;
  pgm.get();
  cv::Mat gray(height, width, CV_8UC1);
  pgm.read(reinterpret_cast<char*>(gray.data), static_cast<std::streamsize>(width) * height);
  if (!pgm) return map;
  std::ifstream yaml(dir + "/map.yaml");
  std::string line;
  while (std::getline(yaml, line)) {
    std::istringstream in(line.substr(line.find(':') + 1));
    if (line.rfind("resolution:", 0) == 0) in >> map.resolution;
    if (line.rfind("occupied_thresh:", 0) == 0) in >> map.occupied_thresh;
    if (line.rfind("free_thresh:", 0) == 0) in >> map.free_thresh;
    if (line.rfind("origin:", 0) == 0) {
      char c = 0;
      in >> c >> map.origin.x() >> c >> map.origin.y();
    }
  }
  map.gray = gray;
  return map;
}

std::map<double, Eigen::Matrix<double, 7, 1>> ReadTumTrajectory(const std::string& path) {
  std::map<double, Eigen::Matrix<double, 7, 1>> rows;
  std::ifstream in(path);
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream row(line);
    double t = 0;
    Eigen::Matrix<double, 7, 1> v;
    row >> t;
    for (int i = 0; i < 7; ++i) row >> v[i];
    if (row) rows[t] = v;
  }
  return rows;
}

}  // namespace sightline::testing
