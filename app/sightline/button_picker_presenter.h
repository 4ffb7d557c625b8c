// The operator's button picker in the GUI: the monocular SLAM presenter's views and processor,
// with the button picker fed from each frame's SLAM result (metric via the arm's poses) and the
// operator panel (tap, "Press this button?" Yes / Cancel, banner with the gate's reason, distance,
// STOP) in a dock that View > Operator panel shows and F11 turns full screen. Targets go out
// through the arm-target server when button.run.serve is on (button.arm.*: 127.0.0.1:5757 by
// default); STOP publishes a stop at once from the GUI thread.
#pragma once

#include <QPointF>
#include <memory>
#include <mutex>
#include <optional>

#include "app/sightline/mono_slam_presenter.h"
#include "core/button/arm_server.h"
#include "core/button/button_picker.h"

class QAction;
class QDockWidget;

namespace sightline {

class OperatorPanel;

// The operator's requests, from the GUI thread to the processor (applied at the next frame),
// and the arm-target server both sides use.
struct ButtonPickerControls {
  std::mutex mutex;
  std::optional<QPointF> tap;  // Image pixel of a tap not yet handled.
  bool confirm = false, cancel = false, stop = false, start = false;
  std::shared_ptr<ArmServer> server;  // Null when not serving.
};

// What the processor hands the GUI for one frame: the SLAM's, plus the picker's.
struct ButtonViewResult : MonoViewResult {
  PickerFrame picker;
  bool tap_answered = false;                 // A tap was handled in this frame ...
  Status tap_status;                         // ... with this outcome.
  std::vector<cv::Point> candidate_outline;  // The found button (image pixels).
  bool scale_converged = false;
};

class ButtonPickerPresenter : public MonoSlamPresenter {
  Q_OBJECT

 public:
  // `server_defaults`: the button.arm.* defaults (tests pass a free port); `serve`: the default of
  // button.run.serve.
  explicit ButtonPickerPresenter(ArmServerOptions server_defaults = {}, bool serve = false,
                                 QObject* parent = nullptr);

  const char* TitleSource() const override;
  Status DeclareOptions(OptionSet* options) const override;
  bool Accepts(SourceKind kind) const override;
  std::unique_ptr<Pipeline> CreateProcessor(const PipelineSource& source) override;
  void Attach(QMainWindow* window) override;
  void Detach() override;
  void Show(const PlaybackResult& result) override;

  OperatorPanel* panel() const { return panel_; }
  // The last picker state shown, for tests.
  PickerState last_state() const { return last_state_; }
  bool scale_converged() const { return scale_converged_; }

 private:
  void Stop();

  ArmServerOptions server_defaults_;
  bool serve_;
  std::shared_ptr<ButtonPickerControls> controls_ = std::make_shared<ButtonPickerControls>();
  QDockWidget* panel_dock_ = nullptr;
  OperatorPanel* panel_ = nullptr;
  QAction* panel_action_ = nullptr;
  QAction* full_screen_action_ = nullptr;
  PickerState last_state_ = PickerState::kIdle;
  bool scale_converged_ = false;
};

}  // namespace sightline
