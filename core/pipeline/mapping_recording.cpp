#include "core/pipeline/mapping_recording.h"

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "core/common/text_file.h"
#include "core/io/dataset.h"
#include "core/pipeline/mapping_pipeline.h"

namespace sightline {

namespace {

// "  sim.motion.camera_forward_m: 0.1" in a simulator's scene.yaml.
std::optional<double> CameraForwardFromSceneYaml(const std::string& path) {
  std::ifstream in(path);
  std::string line;
  while (std::getline(in, line)) {
    const size_t key = line.find("motion.camera_forward_m:");
    if (key == std::string::npos) continue;
    char* end = nullptr;
    const std::string value = line.substr(line.find(':', key) + 1);
    const double v = std::strtod(value.c_str(), &end);
    if (end != value.c_str() && std::isfinite(v)) return v;
  }
  return std::nullopt;
}

}  // namespace

std::string MappingRecordingRoot(const std::string& path) {
  namespace fs = std::filesystem;
  if (!DetectDataset(path)) return path;  // A recording with sensor sub-folders.
  std::string parent = fs::path(path).lexically_normal().parent_path().string();
  for (const char* name : {"odometry.txt", "walls.csv", "people.csv", "scene.yaml"}) {
    if (!parent.empty() && FileExists(JoinPath(parent, name))) return parent;
  }
  return path;
}

StatusOr<MappingRecording> LoadMappingRecording(const PipelineSource& source,
                                                const MappingRunOptions& run) {
  const SourceInfo& info = source.info;
  MappingRecording recording;
  if (info.rgbd) {
    recording.camera = info.rgbd->color;
  } else if (info.camera) {
    recording.camera = *info.camera;
  } else {
    return FailedPrecondition(info.path + ": the RGB-D source has no camera intrinsics");
  }
  recording.root = MappingRecordingRoot(info.path);
  const std::string& root = recording.root;
  if (const std::string path = JoinPath(root, "odometry.txt"); FileExists(path)) {
    StatusOr<Trajectory> read = ReadTumTrajectory(path);
    if (!read.ok()) return read.status();
    recording.odometry = std::move(*read);
    recording.log_lines.push_back("pose source: wheel odometry " + path);
  } else if (source.odometry) {
    recording.odometry = *source.odometry;
    recording.log_lines.push_back("pose source: the recording's odometry (" +
                                  std::to_string(source.odometry->size()) + " poses)");
  } else if (source.live_odometry) {
    recording.live_odometry = source.live_odometry;
    recording.log_lines.push_back(
        "pose source: the live source's odometry at each frame (ros:// tf odom_frame -> "
        "base_frame)");
  } else {
    recording.log_lines.push_back(
        "pose source: none (no odometry.txt, no odometry in the recording); heading from walls "
        "only");
  }
  if (const std::string path = JoinPath(root, "people.csv"); FileExists(path)) {
    StatusOr<PersonBoxTable> read = PersonBoxTable::Read(path);
    if (!read.ok()) return read.status();
    recording.people = std::move(*read);
    recording.people->SetImageSize(cv::Size(recording.camera.width, recording.camera.height));
    recording.log_lines.push_back("ground-truth person boxes available: " + path);
  }
  if (const std::string path = JoinPath(root, "walls.csv"); FileExists(path)) {
    StatusOr<std::vector<TrueWall>> read = ReadWallsCsv(path);
    if (!read.ok()) return read.status();
    recording.walls = std::move(*read);
  }
  recording.camera_forward_m = run.camera_forward_m;
  if (run.camera_offset_from_scene) {
    if (auto v = CameraForwardFromSceneYaml(JoinPath(root, "scene.yaml"))) {
      recording.camera_forward_m = *v;
    }
  }
  return recording;
}

MappingInput MappingRecording::MakeInput(const RgbdFrame& frame, double tolerance_s) const {
  MappingInput input;
  input.stamp = frame.stamp;
  input.depth_m = frame.depth_m;
  input.color = frame.color;
  const Trajectory* poses = odometry ? &*odometry : live_odometry ? live_odometry() : nullptr;
  if (poses != nullptr) {
    if (auto i = poses->Nearest(frame.stamp.sensor_time_s, tolerance_s)) {
      Pose2d pose = Pose2d::FromIsometry(poses->poses()[*i].world_from_sensor);
      pose.x += camera_forward_m * std::cos(pose.heading_rad);
      pose.y += camera_forward_m * std::sin(pose.heading_rad);
      input.odometry = pose;
    }
  }
  if (people) input.people = people->ForFrame(frame.stamp.sequence_id);
  return input;
}

}  // namespace sightline
