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

// Why an operator's tap was not taken (the panel says it in words; never applied later).
enum class TapRefusal {
  kNone,
  kNoPicture,  // The tap names no frame the pipeline still holds (none shown yet, or a seek).
  kTooOld,     // The tapped frame is older than button.gui.max_tap_age_s in data time.
  kStopped,    // STOP is on: press Start first.
};
// The refusal as a key for messages ("none", "no_picture", "too_old", "stopped"), and back
// (nullopt for a key this build does not know).
const char* TapRefusalKey(TapRefusal refusal);
std::optional<TapRefusal> TapRefusalOfKey(const std::string& key);

// One frame of the button picker: the monocular SLAM's frame and the picker's.
struct ButtonFrameResult : MonoSlamFrameResult {
  PickerFrame picker;                          // State, track, location, gate verdict, target.
  bool tap_answered = false;                   // A tap was handled in this frame ...
  Status tap_status;                           // ... with this outcome.
  TapRefusal tap_refused = TapRefusal::kNone;  // ... and, when not taken, why.
  double tap_stamp_s = 0;  // ... made on the picture with this sensor time (the tap's stamp).
  std::vector<cv::Point> candidate_outline;  // The button found at the tap (image pixels).
  bool scale_converged = false;              // The metric scale counts as converged.
  // No metric scale (no arm: mono.run.metric_source = none, or auto without arm poses): the
  // button is tracked and located in map units only and no target is ever sent.
  bool tracking_only = false;
  double scale_ml = 0;  // Map units per metre of the metric view, 0 = unknown.
  // The live source gave no arm pose at this frame's stamp (tf lacks the end effector there):
  // why, naming the frames and the stamp; the frame has no base frame and no scale pair. "" when
  // it had one, or the arm's poses do not come from the live source.
  std::string arm_pose_missing;
  // The target went to the arm-target server and the server took it (not stopped, not closed).
  bool target_published = false;
  bool held = false;     // Targets were held (the picture is paused): nothing was published.
  bool stopped = false;  // The operator's STOP is on (latched until Start).
  bool serving = false;  // The arm-target server runs.
  int arm_clients = 0;   // Arm clients receiving targets now.
};

// A tap of the operator on the image: the pixel and the frame it was made on.
struct ButtonTapRequest {
  double x = 0, y = 0;
  // The operator's tap: the stream index (sequence id) and sensor time of the frame shown when
  // the operator tapped. The pipeline finds the button on that very frame, or refuses the tap
  // (TapRefusal); it is never kept for a later frame. -1: no frame was shown (refused).
  int64_t frame = -1;
  double stamp_s = 0;
  // Headless (button.run.tap, --tap X,Y@FRAME): `frame` is the run's frame index the tap is
  // for, applied when that frame comes.
  bool ahead = false;
  bool confirm = false;   // The tap is also the operator's Yes (headless runs).
  bool required = false;  // A tap that finds no button ends the run (headless runs).
};

// The pipeline's answer to an operator's tap, kept for the view until it takes it: a view that
// skips frames (it always draws the newest) still sees every answer.
struct ButtonTapAnswer {
  int64_t frame = -1;                        // The frame the tap was made on.
  Status status;                             // Ok: a candidate; NotFound: no button there.
  TapRefusal refused = TapRefusal::kNone;    // Not taken, and why.
  std::vector<cv::Point> candidate_outline;  // With a candidate (image pixels).
};

// The operator's commands to a running button pipeline. Thread-safe: the GUI thread (operator
// panel) and the CLI (--tap) call them; the pipeline takes them at its next frame. Stop and
// Restart also reach the arm-target server at once, not at the next frame. STOP is latched
// here, in the object the panel and every pipeline object of it share: only Restart (the
// operator's Start) lifts it; new options, serving on or off or a new pipeline object never do.
class ButtonCommands {
 public:
  void Tap(const ButtonTapRequest& tap);
  void Confirm();
  void Cancel();
  void Stop(const std::string& reason = "operator");
  void Restart();
  // Holds the targets while `hold` is set (the picture is paused): the pipeline publishes
  // nothing. Holding also drops a tap not yet taken; returns whether one was dropped.
  bool SetHold(bool hold);
  bool held() const;
  // STOP is on.
  bool stopped() const;

  // What the pipeline applies in one frame (in this order: stop, restart, cancel, tap, confirm).
  struct Pending {
    bool stop = false, restart = false, cancel = false, confirm = false;
    std::optional<ButtonTapRequest> tap;
  };
  // Takes the commands for the frame with run index `index`. An operator's tap is always taken
  // (its frame decides); a headless tap for a later index stays.
  Pending Take(int64_t index);
  // Whether a tap waits for a frame.
  bool tap_pending() const;
  // The pipeline's answer to the last tap (it replaces an answer not taken yet); the view takes
  // it once.
  void PostAnswer(ButtonTapAnswer answer);
  std::optional<ButtonTapAnswer> TakeAnswer();
  // Where Stop and Restart go at once (the arm-target server of pipeline object `owner`).
  void SetImmediate(const void* owner, std::function<void(const std::string&)> stop,
                    std::function<void()> restart);
  // Detaches them, if `owner` set them last.
  void ClearImmediate(const void* owner);

 private:
  mutable std::mutex mutex_;
  Pending pending_;
  std::optional<ButtonTapAnswer> answer_;
  bool stopped_ = false;
  bool held_ = false;
  const void* immediate_owner_ = nullptr;
  std::function<void(const std::string&)> stop_now_;
  std::function<void()> restart_now_;
};

// The statistics every ButtonFrameResult may hold ("button/slam_ms", "mono/inliers", ...).
const StatisticTable& ButtonStatistics();

// The registry entry of "button". Without `commands` every object is headless: the tap comes
// from button.run.tap (--tap) and is confirmed at once. With them (the GUI's operator panel) the
// operator's commands drive it; `mono_commands` carry Reset map / Pause mapping.
PipelineInfo ButtonPipelineInfo(const std::shared_ptr<ButtonCommands>& commands = nullptr,
                                const std::shared_ptr<MonoSlamCommands>& mono_commands = nullptr);

}  // namespace sightline
