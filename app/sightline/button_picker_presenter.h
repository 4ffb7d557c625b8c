// The operator's button picker in the GUI: the monocular SLAM presenter's views and processor,
// with the button picker fed from each frame's SLAM result (metric via the arm's poses) and the
// operator panel (tap, "Press this button?" Yes / Cancel, "Target sent" or "Holding: nothing
// sent" and why, the ring on the tracked button, distance, STOP) in a dock that View > Operator
// panel shows and F11 turns into a full-screen window of its own (`sightline --operator` opens
// it alone). Draw-only: the registry's "button" pipeline does the work, including the
// arm-target server when button.gui.serve or button.run.serve is on (button.arm.*:
// 127.0.0.1:5757 by default); the panel sends the operator's commands to it (ButtonCommands),
// and STOP reaches the arm at once. A tap is bound to the frame on screen and refused with
// words on a paused or ended picture; while the picture is paused the pipeline holds targets.
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

// Why the gate let no target out, in the operator's words ("Button lost"); empty for kSend.
QString OperatorReasonText(GateReason reason);
// Why the operator's tap was not taken, in the operator's words; empty for kNone.
QString TapRefusalText(TapRefusal refusal);

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
  // Operator mode: the panel alone, in a full-screen window of its own; leaving it (Esc, Yes)
  // emits OperatorLeft. Call after Attach.
  void EnterOperatorMode();
  // The panel is a full-screen window of its own (F11) rather than a dock.
  void SetPanelWindowed(bool on);
  bool panel_windowed() const { return panel_windowed_; }
  // The last picker state shown, for tests.
  PickerState last_state() const { return last_state_; }
  bool scale_converged() const { return scale_converged_; }
  // The last frame's result shown, for tests (null before the first).
  std::shared_ptr<const ButtonFrameResult> last_result() const { return last_result_; }

 signals:
  // Operator mode ended: the operator left the panel.
  void OperatorLeft();

 private:
  ButtonPickerPresenter(std::shared_ptr<ButtonCommands> commands,
                        std::shared_ptr<MonoSlamCommands> mono_commands,
                        std::vector<std::string> option_defaults, QObject* parent);

  void ConnectPanel();
  void OnTapped(QPointF image_px);
  void OnPlayState(bool playing, bool ended);
  void OnLeave();
  void ShowTapAnswer(const ButtonTapAnswer& answer);
  void ShowLink(const ButtonFrameResult& view);
  void ShowRing(const ButtonFrameResult& view);
  // Holds with the reason the picture gives (paused, ended), unless a question or STOP is shown.
  void HoldForPicture();
  QString PictureReason() const;

  std::shared_ptr<ButtonCommands> commands_;
  QMainWindow* window_ = nullptr;
  QDockWidget* panel_dock_ = nullptr;
  OperatorPanel* panel_ = nullptr;
  QAction* panel_action_ = nullptr;
  QAction* full_screen_action_ = nullptr;
  PickerState last_state_ = PickerState::kIdle;
  bool scale_converged_ = false;
  std::shared_ptr<const ButtonFrameResult> last_result_;
  bool playing_ = false, ended_ = false;  // The picture's playback.
  bool shown_ = false;                    // A frame is on the panel ...
  int64_t shown_id_ = -1;                 // ... with this stream index ...
  double shown_stamp_s_ = 0;              // ... and sensor time.
  bool operator_mode_ = false;
  bool panel_windowed_ = false;
};

}  // namespace sightline
