#include "app/cli/simulate_bag.h"

#include "core/sim/simulator.h"

#ifdef SIGHTLINE_HAVE_ROS
#include "core/ros/bag_writer.h"
#endif

namespace sightline::cli {

#ifdef SIGHTLINE_HAVE_ROS
namespace {

constexpr double kEpochS = 1.0;

// Writes frame `i` of `sensor` and its true pose; counts the messages.
Status WriteSensorFrame(sim::Simulator& simulator, const std::string& sensor, int i, BagWriter& bag,
                        int64_t* messages) {
  const double t = kEpochS + simulator.TimeOf(i);
  if (sensor == "rgbd") {
    sim::SimulatedRgbd f;
    SIGHTLINE_RETURN_IF_ERROR(simulator.RenderRgbd(i, &f));
    SIGHTLINE_RETURN_IF_ERROR(bag.WriteRgbdFrame(t, f.color, f.depth_m, simulator.rgbd_camera()));
    *messages += 4;
    return bag.WriteTransform(t, "world", BagWriter::kRgbdFrameId, f.world_from_camera);
  }
  if (sensor == "stereo") {
    sim::SimulatedStereo f;
    SIGHTLINE_RETURN_IF_ERROR(simulator.RenderStereo(i, &f));
    SIGHTLINE_RETURN_IF_ERROR(bag.WriteStereoFrame(t, f.left, f.right, simulator.stereo_rig()));
    *messages += 5;
    return bag.WriteTransform(t, "world", BagWriter::kLeftFrameId, f.world_from_left);
  }
  sim::SimulatedMono f;
  SIGHTLINE_RETURN_IF_ERROR(simulator.RenderMono(i, &f));
  SIGHTLINE_RETURN_IF_ERROR(bag.WriteMonoFrame(t, f.image, simulator.mono_camera()));
  *messages += 3;
  return bag.WriteTransform(t, "world", BagWriter::kMonoFrameId, f.world_from_camera);
}

// Wheel odometry on /odom and the arm's reported poses on /tf.
Status WriteBodyPoses(const sim::Simulator& simulator, BagWriter& bag, int64_t* messages) {
  const Trajectory odometry = simulator.WheelOdometry();
  const Trajectory arm = simulator.ArmPoses();
  for (const TimedPose& p : odometry.poses()) {
    SIGHTLINE_RETURN_IF_ERROR(
        bag.WriteOdometry("/odom", kEpochS + p.time_s, p.world_from_sensor, "odom", "base_link"));
    ++*messages;
  }
  for (const TimedPose& p : arm.poses()) {
    SIGHTLINE_RETURN_IF_ERROR(
        bag.WriteTransform(kEpochS + p.time_s, "base_link", "end_effector", p.world_from_sensor));
    ++*messages;
  }
  return Status::Ok();
}

}  // namespace

StatusOr<SimulatedBag> SimulateToBag(const sim::SimulationOptions& options, const std::string& path,
                                     const std::function<void(int64_t, int64_t)>& progress,
                                     const std::atomic<bool>* cancel) {
  StatusOr<std::vector<std::string>> sensors = options.SensorList();
  if (!sensors.ok()) return sensors.status();
  StatusOr<sim::Simulator> simulator = sim::Simulator::Create(options);
  if (!simulator.ok()) return simulator.status();
  StatusOr<std::unique_ptr<BagWriter>> bag = BagWriter::Create(path);
  if (!bag.ok()) return bag.status();
  SimulatedBag out;
  out.path = path;
  for (int i = 0; i < simulator->frames(); ++i) {
    if (cancel != nullptr && cancel->load()) {
      return Cancelled("simulation cancelled after " + std::to_string(i) + " frames");
    }
    for (const std::string& sensor : *sensors) {
      SIGHTLINE_RETURN_IF_ERROR(WriteSensorFrame(*simulator, sensor, i, **bag, &out.messages));
    }
    out.frames = i + 1;
    if (progress) progress(i + 1, simulator->frames());
  }
  SIGHTLINE_RETURN_IF_ERROR(WriteBodyPoses(*simulator, **bag, &out.messages));
  SIGHTLINE_RETURN_IF_ERROR((*bag)->Close());
  return out;
}
#else
StatusOr<SimulatedBag> SimulateToBag(const sim::SimulationOptions&, const std::string&,
                                     const std::function<void(int64_t, int64_t)>&,
                                     const std::atomic<bool>*) {
  return Unavailable("simulate --format bag needs a build with SIGHTLINE_WITH_ROS=ON");
}
#endif

}  // namespace sightline::cli
