// Rendering speed of the simulator (target: >= 50 RGB-D frames per second at 640x480 on one
// core, i.e. <= 20 ms per frame, so tests can generate their data on the fly).
// Run: build/bin/bench_sim --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
#include <benchmark/benchmark.h>

#include "core/sim/simulator.h"

namespace sightline::sim {
namespace {

// Simulators for the corridor, frames spread along the route (turns included).
Simulator MakeCorridor(const std::string& resolution, bool kitti_stereo) {
  SimulationOptions options = SimulationOptions::ForScene("corridor");
  options.frames = 600;
  options.rgbd.resolution = resolution;
  if (kitti_stereo) {
    options.stereo.width = 1241;
    options.stereo.height = 376;
    options.stereo.focal_px = 718.856;
    options.stereo.baseline_m = 0.54;
  }
  auto sim = Simulator::Create(options);
  if (!sim.ok()) std::abort();
  return std::move(*sim);
}

// One Kinect frame: render, depth model (noise, quantisation, dropout) and colour noise.
void BM_CorridorRgbd(benchmark::State& state, const std::string& resolution) {
  Simulator sim = MakeCorridor(resolution, false);
  SimulatedRgbd frame;
  int i = 0;
  for (auto _ : state) {
    if (!sim.RenderRgbd((i += 37) % sim.frames(), &frame).ok()) state.SkipWithError("render");
    benchmark::DoNotOptimize(frame.depth_m.data);
  }
  state.SetItemsProcessed(state.iterations());
  state.counters["fps"] =
      benchmark::Counter(static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
}
BENCHMARK_CAPTURE(BM_CorridorRgbd, 640x480, std::string("640x480"))->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_CorridorRgbd, 320x240, std::string("320x240"))->Unit(benchmark::kMillisecond);

// One KITTI-sized rectified stereo pair (two grey renders and image noise).
void BM_CorridorStereoKitti(benchmark::State& state) {
  Simulator sim = MakeCorridor("640x480", true);
  SimulatedStereo frame;
  int i = 0;
  for (auto _ : state) {
    if (!sim.RenderStereo((i += 37) % sim.frames(), &frame).ok()) state.SkipWithError("render");
    benchmark::DoNotOptimize(frame.right.data);
  }
  state.counters["fps"] =
      benchmark::Counter(static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_CorridorStereoKitti)->Unit(benchmark::kMillisecond);

// Building the corridor scene (textures baked, walls laid out).
void BM_BuildCorridorScene(benchmark::State& state) {
  const SimulationOptions options = SimulationOptions::ForScene("corridor");
  for (auto _ : state) {
    auto scene = BuildScene(options);
    benchmark::DoNotOptimize(scene.ok());
  }
}
BENCHMARK(BM_BuildCorridorScene)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace sightline::sim
