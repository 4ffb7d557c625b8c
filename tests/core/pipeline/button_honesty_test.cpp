// The button pipeline's targets against the simulator's truth on the default simulated approach
// (8 cm sideways, the seed's plan) with several seeds: the approach direction is the panel's
// push direction within 5 deg, and the target's stated uncertainty is honest (the true error
// lies within 3 stated sigmas on at least 95 % of the targets).
#include <gtest/gtest.h>

#include <cstdio>
#include <map>

#include "core/pipeline/button_pipeline.h"
#include "core/pipeline/pipeline_registry.h"
#include "core/sim/simulate.h"
#include "tests/support/test_data.h"

namespace sightline {
namespace {

std::map<std::string, double> Figures(const RunReport& report) {
  std::map<std::string, double> m;
  for (const auto& [key, value] : report.result.accuracy) m[key] = value;
  return m;
}

// "button.run.tap=U,V@0" 2 px off the true centre of `id` in frame 0 of `dir`.
std::string TapOn(const std::string& dir, int id) {
  StatusOr<std::vector<TrueButton>> buttons = ReadTrueButtons(dir + "/buttons.csv");
  EXPECT_TRUE(buttons.ok()) << buttons.status().ToString();
  for (const TrueButton& b : *buttons) {
    if (b.id != id) continue;
    char tap[96];
    std::snprintf(tap, sizeof(tap), "button.run.tap=%.1f,%.1f@0", b.pixel[0].x() + 2,
                  b.pixel[0].y() - 2);
    return tap;
  }
  ADD_FAILURE() << "button " << id << " not in " << dir;
  return "button.run.tap=0,0";
}

// Simulates the default panel approach with `seed` and runs the button pipeline on it.
std::map<std::string, double> RunSeed(int seed) {
  const std::string dir = testing::TempDir("button_honesty_sim_" + std::to_string(seed));
  sim::SimulationOptions options = sim::SimulationOptions::ForScene("panel");
  options.seed = seed;
  EXPECT_TRUE(sim::Simulate(options, dir).ok());
  RunRequest request;
  request.pipeline = "button";
  request.dataset_path = dir;
  request.out_dir = testing::TempDir("button_honesty_run_" + std::to_string(seed));
  request.overrides = {TapOn(dir, 5)};
  StatusOr<RunReport> report = RunPipeline(BuiltinPipelines(), request);
  EXPECT_TRUE(report.ok()) << report.status().ToString();
  if (!report.ok()) return {};
  return Figures(*report);
}

TEST(ButtonHonesty, ApproachIsThePanelNormalAndTheStatedUncertaintyCoversTheTrueError) {
  double targets = 0, covered = 0;
  for (int seed : {1, 2, 3}) {
    std::map<std::string, double> m = RunSeed(seed);
    std::printf(
        "seed %d: %g targets, final %.2f mm, approach median %.2f max %.2f deg, "
        "position within 3 sigma %.3f, approach within 3 sigma %.3f\n",
        seed, m["targets_sent"], m["final_error_mm"], m["approach_error_deg_median"],
        m["approach_error_deg_max"], m["position_within_3_sigma"], m["approach_within_3_sigma"]);
    ASSERT_GT(m["targets_sent"], 10) << "seed " << seed;
    ASSERT_TRUE(m.count("approach_error_deg_max")) << "seed " << seed;
    EXPECT_LT(m["approach_error_deg_max"], 5.0) << "seed " << seed;
    EXPECT_LT(m["approach_error_deg_median"], 4.0) << "seed " << seed;
    EXPECT_GE(m["approach_within_3_sigma"], 0.95) << "seed " << seed;
    targets += m["targets_sent"];
    covered += m["position_within_3_sigma"] * m["targets_sent"];
  }
  EXPECT_GE(covered / targets, 0.95);
}

}  // namespace
}  // namespace sightline
