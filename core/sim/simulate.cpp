#include "core/sim/simulate.h"

#include <algorithm>
#include <chrono>
#include <memory>

#include "core/common/text_file.h"
#include "core/sim/ground_truth_files.h"
#include "core/sim/observations.h"
#include "core/sim/recording_writer.h"
#include "core/sim/simulator.h"

namespace sightline::sim {
namespace {

double Now() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

bool Has(const std::vector<std::string>& list, const std::string& name) {
  return std::find(list.begin(), list.end(), name) != list.end();
}

}  // namespace

StatusOr<SimulationSummary> Simulate(const SimulationOptions& options, const std::string& dir,
                                     const SimulationCallbacks& callbacks) {
  const double start = Now();
  StatusOr<Simulator> created = Simulator::Create(options);
  if (!created.ok()) return created.status();
  Simulator& sim = *created;
  const std::vector<std::string> sensors = *options.SensorList();
  const Scene& scene = sim.scene();

  RecordingSetup setup;
  setup.dir = dir;
  setup.rate_hz = options.rate_hz;
  setup.png_compression = options.png_compression;
  if (Has(sensors, "rgbd")) setup.rgbd_camera = sim.rgbd_camera();
  setup.rgbd_max_depth_m = options.rgbd.max_depth_m;
  if (Has(sensors, "stereo")) setup.stereo_rig = sim.stereo_rig();
  if (Has(sensors, "mono")) setup.mono_camera = sim.mono_camera();
  auto writer = RecordingWriter::Create(setup);
  if (!writer.ok()) return writer.status();

  SimulationSummary summary;
  summary.dir = dir;
  summary.scene = scene.name();
  summary.motion = sim.motion().kind;
  summary.sensors = sensors;
  // The camera the per-frame annotations refer to: mono for arm scenes, else the first sensor.
  SceneRecord record;
  record.sensors = sensors;
  record.motion = summary.motion;
  record.annotated_camera = Has(sensors, "mono") && scene.hints.target_button >= 0 ? "mono"
                            : Has(sensors, "rgbd")                                 ? "rgbd"
                            : Has(sensors, "stereo")                               ? "stereo"
                                                                                   : "mono";
  std::vector<std::string> files;
  auto add_file = [&](const std::string& name, Status status) -> Status {
    if (status.ok()) files.push_back(name);
    return status;
  };
  if (!scene.walls.empty()) {
    SIGHTLINE_RETURN_IF_ERROR(
        add_file("walls.csv", WriteWallsCsv(scene, JoinPath(dir, "walls.csv"))));
  }
  if (!scene.regions.empty()) {
    SIGHTLINE_RETURN_IF_ERROR(
        add_file("regions.csv", WriteRegionsCsv(scene, JoinPath(dir, "regions.csv"))));
  }
  ObservationWriter observations;
  SIGHTLINE_RETURN_IF_ERROR(observations.Open(dir, !scene.buttons.empty(), !scene.people.empty()));
  if (!scene.buttons.empty()) files.push_back("buttons.csv");
  if (!scene.people.empty()) files.push_back("people.csv");

  SimulatedRgbd rgbd;
  SimulatedStereo stereo;
  SimulatedMono mono;
  double render_s = 0;
  Status stopped = Status::Ok();
  int done = 0;
  for (int i = 0; i < sim.frames(); ++i) {
    if (callbacks.cancel != nullptr && callbacks.cancel->load()) {
      stopped = Cancelled("simulation stopped after " + std::to_string(done) + " frames");
      break;
    }
    const double t = sim.TimeOf(i);
    const RenderedView* annotated = nullptr;
    PinholeCamera annotated_camera;
    Eigen::Isometry3d annotated_pose;
    for (const std::string& sensor : sensors) {
      const double r0 = Now();
      if (sensor == "rgbd") {
        SIGHTLINE_RETURN_IF_ERROR(sim.RenderRgbd(i, &rgbd));
      } else if (sensor == "stereo") {
        SIGHTLINE_RETURN_IF_ERROR(sim.RenderStereo(i, &stereo));
      } else {
        SIGHTLINE_RETURN_IF_ERROR(sim.RenderMono(i, &mono));
      }
      render_s += Now() - r0;
      if (sensor == "rgbd") {
        SIGHTLINE_RETURN_IF_ERROR(
            (*writer)->WriteRgbd(i, t, rgbd.color, rgbd.depth_m, rgbd.world_from_camera));
      } else if (sensor == "stereo") {
        SIGHTLINE_RETURN_IF_ERROR(
            (*writer)->WriteStereo(i, t, stereo.left, stereo.right, stereo.world_from_left));
      } else {
        SIGHTLINE_RETURN_IF_ERROR((*writer)->WriteMono(i, t, mono.image, mono.world_from_camera));
      }
      if (sensor == record.annotated_camera) {
        if (sensor == "rgbd") {
          annotated = &rgbd.view, annotated_camera = sim.rgbd_camera();
          annotated_pose = rgbd.world_from_camera;
        } else if (sensor == "stereo") {
          annotated = &stereo.left_view, annotated_camera = sim.stereo_rig().left;
          annotated_pose = stereo.world_from_left;
        } else {
          annotated = &mono.view, annotated_camera = sim.mono_camera();
          annotated_pose = mono.world_from_camera;
        }
      }
    }
    if (annotated != nullptr) {
      SIGHTLINE_RETURN_IF_ERROR(
          observations.Write(ObserveButtons(scene, annotated_camera, annotated_pose, *annotated, i),
                             ObservePeople(scene, *annotated, i)));
    }
    ++done;
    if (callbacks.progress) callbacks.progress(done, sim.frames());
  }
  SIGHTLINE_RETURN_IF_ERROR(observations.Close());
  SIGHTLINE_RETURN_IF_ERROR((*writer)->Close());

  // Trajectories of the sensor carrier, truncated to the frames written.
  auto truncated = [&](Trajectory t) {
    t.mutable_poses().resize(std::min<size_t>(t.size(), done));
    return t;
  };
  SIGHTLINE_RETURN_IF_ERROR(add_file(
      "body_groundtruth.txt",
      WriteTumTrajectory(truncated(sim.BodyGroundTruth()), JoinPath(dir, "body_groundtruth.txt"))));
  if (sim.motion().is_robot()) {
    SIGHTLINE_RETURN_IF_ERROR(add_file(
        "odometry.txt",
        WriteTumTrajectory(truncated(sim.WheelOdometry()), JoinPath(dir, "odometry.txt"))));
  }
  if (sim.motion().is_arm()) {
    SIGHTLINE_RETURN_IF_ERROR(
        add_file("arm_poses.txt",
                 WriteTumTrajectory(truncated(sim.ArmPoses()), JoinPath(dir, "arm_poses.txt"))));
    SIGHTLINE_RETURN_IF_ERROR(
        add_file("hand_eye.yaml",
                 WriteHandEyeYaml(sim.motion().body_from_camera, sim.motion().world_from_arm_base,
                                  JoinPath(dir, "hand_eye.yaml"))));
  }
  record.frames_written = done;
  SIGHTLINE_RETURN_IF_ERROR(
      add_file("scene.yaml", WriteSceneYaml(options, scene, record, JoinPath(dir, "scene.yaml"))));

  summary.frames = done;
  summary.images = (*writer)->images_written();
  summary.files = (*writer)->Files();
  summary.files.insert(summary.files.end(), files.begin(), files.end());
  summary.render_s = render_s;
  summary.total_s = Now() - start;
  summary.render_fps = render_s > 0 ? done / render_s : 0;
  if (!stopped.ok()) return stopped;
  return summary;
}

}  // namespace sightline::sim
