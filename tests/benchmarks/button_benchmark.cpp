// Cost of the button picker on one core, on the simulated panel approach (640x480, camera in
// the arm's hand): tracking per frame with the predicted search window (the bound is
// 20 ms median) and over the whole image, detection from a tap, the plane locator, and the
// compute latency from a tap to the first target (detect, track the next frame, locate, gate,
// publish).
// Run: taskset -c 1 build/bin/bench_button --benchmark_repetitions=5
//        --benchmark_report_aggregates_only=true
#include <benchmark/benchmark.h>

#include <opencv2/core/utility.hpp>
#include <random>

#include "core/button/arm_server.h"
#include "core/button/button_detector.h"
#include "core/button/button_locator.h"
#include "core/button/button_tracker.h"
#include "core/button/safety_gate.h"
#include "core/sim/simulator.h"

namespace sightline {
namespace {

struct Approach {
  PinholeCamera camera;
  Eigen::Vector3d button_in_world;
  double radius_m = 0;
  std::vector<sim::SimulatedMono> frames;

  cv::Point2d Project(size_t f) const {
    const Eigen::Vector2d p =
        camera.Project(frames[f].world_from_camera.inverse() * button_in_world);
    return {p.x(), p.y()};
  }
  double RadiusPx(size_t f) const {
    return camera.fx * radius_m / (frames[f].world_from_camera.inverse() * button_in_world).z();
  }
};

const Approach& Panel() {
  static const Approach approach = [] {
    Approach a;
    auto simulator = sim::Simulator::Create(sim::SimulationOptions::ForScene("panel"));
    if (!simulator.ok()) return a;
    a.camera = simulator->mono_camera();
    const int target = simulator->scene().hints.target_button;
    a.button_in_world = simulator->scene().buttons[target].center;
    a.radius_m = simulator->scene().buttons[target].radius_m;
    for (int i = 0; i < simulator->frames(); i += 2) {
      sim::SimulatedMono frame;
      if (!simulator->RenderMono(i, &frame).ok()) break;
      a.frames.push_back(std::move(frame));
    }
    return a;
  }();
  return approach;
}

void Track(benchmark::State& state, bool window) {
  cv::setNumThreads(1);
  const Approach& a = Panel();
  if (a.frames.size() < 2) {
    state.SkipWithError("panel simulation failed");
    return;
  }
  auto model = ButtonDetector().Detect(a.frames[0].image, a.Project(0));
  if (!model.ok()) {
    state.SkipWithError(model.status().message().c_str());
    return;
  }
  ButtonTrackerOptions options;
  options.use_window = window;
  auto tracker = std::make_unique<ButtonTracker>(*model, options);
  size_t f = 1;
  int lost = 0;
  for (auto _ : state) {
    TrackPrediction p{true, a.Project(f) + cv::Point2d(3, -2), a.RadiusPx(f) / a.RadiusPx(0)};
    auto t = tracker->Track(a.frames[f].image, p);
    lost += (t.ok() && t->found) ? 0 : 1;
    if (++f == a.frames.size()) {  // Start the approach again with a fresh model.
      state.PauseTiming();
      f = 1;
      tracker = std::make_unique<ButtonTracker>(*model, options);
      state.ResumeTiming();
    }
  }
  state.counters["lost_frames"] = lost;
}

void BM_TrackPredictedWindow(benchmark::State& state) { Track(state, true); }
void BM_TrackWholeImage(benchmark::State& state) { Track(state, false); }
BENCHMARK(BM_TrackPredictedWindow)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_TrackWholeImage)->Unit(benchmark::kMillisecond);

void BM_DetectFromTap(benchmark::State& state) {
  cv::setNumThreads(1);
  const Approach& a = Panel();
  if (a.frames.empty()) return state.SkipWithError("panel simulation failed");
  ButtonDetector detector;
  for (auto _ : state) benchmark::DoNotOptimize(detector.Detect(a.frames[0].image, a.Project(0)));
}
BENCHMARK(BM_DetectFromTap)->Unit(benchmark::kMillisecond);

// 300 map points around the button from the exact depth, 20 % outliers.
std::vector<Eigen::Vector3d> MapPoints(const Approach& a, size_t f) {
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> unit(0, 1);
  const cv::Point2d c = a.Project(f);
  const double r = a.RadiusPx(f);
  std::vector<Eigen::Vector3d> points;
  for (int k = 0; k < 300; ++k) {
    const double rho = 3 * r * std::sqrt(unit(rng)), phi = 2 * M_PI * unit(rng);
    const int u = int(c.x + rho * std::cos(phi)), v = int(c.y + rho * std::sin(phi));
    const float z =
        a.frames[f].view.depth_m.at<float>(std::clamp(v, 0, 479), std::clamp(u, 0, 639));
    if (!std::isfinite(z)) continue;
    Eigen::Vector3d x = a.camera.Unproject(u, v, z);
    if (unit(rng) < 0.2) x *= 0.8;
    points.push_back(a.frames[f].world_from_camera * x);
  }
  return points;
}

void BM_Locate(benchmark::State& state) {
  const Approach& a = Panel();
  if (a.frames.empty()) return state.SkipWithError("panel simulation failed");
  const auto points = MapPoints(a, 0);
  LocatorInput in;
  in.camera = a.camera;
  in.camera_from_world = a.frames[0].world_from_camera.inverse();
  in.points_in_world = &points;
  in.button_px = {a.Project(0).x, a.Project(0).y};
  in.button_radius_px = a.RadiusPx(0);
  ButtonLocator locator;
  for (auto _ : state) benchmark::DoNotOptimize(locator.Locate(in));
}
BENCHMARK(BM_Locate)->Unit(benchmark::kMillisecond);

// Compute latency from the operator's tap (and Yes) to the first target on the wire.
void BM_TapToFirstTarget(benchmark::State& state) {
  cv::setNumThreads(1);
  const Approach& a = Panel();
  if (a.frames.size() < 2) return state.SkipWithError("panel simulation failed");
  ArmServerOptions server_options;
  server_options.port = 0;
  auto server = ArmServer::Start(server_options);
  if (!server.ok()) return state.SkipWithError(server.status().message().c_str());
  const auto points = MapPoints(a, 1);
  for (auto _ : state) {
    auto model = ButtonDetector().Detect(a.frames[0].image, a.Project(0));
    ButtonTracker tracker(*model);
    auto t = tracker.Track(a.frames[1].image, {true, a.Project(1), 1.0});
    LocatorInput in;
    in.camera = a.camera;
    in.camera_from_world = a.frames[1].world_from_camera.inverse();
    in.points_in_world = &points;
    in.button_px = {t->center.x, t->center.y};
    in.button_radius_px = t->radius_px;
    auto at = ButtonLocator().Locate(in);
    SafetyState s;
    s.operator_confirmed = s.tracking = s.has_estimate = s.scale_converged = true;
    s.tracking_confidence = t->confidence;
    s.plane_sound = at.ok() && at->plane_sound;
    s.uncertainty_m = at.ok() ? at->uncertainty_m : 1;
    s.target_in_base = {0.5, 0, 0.3};
    if (CheckSafety(s, {}).send) {
      ArmTarget target;
      target.position_m = at->button_in_camera;
      (*server)->PublishTarget(target);
    } else {
      state.SkipWithError("the gate refused the first target");
      return;
    }
  }
}
BENCHMARK(BM_TapToFirstTarget)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace sightline
