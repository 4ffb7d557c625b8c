// Cost of the monocular SLAM per frame on one core: the simulator's arm approach (640x480,
// rendered in memory once) and kitti_clip1's left images (1226x370, real; skipped with a
// message when absent). Counters: medians of features and tracking per frame, mapping and local
// bundle adjustment per keyframe. Synchronous mode (mapping inline, timed apart from tracking)
// and threaded mode (mapping on its own thread; ...Live hands frames over at the camera's rate,
// as the GUI does, instead of back to back). tracking_ms is wall clock per frame,
// tracking_cpu_ms the tracking thread's own CPU time (the difference is time the tracker was
// not running: another thread or process had the core); cpus is the cores the run may use.
// The threaded setting, tracking on one core and mapping on the other:
//   taskset -c 0,1 build/bin/bench_mono --benchmark_repetitions=5
//   --benchmark_report_aggregates_only=true
#include <benchmark/benchmark.h>
#include <sched.h>

#include <chrono>
#include <cstdlib>
#include <opencv2/core/utility.hpp>
#include <string>
#include <thread>
#include <vector>

#include "core/common/timing.h"
#include "core/io/dataset.h"
#include "core/mono/mono_slam.h"
#include "core/sim/simulator.h"

namespace sightline {
namespace {

struct Clip {
  PinholeCamera camera;
  std::vector<MonoFrame> frames;
};

const Clip* PanelClip() {
  static Clip* clip = [] {
    auto* c = new Clip();
    sim::SimulationOptions options = sim::SimulationOptions::ForScene("panel");
    options.arm.sideways_m = 0.12;
    auto simulator = sim::Simulator::Create(options);
    if (!simulator.ok()) return c;
    c->camera = simulator->mono_camera();
    for (int i = 0; i < options.frames; ++i) {
      sim::SimulatedMono mono;
      if (!simulator->RenderMono(i, &mono).ok()) break;
      MonoFrame f;
      f.stamp.sequence_id = i;
      f.stamp.sensor_time_s = simulator->TimeOf(i);
      f.image = mono.image;
      c->frames.push_back(f);
    }
    return c;
  }();
  return clip;
}

const Clip* KittiClip() {
  static Clip* clip = [] {
    auto* c = new Clip();
    const char* env = std::getenv("SIGHTLINE_DATA_DIR");
    auto source = OpenDataset(std::string(env ? env : SIGHTLINE_DEFAULT_DATA_DIR) + "/kitti_clip1");
    if (!source.ok() || !(*source)->info().stereo) return c;
    c->camera = (*source)->info().stereo->left;
    while ((*source)->Grab().ok()) {
      auto frame = (*source)->Retrieve();
      if (!frame.ok()) break;
      const auto& stereo = std::get<StereoFrame>(*frame);
      c->frames.push_back({stereo.stamp, stereo.left});
    }
    return c;
  }();
  return clip;
}

// `live`: frames are handed over at their timestamps (the camera's rate, as in the GUI) instead
// of back to back, so the tracker idles between frames as it would live.
void RunClip(benchmark::State& state, const Clip* clip, bool threaded, bool live = false) {
  cv::setNumThreads(1);  // One core for OpenCV.
  if (clip->frames.empty()) {
    state.SkipWithError("no frames (kitti_clip1 not found? set SIGHTLINE_DATA_DIR)");
    return;
  }
  TimingStats timing;
  MonoSlamOptions options;
  options.mapping.threaded = threaded;
  for (auto _ : state) {
    MonoSlam slam(options);
    if (!slam.Configure(clip->camera, &timing).ok()) {
      state.SkipWithError("configure failed");
      return;
    }
    const auto start = std::chrono::steady_clock::now();
    for (const MonoFrame& frame : clip->frames) {
      if (live) {
        std::this_thread::sleep_until(
            start + std::chrono::duration<double>(frame.stamp.sensor_time_s -
                                                  clip->frames.front().stamp.sensor_time_s));
      }
      auto result = slam.Process(frame);
      benchmark::DoNotOptimize(result);
    }
    slam.Stop();
  }
  state.SetItemsProcessed(state.iterations() * static_cast<int64_t>(clip->frames.size()));
  cpu_set_t cpus;
  if (sched_getaffinity(0, sizeof(cpus), &cpus) == 0) state.counters["cpus"] = CPU_COUNT(&cpus);
  for (const std::string& stage : timing.Stages()) {
    state.counters[stage + "_ms"] = timing.Summary(stage).median_ms;
  }
}

void BM_MonoSlamPanel(benchmark::State& state) { RunClip(state, PanelClip(), false); }
void BM_MonoSlamPanelThreaded(benchmark::State& state) { RunClip(state, PanelClip(), true); }
void BM_MonoSlamPanelThreadedLive(benchmark::State& state) {
  RunClip(state, PanelClip(), true, true);
}
void BM_MonoSlamKittiClip(benchmark::State& state) { RunClip(state, KittiClip(), false); }

BENCHMARK(BM_MonoSlamPanel)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK(BM_MonoSlamPanelThreaded)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK(BM_MonoSlamPanelThreadedLive)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK(BM_MonoSlamKittiClip)->Unit(benchmark::kMillisecond)->Iterations(1);

}  // namespace
}  // namespace sightline
