// Cost of stereo visual odometry per frame on one core: kitti_clip1 (1226x370, real) and the
// EuRoC static sequence (752x480, real, rectified on the fly), with the per-stage medians as
// counters. Skipped (with a message) when the data is absent.
// Run: build/bin/bench_stereo --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
#include <benchmark/benchmark.h>

#include <cstdlib>
#include <opencv2/core/utility.hpp>
#include <string>
#include <vector>

#include "core/common/timing.h"
#include "core/io/dataset.h"
#include "core/stereo/stereo_odometry.h"

namespace sightline {
namespace {

std::string DataPath(const std::string& name) {
  const char* env = std::getenv("SIGHTLINE_DATA_DIR");
  return std::string(env ? env : SIGHTLINE_DEFAULT_DATA_DIR) + "/" + name;
}

struct Clip {
  StereoRig rig;
  std::vector<StereoFrame> frames;
};

// Reads every frame once (decoding is not part of the odometry's cost).
bool LoadClip(const std::string& path, Clip* clip) {
  auto source = OpenDataset(path, SourceKind::kStereo);
  if (!source.ok() || !(*source)->info().stereo) return false;
  clip->rig = *(*source)->info().stereo;
  while ((*source)->Grab().ok()) {
    auto frame = (*source)->Retrieve();
    if (!frame.ok()) return false;
    clip->frames.push_back(std::get<StereoFrame>(*frame));
  }
  return !clip->frames.empty();
}

void RunClip(benchmark::State& state, const std::string& name) {
  cv::setNumThreads(1);  // One core.
  Clip clip;
  if (!LoadClip(DataPath(name), &clip)) {
    state.SkipWithError((name + " not found; set SIGHTLINE_DATA_DIR").c_str());
    return;
  }
  TimingStats timing;
  for (auto _ : state) {
    StereoOdometry odometry;
    if (!odometry.Configure(clip.rig).ok()) {
      state.SkipWithError("configure failed");
      return;
    }
    for (const StereoFrame& frame : clip.frames) {
      auto result = odometry.Process(frame, &timing);
      benchmark::DoNotOptimize(result);
    }
  }
  state.SetItemsProcessed(state.iterations() * static_cast<int64_t>(clip.frames.size()));
  for (const std::string& stage : timing.Stages()) {
    state.counters[stage + "_ms"] = timing.Summary(stage).median_ms;
  }
}

void BM_StereoOdometryKittiClip(benchmark::State& state) { RunClip(state, "kitti_clip1"); }
void BM_StereoOdometryEurocStatic(benchmark::State& state) { RunClip(state, "euroc_v1_01_static"); }

BENCHMARK(BM_StereoOdometryKittiClip)->Unit(benchmark::kMillisecond)->Iterations(3);
BENCHMARK(BM_StereoOdometryEurocStatic)->Unit(benchmark::kMillisecond)->Iterations(3);

}  // namespace
}  // namespace sightline
