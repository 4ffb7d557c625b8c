// Simulating a whole recording to disk: `sightline-cli simulate` and tests that need data.
#pragma once

#include <atomic>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "core/common/status.h"
#include "core/sim/simulation_options.h"

namespace sightline::sim {

// What Simulate() did.
struct SimulationSummary {
  std::string dir;
  std::string scene;
  std::string motion;                // Resolved motion kind.
  std::vector<std::string> sensors;  // Sensor folders written.
  int frames = 0;                    // Frames per sensor.
  int64_t images = 0;                // PNG files written.
  std::vector<std::string> files;    // Index, calibration and ground-truth files (relative).
  double render_s = 0;               // Time spent rendering and applying sensor models.
  double total_s = 0;                // Wall time including writing.
  double render_fps = 0;             // Frames (all sensors of one instant) rendered per second.
};

// Optional hooks of a long simulation.
struct SimulationCallbacks {
  std::function<void(int64_t done, int64_t total)> progress;  // After every frame.
  const std::atomic<bool>* cancel = nullptr;                  // Checked between frames.
};

// Simulates `options` into `dir` (created; existing files of the same names are overwritten):
// the sensor folders (recording_writer.h), the ground truth (ground_truth_files.h), the body's
// true trajectory (body_groundtruth.txt), wheel odometry (odometry.txt, robot motions) or arm
// poses (arm_poses.txt + hand_eye.yaml, arm motions). InvalidArgument for invalid options,
// Unavailable when a file cannot be written, Cancelled when stopped (files so far are valid).
StatusOr<SimulationSummary> Simulate(const SimulationOptions& options, const std::string& dir,
                                     const SimulationCallbacks& callbacks = {});

}  // namespace sightline::sim
