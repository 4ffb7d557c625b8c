// What the `button` pipeline (core/pipeline/button_pipeline.h) gives its views for one frame,
// its table of per-frame statistics, and the operator's commands (tap, confirm, cancel, stop,
// restart) that reach it from any thread. No picker, estimator or server classes: the GUI
// includes this header.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <mutex>
#include <opencv2/core.hpp>
#include <optional>
#include <string>
#include <vector>

#include "core/button/button_types.h"
#include "core/common/status.h"
#include "core/pipeline/mono_slam_result.h"

namespace sightline {

// One frame of the button picker: the monocular SLAM's frame and the picker's.
struct ButtonFrameResult : MonoSlamFrameResult {
  PickerFrame picker;                        // State, track, location, gate verdict, target.
  bool tap_answered = false;                 // A tap was handled in this frame ...
  Status tap_status;                         // ... with this outcome.
  std::vector<cv::Point> candidate_outline;  // The button found at the tap (image pixels).
  bool scale_converged = false;              // The metric scale counts as converged.
  double scale_ml = 0;                       // Map units per metre of the metric view, 0 = unknown.
  bool target_published = false;             // The target went to the arm-target server.
};

// A tap of the operator on the image: pixel and the stream index of the frame it belongs to.
struct ButtonTapRequest {
  double x = 0, y = 0;
  int64_t frame = -1;     // Frame index it is for; -1 = the next frame processed.
  bool confirm = false;   // The tap is also the operator's Yes (headless runs).
  bool required = false;  // A tap that finds no button ends the run (headless runs).
};

// The operator's commands to a running button pipeline. Thread-safe: the GUI thread (operator
// panel) and the CLI (--tap) call them; the pipeline takes them at its next frame. Stop and
// Restart also reach the arm-target server at once, not at the next frame.
class ButtonCommands {
 public:
  void Tap(const ButtonTapRequest& tap);
  void Confirm();
  void Cancel();
  void Stop(const std::string& reason = "operator");
  void Restart();

  // What the pipeline applies in one frame (in this order: stop, restart, cancel, tap, confirm).
  struct Pending {
    bool stop = false, restart = false, cancel = false, confirm = false;
    std::optional<ButtonTapRequest> tap;
  };
  // Takes the commands for the frame with stream index `frame` (a tap for a later frame stays).
  Pending Take(int64_t frame);
  // Whether a tap waits for a frame.
  bool tap_pending() const;
  // Where Stop and Restart go at once (the pipeline's arm-target server); empty to detach.
  void SetImmediate(std::function<void(const std::string&)> stop, std::function<void()> restart);

 private:
  mutable std::mutex mutex_;
  Pending pending_;
  std::function<void(const std::string&)> stop_now_;
  std::function<void()> restart_now_;
};

// The statistics every ButtonFrameResult may hold ("button/slam_ms", "mono/inliers", ...).
const StatisticTable& ButtonStatistics();

// The registry entry of "button". Without `commands` every object is headless: the tap comes
// from button.run.tap (--tap) and is confirmed at once. With them (the GUI's operator panel) the
// operator's commands drive it; `mono_commands` carry Reset map / Pause mapping.
PipelineInfo ButtonPipelineInfo(std::shared_ptr<ButtonCommands> commands = nullptr,
                                std::shared_ptr<MonoSlamCommands> mono_commands = nullptr);

}  // namespace sightline
