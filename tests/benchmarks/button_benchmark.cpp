// Cost of the button picker on one core, on the simulated panel approach (640x480, camera in
// the arm's hand): tracking per frame with the predicted search window (the target bound is
// 20 ms median) and over the whole image, detection from a tap, the plane locator, and the
// compute latency from a tap to the first target (detect, track the next frame, locate, gate,
// publish).
// On the 38 real panel photos (../shared/data/button_panels, or $SIGHTLINE_DATA_DIR): the region
// and the whole detection (region + SIFT) from a tap at each labelled button's centre, one tap
// per iteration in turn, for the multiscale method and the seed's rule.
// Run: taskset -c 1 build/bin/bench_button --benchmark_repetitions=5
//        --benchmark_report_aggregates_only=true
#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <fstream>
#include <map>
#include <opencv2/core/utility.hpp>
#include <opencv2/imgcodecs.hpp>
#include <random>
#include <sstream>

#include "core/button/arm_plane_normal.h"
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

// One frame of the plane from the arm's motion (KLT both ways over up to 300 corners, the
// plane's fit when the parallax allows; an anchor now and then) on the simulated approach, with
// the true camera poses standing for the arm's.
void BM_ArmPlaneFrame(benchmark::State& state) {
  cv::setNumThreads(1);
  const Approach& a = Panel();
  if (a.frames.size() < 2) {
    state.SkipWithError("panel simulation failed");
    return;
  }
  ArmPlaneNormal plane;
  size_t f = 0;
  int planes = 0;
  for (auto _ : state) {
    ArmPlaneView view;
    view.image = a.frames[f].image;
    view.camera = a.camera;
    view.base_from_camera = a.frames[f].world_from_camera;
    const cv::Point2d px = a.Project(f);
    view.button_px = {px.x, px.y};
    view.region_radius_px = PanelNormalOptions().radius_m * a.camera.fx /
                            (a.frames[f].world_from_camera.inverse() * a.button_in_world).z();
    planes += plane.Add(view).ok() ? 1 : 0;
    if (++f == a.frames.size()) {
      f = 0;
      plane.Reset();
    }
  }
  state.counters["planes"] = planes;
}
BENCHMARK(BM_ArmPlaneFrame)->Unit(benchmark::kMillisecond);

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

// Taps at the centres of the labelled buttons, with their photos.
struct RealTaps {
  std::map<std::string, cv::Mat> photos;
  std::vector<std::pair<const cv::Mat*, cv::Point2d>> taps;
};

const RealTaps& RealPanelTaps() {
  static const RealTaps real = [] {
    RealTaps r;
    const char* env = std::getenv("SIGHTLINE_DATA_DIR");
    const std::string dir =
        std::string(env ? env : SIGHTLINE_DEFAULT_DATA_DIR) + "/button_panels/test_panels/";
    std::ifstream in(SIGHTLINE_BUTTON_LABELS);
    std::string line;
    std::vector<std::pair<std::string, cv::Point2d>> wanted;
    while (std::getline(in, line)) {
      if (line.empty() || line[0] == '#') continue;
      std::vector<std::string> f;
      std::stringstream ss(line);
      std::string field;
      while (std::getline(ss, field, ',')) f.push_back(field);
      if (f.size() < 6 || f[1] != "button") continue;
      wanted.push_back(
          {f[0],
           {0.5 * (std::stod(f[2]) + std::stod(f[4])), 0.5 * (std::stod(f[3]) + std::stod(f[5]))}});
    }
    for (const auto& [file, tap] : wanted) {
      cv::Mat& photo = r.photos[file];
      if (photo.empty()) photo = cv::imread(dir + file);
    }
    for (const auto& [file, tap] : wanted) {
      const cv::Mat& photo = r.photos[file];
      if (!photo.empty()) r.taps.push_back({&photo, tap});
    }
    return r;
  }();
  return real;
}

void RealPanels(benchmark::State& state, const std::string& method, bool features,
                double min_button_probability = 0) {
  cv::setNumThreads(1);
  const RealTaps& real = RealPanelTaps();
  if (real.taps.empty()) return state.SkipWithError("real panel photos or labels not found");
  ButtonDetectorOptions options;
  options.method = method;
  options.min_button_probability = min_button_probability;
  const ButtonDetector detector(options);
  size_t i = 0;
  int found = 0;
  std::vector<double> ms;  // Per tap.
  for (auto _ : state) {
    const auto& [photo, tap] = real.taps[i];
    const auto start = std::chrono::steady_clock::now();
    if (features) {
      auto model = detector.Detect(*photo, tap);
      found += model.ok() ? 1 : 0;
    } else {
      auto region = detector.FindRegion(*photo, tap);
      found += region.ok() ? 1 : 0;
    }
    ms.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
                     .count());
    i = (i + 1) % real.taps.size();
  }
  if (!ms.empty()) {  // The per-tap median and 90th percentile, over the taps timed.
    std::sort(ms.begin(), ms.end());
    state.counters["median_ms"] = ms[ms.size() / 2];
    state.counters["p90_ms"] = ms[ms.size() * 9 / 10];
  }
  state.counters["taps"] = double(real.taps.size());
  state.counters["found"] = benchmark::Counter(found, benchmark::Counter::kAvgIterations);
}

void BM_RealPanelRegion(benchmark::State& state) { RealPanels(state, "multiscale", false); }
void BM_RealPanelDetect(benchmark::State& state) { RealPanels(state, "multiscale", true); }
void BM_RealPanelRegionSeed(benchmark::State& state) { RealPanels(state, "seed", false); }
// With the region classifier (button or printed label) asked at p >= 0.3.
void BM_RealPanelRegionClassified(benchmark::State& state) {
  RealPanels(state, "multiscale", false, 0.3);
}
// Each run covers every tap at least once (the labels hold about 390).
BENCHMARK(BM_RealPanelRegion)->Unit(benchmark::kMillisecond)->Iterations(400);
BENCHMARK(BM_RealPanelDetect)->Unit(benchmark::kMillisecond)->Iterations(400);
BENCHMARK(BM_RealPanelRegionSeed)->Unit(benchmark::kMillisecond)->Iterations(400);
BENCHMARK(BM_RealPanelRegionClassified)->Unit(benchmark::kMillisecond)->Iterations(400);

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
    s.approach_sigma_deg = 1;  // The panel normal is not what this benchmark measures.
    s.approach_in_base = Eigen::Vector3d::UnitX();
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
