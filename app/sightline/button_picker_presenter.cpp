#include "app/sightline/button_picker_presenter.h"

#include <QAction>
#include <QDockWidget>
#include <QLabel>
#include <QMainWindow>
#include <QMenu>
#include <QMenuBar>
#include <QSignalBlocker>
#include <cmath>

#include "app/sightline/playback_controller.h"
#include "widgets/operator_panel.h"

namespace sightline {

namespace {

// The "button" entry whose declared options take `defaults` ("key=value") at once.
PipelineInfo WithDefaults(PipelineInfo info, const std::vector<std::string>& defaults) {
  if (defaults.empty()) return info;
  auto declare = info.declare_options;
  info.declare_options = [declare, defaults](OptionSet* set) {
    SIGHTLINE_RETURN_IF_ERROR(declare(set));
    for (const std::string& assignment : defaults) {
      SIGHTLINE_RETURN_IF_ERROR(set->ApplyOverride(assignment));
    }
    return Status::Ok();
  };
  return info;
}

}  // namespace

// Why no target went out, in plain words for the operator panel. The gate's own message, with its
// figures and in English, is the line's tooltip for the engineer beside the chair.
QString OperatorReasonText(GateReason reason) {
  switch (reason) {
    case GateReason::kSend:
      return {};
    case GateReason::kStopped:
      return ButtonPickerPresenter::tr("Stopped");
    case GateReason::kNotConfirmed:
      return ButtonPickerPresenter::tr("Waiting for Yes");
    case GateReason::kTrackingLost:
      return ButtonPickerPresenter::tr("Button lost");
    case GateReason::kTrackingPoor:
      return ButtonPickerPresenter::tr("Button unclear");
    case GateReason::kNoEstimate:
      return ButtonPickerPresenter::tr("Measuring the button");
    case GateReason::kStale:
      return ButtonPickerPresenter::tr("Measuring again");
    case GateReason::kScaleNotConverged:
      return ButtonPickerPresenter::tr("Measuring the distance");
    case GateReason::kPlaneUnsound:
      return ButtonPickerPresenter::tr("Panel unclear");
    case GateReason::kUncertain:
      return ButtonPickerPresenter::tr("Position not sure yet");
    case GateReason::kApproachUncertain:
      return ButtonPickerPresenter::tr("Panel direction not sure yet");
    case GateReason::kOutsideWorkspace:
      return ButtonPickerPresenter::tr("Button out of reach");
  }
  return {};
}

QString TapRefusalText(TapRefusal refusal) {
  switch (refusal) {
    case TapRefusal::kNone:
      return {};
    case TapRefusal::kNoPicture:
      return ButtonPickerPresenter::tr("The picture changed: tap again");
    case TapRefusal::kTooOld:
      return ButtonPickerPresenter::tr("The picture was too old: tap again");
    case TapRefusal::kStopped:
      return ButtonPickerPresenter::tr("Stopped: press Start again first");
  }
  return {};
}

namespace {

// Why no target goes to the arm on a frame after Yes (the picture plays).
QString HoldText(const ButtonFrameResult& view) {
  if (view.held) return ButtonPickerPresenter::tr("Paused");
  if (view.stopped) return ButtonPickerPresenter::tr("Stopped");
  if (view.picker.verdict.send || view.picker.target) {  // The gate let it out, the link did not.
    if (!view.serving) return ButtonPickerPresenter::tr("Arm link off");
    if (view.arm_clients == 0) return ButtonPickerPresenter::tr("No arm connected");
    return ButtonPickerPresenter::tr("Stopped");
  }
  const QString reason = OperatorReasonText(view.picker.verdict.reason);
  return reason.isEmpty() ? ButtonPickerPresenter::tr("Waiting") : reason;
}

}  // namespace

ButtonPickerPresenter::ButtonPickerPresenter(std::vector<std::string> option_defaults,
                                             QObject* parent)
    : ButtonPickerPresenter(std::make_shared<ButtonCommands>(),
                            std::make_shared<MonoSlamCommands>(), std::move(option_defaults),
                            parent) {}

ButtonPickerPresenter::ButtonPickerPresenter(std::shared_ptr<ButtonCommands> commands,
                                             std::shared_ptr<MonoSlamCommands> mono_commands,
                                             std::vector<std::string> option_defaults,
                                             QObject* parent)
    : MonoSlamPresenter(
          WithDefaults(ButtonPipelineInfo(commands, mono_commands), std::move(option_defaults)),
          std::move(mono_commands), parent),
      commands_(std::move(commands)) {}

const char* ButtonPickerPresenter::TitleSource() const {
  return QT_TR_NOOP("Button picker (monocular SLAM)");
}

void ButtonPickerPresenter::Attach(QMainWindow* window) {
  MonoSlamPresenter::Attach(window);
  window_ = window;
  if (panel_dock_ == nullptr) {
    panel_ = new OperatorPanel(window);
    panel_dock_ = new QDockWidget(tr("Operator panel"), window);
    panel_dock_->setObjectName("button_operator_dock");
    panel_dock_->setWidget(panel_);
    ConnectPanel();
    full_screen_action_ = new QAction(tr("Operator panel full screen"), window);
    full_screen_action_->setShortcut(QKeySequence(Qt::Key_F11));
    full_screen_action_->setCheckable(true);
    connect(full_screen_action_, &QAction::toggled, this,
            [this](bool on) { SetPanelWindowed(on); });
  }
  // The picture's state decides about taps and holding: paused, stepped or ended holds.
  if (auto* playback = window->findChild<PlaybackController*>()) {
    connect(playback, &PlaybackController::PlayStateChanged, this,
            &ButtonPickerPresenter::OnPlayState, Qt::UniqueConnection);
    OnPlayState(playback->playing(), playback->ended());
  }
  window->addDockWidget(Qt::RightDockWidgetArea, panel_dock_);
  // A tab beside the log, not a third dock under it: with its 15 mm controls a stacked panel
  // makes the window taller than a laptop's screen.
  if (auto* log_dock = window->findChild<QDockWidget*>("log_dock")) {
    window->tabifyDockWidget(log_dock, panel_dock_);
  }
  window->addAction(full_screen_action_);
  panel_action_ = panel_dock_->toggleViewAction();
  panel_action_->setText(tr("Operator panel"));
  // By name, not by title: a translated title need not match this class's translation of it.
  if (auto* view_menu = window->findChild<QMenu*>("view_menu")) {
    view_menu->addAction(panel_action_);
    view_menu->addAction(full_screen_action_);
  }
  panel_dock_->show();
  panel_dock_->raise();
}

void ButtonPickerPresenter::ConnectPanel() {
  connect(panel_, &OperatorPanel::Tapped, this, &ButtonPickerPresenter::OnTapped);
  connect(panel_, &OperatorPanel::Confirmed, this, [this] { commands_->Confirm(); });
  connect(panel_, &OperatorPanel::Cancelled, this, [this] { commands_->Cancel(); });
  // STOP reaches the arm at once, not at the next frame.
  connect(panel_, &OperatorPanel::StopPressed, this, [this] { commands_->Stop("operator"); });
  connect(panel_, &OperatorPanel::StartRequested, this, [this] {
    commands_->Restart();  // The only way out of STOP.
    if (!playing_) HoldForPicture();
  });
  connect(panel_, &OperatorPanel::FullScreenToggleRequested, this, [this] {
    if (!operator_mode_) return full_screen_action_->setChecked(false);  // Back to the dock.
    panel_->SetFullScreenMode(!panel_->isFullScreen());
  });
  connect(panel_, &OperatorPanel::LeaveRequested, this, &ButtonPickerPresenter::OnLeave);
}

void ButtonPickerPresenter::EnterOperatorMode() {
  if (panel_ == nullptr) return;
  operator_mode_ = true;
  panel_dock_->hide();
  SetPanelWindowed(true);
}

void ButtonPickerPresenter::SetPanelWindowed(bool on) {
  if (panel_ == nullptr || on == panel_windowed_) return;
  panel_windowed_ = on;
  if (on) {
    panel_->setParent(window_, Qt::Window);  // Still owned by the window, shown on its own.
    panel_->setWindowTitle(tr("Operator panel"));
    panel_->SetFullScreenMode(true);
    panel_->activateWindow();
    panel_->setFocus();
  } else {
    panel_->setWindowState(Qt::WindowNoState);
    panel_dock_->setWidget(panel_);
    panel_->show();
  }
  const QSignalBlocker block(full_screen_action_);
  full_screen_action_->setChecked(on);
}

void ButtonPickerPresenter::OnLeave() {
  if (operator_mode_) {
    emit OperatorLeft();
  } else {
    SetPanelWindowed(false);
  }
}

void ButtonPickerPresenter::Detach() {
  MonoSlamPresenter::Detach();
  if (panel_dock_ == nullptr) return;
  SetPanelWindowed(false);
  if (auto* playback = window_ ? window_->findChild<PlaybackController*>() : nullptr) {
    disconnect(playback, &PlaybackController::PlayStateChanged, this,
               &ButtonPickerPresenter::OnPlayState);
  }
  if (auto* window = qobject_cast<QMainWindow*>(panel_dock_->parentWidget())) {
    for (QAction* menu : window->menuBar()->actions()) {
      if (menu->menu() != nullptr) {
        menu->menu()->removeAction(panel_action_);
        menu->menu()->removeAction(full_screen_action_);
      }
    }
    window->removeAction(full_screen_action_);
  }
  panel_dock_->hide();
}

QString ButtonPickerPresenter::PictureReason() const {
  return ended_ ? tr("End of the recording") : tr("Paused");
}

void ButtonPickerPresenter::HoldForPicture() {
  const OperatorState s = panel_->state();
  if (s == OperatorState::kStopped || s == OperatorState::kConfirm) return;
  panel_->SetState(OperatorState::kHolding, PictureReason());
  panel_->SetRing(std::nullopt);
}

void ButtonPickerPresenter::OnPlayState(bool playing, bool ended) {
  playing_ = playing;
  ended_ = ended;
  // At once, before the next frame: the pipeline publishes nothing while the picture stands
  // still, and a tap it has not taken yet is dropped (never applied to a later frame).
  const bool dropped = commands_->SetHold(!playing);
  if (panel_ == nullptr || playing) return;
  if (dropped) {
    panel_->Refuse(tr("The picture is paused: press Play, then tap"));
  } else {
    HoldForPicture();
  }
}

void ButtonPickerPresenter::OnTapped(QPointF image_px) {
  if (ended_) return panel_->Refuse(tr("The recording has ended: nothing to tap"));
  if (!playing_) return panel_->Refuse(tr("The picture is paused: press Play, then tap"));
  if (!shown_) return panel_->Refuse(tr("No picture yet: open a camera or a recording"));
  ButtonTapRequest tap;
  tap.x = image_px.x();
  tap.y = image_px.y();
  tap.frame = shown_id_;  // The frame on screen: the pipeline finds the button on it.
  tap.stamp_s = shown_stamp_s_;
  commands_->Tap(tap);
}

void ButtonPickerPresenter::Show(const PlaybackResult& result) {
  MonoSlamPresenter::Show(result);
  auto view = std::dynamic_pointer_cast<const ButtonFrameResult>(result.pipeline);
  if (view == nullptr || panel_ == nullptr || !view->slam) return;
  last_result_ = view;
  panel_->SetImage(view->slam->image);
  shown_ = true;
  shown_id_ = result.stamp.sequence_id;
  shown_stamp_s_ = result.stamp.sensor_time_s;
  last_state_ = view->picker.state;
  scale_converged_ = view->scale_converged;
  if (std::optional<ButtonTapAnswer> answer = commands_->TakeAnswer()) ShowTapAnswer(*answer);
  ShowLink(*view);
  ShowRing(*view);
  panel_->SetDistance(view->Stat("button/distance_m").value_or(std::nan("")));
}

void ButtonPickerPresenter::ShowTapAnswer(const ButtonTapAnswer& answer) {
  if (answer.refused != TapRefusal::kNone) {
    panel_->Refuse(TapRefusalText(answer.refused));
  } else if (answer.status.ok()) {
    QPolygonF outline;
    for (const cv::Point& p : answer.candidate_outline) outline << QPointF(p.x, p.y);
    panel_->ShowCandidate(outline);
  } else {
    // The banner says it plainly; the detector's reason is for the log.
    panel_->SetState(OperatorState::kNoButton);
    emit Message(
        0, tr("No button at the tap: %1").arg(QString::fromStdString(answer.status.message())));
  }
}

// "Target sent" only while targets really go out to a connected arm; otherwise holding, and why.
void ButtonPickerPresenter::ShowLink(const ButtonFrameResult& view) {
  const PickerFrame& f = view.picker;
  if (!playing_) return HoldForPicture();  // Whatever a late frame says.
  if (f.state == PickerState::kConfirm || f.state == PickerState::kStopped) return;
  if (f.state == PickerState::kIdle) {
    // "No button here" and refusals stay until the next tap; a hold ends with the picture's.
    if (panel_->state() == OperatorState::kHolding) panel_->SetState(OperatorState::kIdle);
    return;
  }
  if (view.tracking_only) {  // No metres: nothing ever goes to the arm.
    panel_->SetState(OperatorState::kTrackingOnly, tr("No metric scale (no arm motion)"));
    panel_->detail_label()->setToolTip(
        tr("Without the arm's poses the button is tracked and located in map units only; "
           "no target is sent."));
    return;
  }
  if (view.target_published && view.arm_clients > 0) {
    panel_->SetState(OperatorState::kTargetSent);
    panel_->detail_label()->setToolTip({});
    return;
  }
  panel_->SetState(OperatorState::kHolding, HoldText(view));
  panel_->detail_label()->setToolTip(QString::fromStdString(f.verdict.message));
}

void ButtonPickerPresenter::ShowRing(const ButtonFrameResult& view) {
  const PickerFrame& f = view.picker;
  const bool tracking = f.state != PickerState::kIdle && f.state != PickerState::kConfirm &&
                        f.state != PickerState::kStopped && f.track.found;
  if (tracking && panel_->state() != OperatorState::kConfirm) {
    panel_->SetRing(QPointF(f.track.center.x, f.track.center.y), f.track.radius_px);
  } else if (panel_->state() != OperatorState::kConfirm) {
    panel_->SetRing(std::nullopt);
  }
}

}  // namespace sightline
