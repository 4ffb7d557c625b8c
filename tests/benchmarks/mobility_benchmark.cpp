// Cost of the mobility map per 640x480 organized cloud on one core (real PCL clouds: office1
// and the grabber sequence), in grid mode at the default stride and at stride 1 (every finite
// pixel) and in the seed's PCL mode, with the mean of every stage as counters (ms). Skipped (with a
// message) when the data is absent.
// Run: taskset -c 1 build/bin/bench_mobility --benchmark_repetitions=5 \
//        --benchmark_report_aggregates_only=true
#include <benchmark/benchmark.h>

#include <cstdlib>
#include <map>
#include <opencv2/core/utility.hpp>
#include <string>
#include <vector>

#include "core/io/dataset.h"
#include "core/mobility/mobility_mapper.h"

namespace sightline {
namespace {

std::string DataPath(const std::string& name) {
  const char* env = std::getenv("SIGHTLINE_DATA_DIR");
  return std::string(env ? env : SIGHTLINE_DEFAULT_DATA_DIR) + "/" + name;
}

// Reads every cloud of a file or folder once (decoding is not part of the map's cost).
std::vector<MobilityInput> LoadClouds(const std::string& path) {
  std::vector<MobilityInput> inputs;
  auto source = OpenDataset(path, SourceKind::kCloud);
  if (!source.ok()) return inputs;
  while ((*source)->Grab().ok()) {
    auto frame = (*source)->Retrieve();
    if (!frame.ok()) break;
    inputs.push_back(MobilityInputFromCloud(std::get<CloudFrame>(*frame)));
  }
  return inputs;
}

void RunMobility(benchmark::State& state, const std::string& name, const std::string& mode,
                 int grid_stride = MobilityOptions().grid_stride) {
  cv::setNumThreads(1);  // One core.
  const std::vector<MobilityInput> inputs = LoadClouds(DataPath(name));
  if (inputs.empty()) {
    state.SkipWithError((name + " not found; set SIGHTLINE_DATA_DIR").c_str());
    return;
  }
  MobilityOptions options;
  options.mode = mode;
  options.grid_stride = grid_stride;
  MobilityMapper mapper(options);
  std::map<std::string, double> stage_ms;
  int64_t frames = 0;
  for (auto _ : state) {
    for (const MobilityInput& input : inputs) {
      auto result = mapper.Process(input);
      for (const StageReport& s : result->stages) stage_ms[s.name] += s.ms;
      ++frames;
      benchmark::DoNotOptimize(result);
    }
  }
  for (const auto& [stage, ms] : stage_ms) {
    state.counters[stage + "_ms"] = ms / static_cast<double>(frames);
  }
  state.counters["frames"] = static_cast<double>(inputs.size());
}

void BM_MobilityGridOffice1(benchmark::State& state) {
  RunMobility(state, "pcl_clouds/office1.pcd", "grid");
}
void BM_MobilityGridGrabber(benchmark::State& state) {
  RunMobility(state, "pcl_clouds/grabber_sequences/pcd", "grid");
}
void BM_MobilityGridStride1Office1(benchmark::State& state) {
  RunMobility(state, "pcl_clouds/office1.pcd", "grid", 1);
}
void BM_MobilityGridStride1Grabber(benchmark::State& state) {
  RunMobility(state, "pcl_clouds/grabber_sequences/pcd", "grid", 1);
}
void BM_MobilityPclOffice1(benchmark::State& state) {
  RunMobility(state, "pcl_clouds/office1.pcd", "pcl");
}
void BM_MobilityPclGrabber(benchmark::State& state) {
  RunMobility(state, "pcl_clouds/grabber_sequences/pcd", "pcl");
}
BENCHMARK(BM_MobilityGridOffice1)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_MobilityGridGrabber)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_MobilityGridStride1Office1)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_MobilityGridStride1Grabber)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_MobilityPclOffice1)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_MobilityPclGrabber)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace sightline
