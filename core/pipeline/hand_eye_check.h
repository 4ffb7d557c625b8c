// The hand-eye transform checked online against the monocular SLAM's own motion (AX = XB seen
// through the keyframes): the camera's displacement between two keyframes in the map and the same
// displacement from the arm's poses times hand_eye.yaml, both in the camera frame at the first
// keyframe, must point the same way (a wrong mount rotation turns the arm's displacements) and,
// once the scale is applied, agree in length; when the arm rotates between keyframes, a wrong
// mount translation adds (R_b - R_a) * error to the arm's displacement, so the residual bounds
// it. Without rotation the mount translation moves every camera pose by the same offset, which
// no motion reveals: the check then says it could not see it (translation_observable = false).
#pragma once

#include <string>

#include "core/common/status.h"
#include "core/common/trajectory.h"
#include "core/mono/scale_estimator.h"
#include "core/mono/slam_map.h"
#include "core/pipeline/mono_inputs.h"

namespace sightline {

// What the keyframes say of the mount.
struct HandEyeCheck {
  int pairs = 0;  // Keyframe pairs compared (every two keyframes at least min_baseline_m apart).
  // Angle between the map's and the arm's displacement directions: the length-weighted RMS over
  // the pairs, less the part the displacement noise explains [deg]. A wrong mount rotation of
  // d deg shows here as up to d deg (as d |sin| of its axis to the displacements).
  double direction_deg = 0;
  double direction_rms_deg = 0;         // The same RMS without taking the noise off [deg].
  double arm_rotation_deg = 0;          // Largest rotation between two compared keyframes.
  bool translation_observable = false;  // Some pair rotated by min_rotation_deg or more.
  double translation_m = 0;             // Mount translation error the residuals imply [m].

  // One line for the run's notes.
  std::string Describe() const;
};

// Checks the mount on the keyframes of `map`, whose scale is `lambda` (map units per metre);
// `base_from_camera` are the measured camera poses (arm times mount), paired with keyframes
// within `tolerance_s`. Every two keyframes whose measured displacement is at least
// `min_baseline_m` (and noise.min_metric_length_m) long are compared: the directions of short
// displacements drown in the arm's and the map's noise. `noise` gives that noise (sigma_map,
// sigma_metric_m), taken off the directions' RMS.
HandEyeCheck CheckHandEye(const MapSnapshot& map, const Trajectory& base_from_camera,
                          double tolerance_s, double lambda, const ScaleEstimatorOptions& noise,
                          double min_rotation_deg, double min_baseline_m);

// The hand_eye.yaml the metric poses of `dataset_path` use (as LoadMetricCameraPoses finds it):
// mono.run.hand_eye, else beside arm_poses.txt; "" when there is none, "none" when switched off.
std::string HandEyePathFor(const std::string& dataset_path, const MonoSlamRunOptions& run);

// The hand-eye sigmas a target states: `sigma_m` and `sigma_deg` (the options'
// button.uncertainty.hand_eye_sigma_m and _deg) raised to the calibration residuals hand_eye.yaml
// states (board_translation_rms_m, board_rotation_rms_deg: the spread of the calibration board's
// pose over the calibration views, of the order of the mount's own error). `hand_eye_path` empty
// or "none": nothing read. Returns a line for the run's notes saying which sigmas are stated and
// why; errors of the file as ReadHandEyeFile reports them.
StatusOr<std::string> StateHandEyeSigmas(const std::string& hand_eye_path, double* sigma_m,
                                         double* sigma_deg);

}  // namespace sightline
