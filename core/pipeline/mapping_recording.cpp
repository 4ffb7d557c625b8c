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
                                                const MappingRunOptions& run,
                                                const std::string& pose_source) {
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
  std::string found;  // The recording's odometry, for the log.
  if (const std::string path = JoinPath(root, "odometry.txt"); FileExists(path)) {
    StatusOr<Trajectory> read = ReadTumTrajectory(path);
    if (!read.ok()) return read.status();
    recording.odometry = std::move(*read);
    found = "wheel odometry " + path;
  } else if (source.odometry) {
    recording.odometry = *source.odometry;
    found = "the recording's odometry (" + std::to_string(source.odometry->size()) + " poses)";
  } else if (source.live_odometry) {
    recording.live_odometry = source.live_odometry;
    found = "the live source's odometry at each frame (ros:// tf odom_frame -> base_frame)";
  }
  const std::string asked = " (mapping.pose.source=" + pose_source + ")";
  if (!found.empty() && (pose_source == "auto" || pose_source == "recording")) {
    recording.pose_source = "recording";
    recording.log_lines.push_back("pose source: " + found);
  } else if (pose_source == "recording") {
    return FailedPrecondition(
        "mapping.pose.source=recording, but " + root +
        " has no odometry.txt and the source carries no odometry; use auto or rgbd");
  } else {
    recording.odometry.reset();
    recording.live_odometry = nullptr;
    recording.pose_source = pose_source;
    const std::string unused = found.empty() ? "" : "; not used: " + found;
    if (pose_source == "none") {
      recording.log_lines.push_back("pose source: none" + asked + "; heading from walls only" +
                                    unused);
    } else {
      recording.log_lines.push_back(
          "pose source: RGB-D odometry on the frames" + asked +
          (found.empty() ? "; no odometry.txt, no odometry in the recording" : unused));
    }
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
