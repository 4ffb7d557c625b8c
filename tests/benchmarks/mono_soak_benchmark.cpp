// Soak run of the monocular SLAM: a robot drives the simulated corridor loop (16 m x 10 m,
// about 51 m round) 1.3 times at 1 m/s, 2000 frames of 640x480 at 30 Hz, rendered one at a
// time (the images are not kept, so the process's memory is the SLAM's). Counters:
//   keyframes_200 / _1000 / _2000, points_200 / ...  map size after that many frames
//   keyframes_first_lap, keyframes_second_lap         keyframes added before / after the frame
//                                                     where the drive is back at its start
//   rss_mb_per_1000_frames_after_first_lap            resident memory growth after that frame
//   rss_mb_end, stop_ms, stop_longest_step_ms         memory at the end; Stop() and its longest
//                                                     single adjustment step
//   ate_pct_of_path, keyframe_ate_pct_of_path         Sim(3) ATE of the tracked frames / of the
//                                                     map's keyframes after Stop()
//   tracking_ms (median, wall), tracking_cpu_ms, revisits, idle_slices, lost
// ...NoRevisits runs the same drive without revisit search and idle-time adjustment and with
// the full adjustment at stop, as before the map was bounded. Not part of ctest (minutes):
//   build/bin/bench_mono_soak --benchmark_filter='CorridorLoop/'
#include <benchmark/benchmark.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <opencv2/core/utility.hpp>

#include "core/common/timing.h"
#include "core/eval/evaluation.h"
#include "core/mono/mono_slam.h"
#include "core/sim/simulator.h"
#include "tests/core/mono/mono_test_util.h"

namespace sightline {
namespace {

double ResidentMb() {
  long pages = 0, resident = 0;
  FILE* f = std::fopen("/proc/self/statm", "r");
  if (f == nullptr) return 0;
  if (std::fscanf(f, "%ld %ld", &pages, &resident) != 2) resident = 0;
  std::fclose(f);
  return resident * static_cast<double>(sysconf(_SC_PAGESIZE)) / (1024.0 * 1024.0);
}

double AtePercent(const Trajectory& estimate, const Trajectory& ground_truth) {
  EvaluationOptions eval;
  eval.align = "sim3";
  StatusOr<TrajectoryErrors> errors = EvaluateTrajectory(estimate, ground_truth, eval);
  if (!errors.ok() || errors->ground_truth_length_m <= 0) return -1;
  return 100 * errors->ate.rmse / errors->ground_truth_length_m;
}

void RunSoak(benchmark::State& state, const MonoSlamOptions& options) {
  cv::setNumThreads(1);
  const testing::CorridorLoop loop;  // The defaults are the drive described above.
  StatusOr<sim::Simulator> simulator = sim::Simulator::Create(testing::CorridorLoopOptions(loop));
  if (!simulator.ok()) {
    state.SkipWithError(simulator.status().ToString().c_str());
    return;
  }
  const int lap_end = testing::FirstLapEnd(simulator->BodyGroundTruth());
  for (auto _ : state) {
    TimingStats timing;
    MonoSlam slam(options);
    if (!slam.Configure(simulator->mono_camera(), &timing).ok()) {
      state.SkipWithError("configure failed");
      return;
    }
    Trajectory estimate, truth;
    double rss_lap_end = 0;
    int keyframes_lap_end = 0;
    for (int i = 0; i < loop.frames; ++i) {
      sim::SimulatedMono mono;
      if (!simulator->RenderMono(i, &mono).ok()) {
        state.SkipWithError("render failed");
        return;
      }
      MonoFrame frame;
      frame.stamp.sequence_id = i;
      frame.stamp.sensor_time_s = simulator->TimeOf(i);
      frame.image = mono.image;
      truth.Add(frame.stamp.sensor_time_s, mono.world_from_camera);
      StatusOr<std::shared_ptr<const MonoSlamResult>> r = slam.Process(frame);
      if (!r.ok()) {
        state.SkipWithError(r.status().ToString().c_str());
        return;
      }
      if ((*r)->tracked) estimate.Add(frame.stamp.sensor_time_s, (*r)->map_from_camera);
      for (int at : {200, 1000, 2000}) {
        if (i + 1 != at) continue;
        state.counters["keyframes_" + std::to_string(at)] = (*r)->stats.keyframes;
        state.counters["points_" + std::to_string(at)] = (*r)->stats.map_points;
      }
      if (i == lap_end) {
        keyframes_lap_end = (*r)->stats.keyframes;
        rss_lap_end = ResidentMb();
      }
    }
    const double rss_before_stop = ResidentMb();
    const double stop_start = HostTimeS();
    slam.Stop();
    const double stop_ms = (HostTimeS() - stop_start) * 1000.0;
    const IdleBundleTotals idle = slam.idle_bundle();
    Trajectory keyframes;
    for (const MapSnapshot::Frame& k : slam.Snapshot()->keyframes) {
      keyframes.Add(k.time_s, k.map_from_camera);
    }
    const int total_keyframes = static_cast<int>(slam.Snapshot()->keyframes.size());
    state.counters["keyframes_first_lap"] = keyframes_lap_end;
    state.counters["keyframes_second_lap"] = total_keyframes - keyframes_lap_end;
    state.counters["rss_mb_per_1000_frames_after_first_lap"] =
        (rss_before_stop - rss_lap_end) * 1000.0 / std::max(1, loop.frames - 1 - lap_end);
    state.counters["rss_mb_end"] = ResidentMb();
    state.counters["stop_ms"] = stop_ms;
    state.counters["stop_longest_step_ms"] = idle.stop_longest_step_ms;
    state.counters["ate_pct_of_path"] = AtePercent(estimate, truth);
    state.counters["keyframe_ate_pct_of_path"] = AtePercent(keyframes, truth);
    state.counters["tracking_ms"] = timing.Summary("tracking").median_ms;
    state.counters["tracking_cpu_ms"] = timing.Summary("tracking_cpu").median_ms;
    state.counters["revisits"] = slam.revisits();
    state.counters["idle_slices"] = idle.slices;
    state.counters["lost"] = slam.lost_frames();
  }
}

void BM_MonoSoakCorridorLoop(benchmark::State& state) { RunSoak(state, MonoSlamOptions()); }

void BM_MonoSoakCorridorLoopNoRevisits(benchmark::State& state) {
  MonoSlamOptions options;
  options.mapping.loop_search_radius = 0;
  options.mapping.local_map_distance = 0;
  options.mapping.idle_ba_iterations = 0;
  options.mapping.final_ba_max_keyframes = 100000;
  RunSoak(state, options);
}

BENCHMARK(BM_MonoSoakCorridorLoop)->Unit(benchmark::kSecond)->Iterations(1);
BENCHMARK(BM_MonoSoakCorridorLoopNoRevisits)->Unit(benchmark::kSecond)->Iterations(1);

}  // namespace
}  // namespace sightline
