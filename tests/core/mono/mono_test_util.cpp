#include "tests/core/mono/mono_test_util.h"

#include <algorithm>
#include <limits>

#include "core/eval/evaluation.h"
#include "core/sim/simulator.h"

namespace sightline::testing {

StatusOr<PanelSequence> RenderPanel(int frames, double sideways_m) {
  sim::SimulationOptions options = sim::SimulationOptions::ForScene("panel");
  // The 150-frame approach of the panel scene; only the first `frames` are rendered.
  options.arm.sideways_m = sideways_m;
  StatusOr<sim::Simulator> simulator = sim::Simulator::Create(options);
  if (!simulator.ok()) return simulator.status();
  PanelSequence out;
  out.camera = simulator->mono_camera();
  for (int i = 0; i < std::min(frames, options.frames); ++i) {
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
