#include "tests/core/mono/mono_test_util.h"

#include <algorithm>
#include <limits>

#include "core/eval/evaluation.h"
#include "core/sim/simulator.h"

namespace sightline::testing {

namespace {

// Frames [0, frames) of `simulator`'s mono camera with their true poses.
StatusOr<MonoSequence> RenderMonoFrames(sim::Simulator* simulator, int frames) {
  MonoSequence out;
  out.camera = simulator->mono_camera();
  for (int i = 0; i < frames; ++i) {
    sim::SimulatedMono mono;
    SIGHTLINE_RETURN_IF_ERROR(simulator->RenderMono(i, &mono));
    MonoFrame frame;
    frame.stamp.sequence_id = i;
    frame.stamp.sensor_time_s = simulator->TimeOf(i);
    frame.image = mono.image;
    out.frames.push_back(frame);
    out.ground_truth.Add(frame.stamp.sensor_time_s, mono.world_from_camera);
  }
  return out;
}

}  // namespace

StatusOr<PanelSequence> RenderPanel(int frames, double sideways_m) {
  sim::SimulationOptions options = sim::SimulationOptions::ForScene("panel");
  // The 150-frame approach of the panel scene; only the first `frames` are rendered.
  options.arm.sideways_m = sideways_m;
  StatusOr<sim::Simulator> simulator = sim::Simulator::Create(options);
  if (!simulator.ok()) return simulator.status();
  return RenderMonoFrames(&*simulator, std::min(frames, options.frames));
}

sim::SimulationOptions CorridorLoopOptions(const CorridorLoop& loop) {
  sim::SimulationOptions options = sim::SimulationOptions::ForScene("corridor");
  options.sensors = "mono";
  options.frames = loop.frames;
  options.rate_hz = loop.rate_hz;
  options.motion.speed_mps = loop.speed_mps;
  options.corridor.loop_length_m = loop.loop_length_m;
  options.corridor.loop_width_m = loop.loop_width_m;
  options.mono.width = loop.width;
  options.mono.height = loop.height;
  options.mono.focal_px *= loop.width / 640.0;
  return options;
}

int FirstLapEnd(const Trajectory& ground_truth) {
  // The route loops: the lap ends where the camera comes nearest its first position again,
  // searched after it has been farthest from it.
  const auto& poses = ground_truth.poses();
  if (poses.empty()) return 0;
  const Eigen::Vector3d start = poses.front().world_from_sensor.translation();
  size_t farthest = 0;
  for (size_t i = 0; i < poses.size(); ++i) {
    if ((poses[i].world_from_sensor.translation() - start).norm() >
        (poses[farthest].world_from_sensor.translation() - start).norm()) {
      farthest = i;
    }
  }
  size_t nearest = poses.size() - 1;
  for (size_t i = farthest; i < poses.size(); ++i) {
    if ((poses[i].world_from_sensor.translation() - start).norm() <
        (poses[nearest].world_from_sensor.translation() - start).norm()) {
      nearest = i;
    }
  }
  return static_cast<int>(nearest);
}

StatusOr<MonoSequence> RenderCorridorLoop(const CorridorLoop& loop) {
  StatusOr<sim::Simulator> simulator = sim::Simulator::Create(CorridorLoopOptions(loop));
  if (!simulator.ok()) return simulator.status();
  return RenderMonoFrames(&*simulator, loop.frames);
}

Trajectory RunFrames(MonoSlam* slam, const std::vector<MonoFrame>& frames) {
  Trajectory estimate;
  for (const MonoFrame& frame : frames) {
    StatusOr<std::shared_ptr<const MonoSlamResult>> r = slam->Process(frame);
    if (r.ok() && (*r)->tracked) estimate.Add((*r)->stamp.sensor_time_s, (*r)->map_from_camera);
  }
  return estimate;
}

double Sim3AteRmse(const Trajectory& estimate, const Trajectory& ground_truth) {
  EvaluationOptions eval;
  eval.align = "sim3";
  StatusOr<TrajectoryErrors> errors = EvaluateTrajectory(estimate, ground_truth, eval);
  return errors.ok() ? errors->ate.rmse : std::numeric_limits<double>::infinity();
}

}  // namespace sightline::testing
