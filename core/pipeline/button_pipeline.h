// The `button` pipeline: the operator's button picker run headless on a recording. Monocular
// SLAM (synchronous), the metric scale from the arm's poses, the tap of --tap X,Y[@FRAME]
// (confirmed at once: the operator's Yes is implied), tracking, 3D location and the safety gate
// per frame; targets optionally published through the arm-target server (--serve HOST:PORT).
// Writes button.csv and, with the simulator's buttons.csv beside the images, the accuracy
// against the true centre of the tapped button.
#pragma once

#include <Eigen/Geometry>
#include <optional>
#include <string>
#include <vector>

#include "core/button/button_picker.h"
#include "core/common/status.h"
#include "core/options/option_table.h"
#include "core/pipeline/pipeline_registry.h"

namespace sightline {

// Run-level options of the button pipeline. Keys "button.run.*".
struct ButtonRunOptions {
  std::string tap;             // "X,Y" or "X,Y@FRAME" (frame index; default 0). Required.
  bool serve = false;          // Publish targets through the arm-target server (button.arm.*).
  int wait_clients = 0;        // With serve: wait for this many clients before the first frame.
  double wait_clients_s = 30;  // ... at most this long [s].
  double linger_s = 0.5;       // With serve: keep serving this long after the last frame [s].

  bool IsValid(std::string* error) const;
  static OptionTable<ButtonRunOptions> Describe();
};

// A parsed tap.
struct ButtonTap {
  double x = 0, y = 0;
  int64_t frame = 0;
};
// Parses "X,Y" or "X,Y@FRAME". InvalidArgument naming button.run.tap otherwise.
StatusOr<ButtonTap> ParseButtonTap(const std::string& text);

// One row of button.csv.
struct ButtonRunRow {
  PickerFrame picker;
  double slam_ms = 0;
  bool slam_tracking = false;
  bool scale_converged = false;
  double lambda_ml = 0;
};

// A true button of the simulator's buttons.csv: its centre (map frame) and its projection per
// frame (NaN when not visible).
struct TrueButton {
  int id = -1;
  Eigen::Vector3d center_in_world = Eigen::Vector3d::Zero();
  std::vector<Eigen::Vector2d> pixel;  // Indexed by frame.
  std::vector<bool> visible;
};
// Reads buttons.csv. NotFound / ParseError naming the file and line.
StatusOr<std::vector<TrueButton>> ReadTrueButtons(const std::string& path);

// Writes button.csv (one row per frame from the tap on).
Status WriteButtonCsv(const std::vector<ButtonRunRow>& rows, const std::string& path);

// The registry entry.
PipelineInfo ButtonPipeline();

}  // namespace sightline
