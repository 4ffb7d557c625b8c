// The operator's button picker in the GUI: the monocular SLAM presenter's views and processor,
// with the button picker fed from each frame's SLAM result (metric via the arm's poses) and the
// operator panel (tap, "Press this button?" Yes / Cancel, banner with the gate's reason, distance,
// STOP) in a dock that View > Operator panel shows and F11 turns full screen. Draw-only: the
// registry's "button" pipeline does the work, including the arm-target server when
// button.gui.serve or button.run.serve is on (button.arm.*: 127.0.0.1:5757 by default); the
// panel sends the operator's commands to it (ButtonCommands), and STOP reaches the arm at once.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "app/sightline/mono_slam_presenter.h"
#include "core/pipeline/button_result.h"

class QAction;
class QDockWidget;

namespace sightline {

class OperatorPanel;

class ButtonPickerPresenter : public MonoSlamPresenter {
  Q_OBJECT

 public:
  // `option_defaults`: "key=value" assignments applied to the pipeline's options as they are
  // declared (tests: "button.arm.port=PORT", "button.gui.serve=true").
  explicit ButtonPickerPresenter(std::vector<std::string> option_defaults = {},
                                 QObject* parent = nullptr);

  const char* TitleSource() const override;
  void Attach(QMainWindow* window) override;
  void Detach() override;
  void Show(const PlaybackResult& result) override;

  OperatorPanel* panel() const { return panel_; }
  // The last picker state shown, for tests.
  PickerState last_state() const { return last_state_; }
  bool scale_converged() const { return scale_converged_; }

 private:
  ButtonPickerPresenter(std::shared_ptr<ButtonCommands> commands,
                        std::shared_ptr<MonoSlamCommands> mono_commands,
                        std::vector<std::string> option_defaults, QObject* parent);

  std::shared_ptr<ButtonCommands> commands_;
  QDockWidget* panel_dock_ = nullptr;
  OperatorPanel* panel_ = nullptr;
  QAction* panel_action_ = nullptr;
  QAction* full_screen_action_ = nullptr;
  PickerState last_state_ = PickerState::kIdle;
  bool scale_converged_ = false;
};

}  // namespace sightline
