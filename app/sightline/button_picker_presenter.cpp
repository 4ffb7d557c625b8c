#include "app/sightline/button_picker_presenter.h"

#include <QAction>
#include <QDockWidget>
#include <QLabel>
#include <QMainWindow>
#include <QMenu>
#include <QMenuBar>
#include <cmath>

#include "widgets/operator_panel.h"

namespace sightline {

namespace {

// The "button" entry whose declared options take `defaults` ("key=value") at once.
PipelineInfo WithDefaults(PipelineInfo info, std::vector<std::string> defaults) {
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
    case GateReason::kOutsideWorkspace:
      return ButtonPickerPresenter::tr("Button out of reach");
  }
  return {};
}

OperatorState PanelState(PickerState s) {
  switch (s) {
    case PickerState::kIdle:
      return OperatorState::kIdle;
    case PickerState::kConfirm:
      return OperatorState::kConfirm;
    case PickerState::kSearching:
      return OperatorState::kSearching;
    case PickerState::kTracking:
      return OperatorState::kTracking;
    case PickerState::kLocating:
      return OperatorState::kLocating;
    case PickerState::kTargetSent:
      return OperatorState::kTargetSent;
    case PickerState::kLost:
      return OperatorState::kLost;
    case PickerState::kStopped:
      return OperatorState::kStopped;
  }
  return OperatorState::kIdle;
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
          mono_commands, parent),
      commands_(std::move(commands)) {}

const char* ButtonPickerPresenter::TitleSource() const {
  return QT_TR_NOOP("Button picker (monocular SLAM)");
}

void ButtonPickerPresenter::Attach(QMainWindow* window) {
  MonoSlamPresenter::Attach(window);
  if (panel_dock_ == nullptr) {
    panel_ = new OperatorPanel(window);
    panel_dock_ = new QDockWidget(tr("Operator panel"), window);
    panel_dock_->setObjectName("button_operator_dock");
    panel_dock_->setWidget(panel_);
    connect(panel_, &OperatorPanel::Tapped, this, [this](QPointF px) {
      ButtonTapRequest tap;
      tap.x = px.x();
      tap.y = px.y();
      commands_->Tap(tap);
    });
    connect(panel_, &OperatorPanel::Confirmed, this, [this] { commands_->Confirm(); });
    connect(panel_, &OperatorPanel::Cancelled, this, [this] { commands_->Cancel(); });
    // STOP reaches the arm at once, not at the next frame.
    connect(panel_, &OperatorPanel::StopPressed, this, [this] { commands_->Stop("operator"); });
    connect(panel_, &OperatorPanel::StartRequested, this, [this] { commands_->Restart(); });
    full_screen_action_ = new QAction(tr("Operator panel full screen"), window);
    full_screen_action_->setShortcut(QKeySequence(Qt::Key_F11));
    full_screen_action_->setCheckable(true);
    connect(full_screen_action_, &QAction::toggled, this, [this](bool on) {
      panel_dock_->setFloating(on);
      panel_->SetFullScreenMode(on);
    });
  }
  window->addDockWidget(Qt::RightDockWidgetArea, panel_dock_);
  window->addAction(full_screen_action_);
  panel_action_ = panel_dock_->toggleViewAction();
  panel_action_->setText(tr("Operator panel"));
  // By name, not by title: a translated title need not match this class's translation of it.
  if (auto* view_menu = window->findChild<QMenu*>("view_menu")) {
    view_menu->addAction(panel_action_);
    view_menu->addAction(full_screen_action_);
  }
  panel_dock_->show();
}

void ButtonPickerPresenter::Detach() {
  MonoSlamPresenter::Detach();
  if (panel_dock_ == nullptr) return;
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

void ButtonPickerPresenter::Show(const PlaybackResult& result) {
  MonoSlamPresenter::Show(result);
  const auto* view = dynamic_cast<const ButtonFrameResult*>(result.pipeline.get());
  if (view == nullptr || panel_ == nullptr || !view->slam) return;
  panel_->SetImage(view->slam->image);
  if (view->tap_answered) {
    if (view->tap_status.ok()) {
      QPolygonF outline;
      for (const cv::Point& p : view->candidate_outline) outline << QPointF(p.x, p.y);
      panel_->ShowCandidate(outline);
    } else {
      // The banner says it plainly; the detector's reason is for the log.
      panel_->SetState(OperatorState::kNoButton);
      emit Message(
          0,
          tr("No button at the tap: %1").arg(QString::fromStdString(view->tap_status.message())));
    }
  }
  const PickerFrame& f = view->picker;
  last_state_ = f.state;
  scale_converged_ = view->scale_converged;
  if (f.state != PickerState::kIdle && f.state != PickerState::kConfirm) {
    panel_->SetState(PanelState(f.state),
                     f.verdict.send ? QString() : OperatorReasonText(f.verdict.reason));
    panel_->detail_label()->setToolTip(f.verdict.send ? QString()
                                                      : QString::fromStdString(f.verdict.message));
  }
  panel_->SetDistance(view->Stat("button/distance_m").value_or(std::nan("")));
}

}  // namespace sightline
