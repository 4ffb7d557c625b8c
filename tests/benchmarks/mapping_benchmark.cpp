// Speed of indoor mapping (seed 000): the whole per-frame path (320x240 depth -> occupancy image
// -> polar scan -> wall lines -> Manhattan rotation -> map stitching) on simulated corridor
// frames, target <= 2 ms median on one core; and each stage on its own.
// Run: build/bin/bench_mapping --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
// The counters median_ms and p95_ms are the per-frame distribution of the last repetition.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <vector>

#include "core/mapping/mapping_frame_processor.h"
#include "core/sim/observations.h"
#include "core/sim/simulator.h"

namespace sightline {
namespace {

// 120 corridor frames at 320x240 (60 m of the loop at 1 m/s and 2 Hz, turns included), with
// wheel odometry and ground-truth person boxes, rendered once.
struct CorridorFrames {
  PinholeCamera camera;
  FloorPlane floor;
  std::vector<MappingInput> inputs;
};

const CorridorFrames& Frames() {
  static const CorridorFrames* frames = [] {
    auto* f = new CorridorFrames;
    sim::SimulationOptions options = sim::SimulationOptions::ForScene("corridor");
    options.sensors = "rgbd";
    options.rgbd.resolution = "320x240";
    options.rate_hz = 2.0;
    options.motion.speed_mps = 1.0;
    options.frames = 120;
    options.corridor.loop_length_m = 30.0;
    options.corridor.loop_width_m = 20.0;
    auto simulator = sim::Simulator::Create(options);
    if (!simulator.ok()) std::abort();
    f->camera = simulator->rgbd_camera();
    const Trajectory odometry = simulator->WheelOdometry();
    const double forward = simulator->motion().body_from_camera.translation().x();
    sim::SimulatedRgbd frame;
    std::vector<Eigen::Vector3f> points;
    for (int k = 0; k < simulator->frames(); ++k) {
      if (!simulator->RenderRgbd(k, &frame).ok()) std::abort();
      if (k < 3) AppendDepthPoints(frame.depth_m, f->camera, 6.0, 1, &points);
      MappingInput input;
      input.stamp.sequence_id = k;
      input.stamp.sensor_time_s = simulator->TimeOf(k);
      input.depth_m = frame.depth_m.clone();
      Pose2d pose = Pose2d::FromIsometry(odometry.poses()[k].world_from_sensor);
      pose.x += forward * std::cos(pose.heading_rad);
      pose.y += forward * std::sin(pose.heading_rad);
      input.odometry = pose;
      std::vector<PersonBox> people;
      for (const sim::PersonObservation& p :
           sim::ObservePeople(simulator->scene(), frame.view, k)) {
        if (p.pixels == 0) continue;
        PersonBox box;
        box.id = p.person;
        box.box = cv::Rect2d(p.u0, p.v0, p.u1 - p.u0 + 1, p.v1 - p.v0 + 1);
        box.image_size = cv::Size(f->camera.width, f->camera.height);
        people.push_back(box);
      }
      input.people = people;
      f->inputs.push_back(std::move(input));
    }
    StatusOr<FloorFitResult> fit = FloorPlaneEstimator().Fit(points);
    if (!fit.ok()) std::abort();
    f->floor = fit->plane;
    return f;
  }();
  return *frames;
}

double Percentile(std::vector<double> v, double q) {
  if (v.empty()) return 0;
  const size_t k = std::min(v.size() - 1, static_cast<size_t>(q * v.size()));
  std::nth_element(v.begin(), v.begin() + k, v.end());
  return v[k];
}

// The whole per-frame path, frames in order (the processor restarts when the sequence wraps,
// outside the timing).
void BM_MappingFrame(benchmark::State& state) {
  const CorridorFrames& frames = Frames();
  MappingFrameProcessor processor;
  if (!processor.Configure(frames.floor, frames.camera).ok()) {
    state.SkipWithError("configure");
    return;
  }
  std::vector<double> total_ms, occupancy_ms, scan_ms, lines_ms, rotation_ms, stitch_ms;
  size_t i = 0;
  for (auto _ : state) {
    if (i == frames.inputs.size()) {
      state.PauseTiming();
      processor.Restart();
      i = 0;
      state.ResumeTiming();
    }
    const auto start = std::chrono::steady_clock::now();
    StatusOr<std::shared_ptr<const MappingFrameResult>> r = processor.Process(frames.inputs[i++]);
    total_ms.push_back(
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
            .count());
    if (!r.ok()) {
      state.SkipWithError("process");
      return;
    }
    occupancy_ms.push_back((*r)->times.occupancy_ms);
    scan_ms.push_back((*r)->times.scan_ms);
    lines_ms.push_back((*r)->times.lines_ms);
    rotation_ms.push_back((*r)->times.rotation_ms);
    stitch_ms.push_back((*r)->times.stitch_ms);
  }
  state.counters["median_ms"] = Percentile(total_ms, 0.5);
  state.counters["p95_ms"] = Percentile(total_ms, 0.95);
  state.counters["occupancy_ms"] = Percentile(occupancy_ms, 0.5);
  state.counters["scan_ms"] = Percentile(scan_ms, 0.5);
  state.counters["lines_ms"] = Percentile(lines_ms, 0.5);
  state.counters["rotation_ms"] = Percentile(rotation_ms, 0.5);
  state.counters["stitch_ms"] = Percentile(stitch_ms, 0.5);
}
BENCHMARK(BM_MappingFrame)->Unit(benchmark::kMillisecond)->MinTime(2.0);

// The same path with split-and-merge instead of multi-line RANSAC.
void BM_MappingFrameSplitAndMerge(benchmark::State& state) {
  const CorridorFrames& frames = Frames();
  MappingOptions options;
  options.extractor = "split_and_merge";
  MappingFrameProcessor processor(options);
  if (!processor.Configure(frames.floor, frames.camera).ok()) {
    state.SkipWithError("configure");
    return;
  }
  size_t i = 0;
  for (auto _ : state) {
    if (i == frames.inputs.size()) {
      state.PauseTiming();
      processor.Restart();
      i = 0;
      state.ResumeTiming();
    }
    benchmark::DoNotOptimize(processor.Process(frames.inputs[i++]));
  }
}
BENCHMARK(BM_MappingFrameSplitAndMerge)->Unit(benchmark::kMillisecond)->MinTime(2.0);

// Multi-line RANSAC alone on the scans of the frames.
void BM_MultiLineRansac(benchmark::State& state) {
  const CorridorFrames& frames = Frames();
  OccupancyImageBuilder builder;
  PolarScanner scanner;
  if (!builder.Configure(frames.floor, frames.camera).ok() ||
      !scanner.Configure(400, 400, 0.02, builder.fov_min_rad(), builder.fov_max_rad()).ok()) {
    state.SkipWithError("configure");
    return;
  }
  std::vector<PolarScan> scans;
  for (const MappingInput& input : frames.inputs) {
    StatusOr<OccupancyImage> image = builder.Build(input.depth_m, *input.people);
    if (!image.ok()) std::abort();
    scans.push_back(*scanner.Scan(*image));
  }
  MultiLineRansac ransac;
  size_t i = 0;
  for (auto _ : state) benchmark::DoNotOptimize(ransac.Extract(scans[i++ % scans.size()]));
}
BENCHMARK(BM_MultiLineRansac)->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace sightline
