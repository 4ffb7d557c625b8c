// Cost of evaluating a trajectory: a TUM-sized ground truth (~2,300 poses, 100 Hz) against a
// 30 Hz estimate, and a long KITTI-sized sequence (4,500 poses, 3.7 km) with the devkit's lengths.
// Run: build/bin/bench_eval --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
#include <benchmark/benchmark.h>

#include <cmath>

#include "core/eval/evaluation.h"
#include "core/eval/trajectory_plot.h"

namespace sightline {
namespace {

// A gently curving path with `step_m` per pose, one pose every `period_s`.
Trajectory Wander(int n, double step_m, double period_s) {
  Trajectory t;
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  for (int i = 0; i < n; ++i) {
    Eigen::Isometry3d motion = Eigen::Isometry3d::Identity();
    motion.linear() =
        Eigen::AngleAxisd(0.02 * std::sin(0.01 * i), Eigen::Vector3d::UnitY()).toRotationMatrix();
    motion.translation() = Eigen::Vector3d(0, 0, step_m);
    pose = pose * motion;
    t.Add(period_s * i, pose);
  }
  return t;
}

Trajectory Perturbed(const Trajectory& t, double every) {
  Trajectory out;
  for (size_t i = 0; i < t.size(); i += static_cast<size_t>(every)) {
    Eigen::Isometry3d pose = t.poses()[i].world_from_sensor;
    pose.translation() *= 1.01;
    out.Add(t.poses()[i].time_s + 0.001, pose);
  }
  return out;
}

void BM_EvaluateTumSized(benchmark::State& state) {
  const Trajectory gt = Wander(2300, 0.005, 0.01);
  const Trajectory est = Perturbed(gt, 3);
  EvaluationOptions options;
  options.segment_lengths_m = "1,2,4";
  for (auto _ : state) benchmark::DoNotOptimize(EvaluateTrajectory(est, gt, options));
}
BENCHMARK(BM_EvaluateTumSized)->Unit(benchmark::kMillisecond);

void BM_EvaluateKittiSized(benchmark::State& state) {
  const Trajectory gt = Wander(4500, 0.8, 0.1);
  const Trajectory est = Perturbed(gt, 1);
  EvaluationOptions options;
  options.segment_lengths_m = "kitti";
  options.segment_step_frames = static_cast<int>(state.range(0));
  for (auto _ : state) benchmark::DoNotOptimize(EvaluateTrajectory(est, gt, options));
}
BENCHMARK(BM_EvaluateKittiSized)->Arg(1)->Arg(10)->Unit(benchmark::kMillisecond);

void BM_DrawPlots(benchmark::State& state) {
  const Trajectory gt = Wander(2300, 0.005, 0.01);
  const TrajectoryErrors errors = *EvaluateTrajectory(Perturbed(gt, 3), gt, EvaluationOptions());
  for (auto _ : state) {
    benchmark::DoNotOptimize(DrawTopView(errors, PlotPlane::kAuto));
    benchmark::DoNotOptimize(DrawAteOverTime(errors));
  }
}
BENCHMARK(BM_DrawPlots)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace sightline
