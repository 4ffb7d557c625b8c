#include "app/sightline/button_picker_presenter.h"

#include <QAction>
#include <QDockWidget>
#include <QLabel>
#include <QMainWindow>
#include <QMenu>
#include <QMenuBar>
#include <chrono>
#include <cmath>

#include "app/sightline/button_pipeline_options.h"
#include "core/pipeline/metric_slam_view.h"
#include "core/pipeline/mono_inputs.h"
#include "widgets/operator_panel.h"

namespace sightline {

namespace {

// The mono presenter's processor, then the picker on its result.
class ButtonPickerProcessor : public FrameProcessor {
 public:
  ButtonPickerProcessor(SourceInfo info, PinholeCamera camera, std::unique_ptr<Pipeline> mono,
                        std::shared_ptr<ButtonPickerControls> controls)
      : info_(std::move(info)),
        camera_(camera),
        mono_(std::move(mono)),
        controls_(std::move(controls)) {}

  Status Configure(const OptionSet& options) override {
    SIGHTLINE_RETURN_IF_ERROR(mono_->Configure(options));
    const ButtonPickerOptions picker = options.Extract(ButtonPickerOptions::Describe());
    const MetricViewOptions view = options.Extract(MetricViewOptions::Describe());
    const MonoSlamOptions slam = options.Extract(MonoSlamOptions::Describe());
    MonoSlamRunOptions run = options.Extract(MonoSlamRunOptions::Describe());
    const ButtonGuiOptions gui = options.Extract(ButtonGuiOptions::Describe());
    const ArmServerOptions server_options = options.Extract(ArmServerOptions::Describe());
    std::string error;
    if (!picker.IsValid(&error) || !view.IsValid(&error)) return InvalidArgument(error);
    run.metric_source = "arm";
    std::string source;
    StatusOr<Trajectory> base = LoadMetricCameraPoses(info_.path, run, std::nullopt, &source);
    if (!base.ok()) return base.status().WithContext("button picker: the arm's poses");
    picker_ = std::make_unique<ButtonPicker>(picker);
    metric_ = std::make_unique<MetricSlamView>(*base, slam.scale, view, run.gt_tolerance_s);
    std::shared_ptr<ArmServer> server;
    if (gui.serve) {
      StatusOr<std::unique_ptr<ArmServer>> started = ArmServer::Start(server_options);
      if (!started.ok()) return started.status();
      server = std::move(*started);
    }
    std::lock_guard<std::mutex> lock(controls_->mutex);
    controls_->server = std::move(server);
    return Status::Ok();
  }

  std::shared_ptr<const PipelineFrameResult> ProcessFrame(const Frame& frame) override {
    const auto start = std::chrono::steady_clock::now();
    StatusOr<std::shared_ptr<const PipelineResult>> processed = mono_->Process(frame);
    std::shared_ptr<const PipelineFrameResult> base = processed.ok() ? *processed : nullptr;
    const auto* mono = dynamic_cast<const MonoViewResult*>(base.get());
    if (mono == nullptr || !mono->slam || !picker_) return base;
    auto out = std::make_shared<ButtonViewResult>();
    static_cast<MonoViewResult&>(*out) = *mono;
    const MonoSlamResult& r = *mono->slam;
    SlamView view = metric_->Update(r, camera_);
    out->scale_converged = view.scale_converged;
    std::optional<QPointF> tap;
    bool confirm, cancel, stop, restart;
    std::shared_ptr<ArmServer> server;
    {
      std::lock_guard<std::mutex> lock(controls_->mutex);
      tap = controls_->tap;
      controls_->tap.reset();
      confirm = std::exchange(controls_->confirm, false);
      cancel = std::exchange(controls_->cancel, false);
      stop = std::exchange(controls_->stop, false);
      restart = std::exchange(controls_->start, false);
      server = controls_->server;
    }
    if (stop) picker_->Stop();
    if (restart) picker_->Start();
    if (cancel) picker_->Cancel();
    if (tap) {
      out->tap_answered = true;
      out->tap_status = picker_->Tap(r.image, {tap->x(), tap->y()}, r.stamp.sequence_id);
      if (out->tap_status.ok()) out->candidate_outline = picker_->candidate()->contour;
    }
    if (confirm) picker_->Confirm();
    const std::optional<Eigen::Isometry3d> base_pose =
        metric_->BaseFromCamera(r.stamp.sensor_time_s);
    if (!base_pose) view.tracking = false;
    const double elapsed_s =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    out->picker = picker_->Process(r.stamp.sequence_id, r.stamp.sensor_time_s, r.image, view,
                                   base_pose.value_or(Eigen::Isometry3d::Identity()),
                                   r.stamp.sensor_time_s + elapsed_s);
    if (out->picker.target && server) server->PublishTarget(*out->picker.target);
    out->stats.emplace_back("button/tracking_ms", out->picker.tracking_ms);
    return out;
  }

  std::shared_ptr<const PipelineFrameResult> ReprocessFrame(const Frame& frame) override {
    return ProcessFrame(frame);
  }

  void Reset() override {
    mono_->Reset();
    if (picker_) picker_->Cancel();
  }

 private:
  SourceInfo info_;
  PinholeCamera camera_;
  std::unique_ptr<Pipeline> mono_;
  std::shared_ptr<ButtonPickerControls> controls_;
  std::unique_ptr<ButtonPicker> picker_;
  std::unique_ptr<MetricSlamView> metric_;
};

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

ButtonPickerPresenter::ButtonPickerPresenter(ArmServerOptions server_defaults, bool serve,
                                             QObject* parent)
    : MonoSlamPresenter(parent), server_defaults_(std::move(server_defaults)), serve_(serve) {}

const char* ButtonPickerPresenter::TitleSource() const {
  return QT_TR_NOOP("Button picker (monocular SLAM)");
}

Status ButtonPickerPresenter::DeclareOptions(OptionSet* options) const {
  SIGHTLINE_RETURN_IF_ERROR(MonoSlamPresenter::DeclareOptions(options));
  SIGHTLINE_RETURN_IF_ERROR(options->Declare(ButtonPickerOptions::Describe()));
  SIGHTLINE_RETURN_IF_ERROR(options->Declare(MetricViewOptions::Describe()));
  SIGHTLINE_RETURN_IF_ERROR(options->Declare(ArmServerOptions::Describe(), server_defaults_));
  ButtonGuiOptions gui;
  gui.serve = serve_;
  return options->Declare(ButtonGuiOptions::Describe(), gui);
}

bool ButtonPickerPresenter::Accepts(SourceKind kind) const { return kind == SourceKind::kMono; }

std::unique_ptr<Pipeline> ButtonPickerPresenter::CreateProcessor(const PipelineSource& source) {
  const SourceInfo& info = source.info;
  std::unique_ptr<Pipeline> mono = MonoSlamPresenter::CreateProcessor(source);
  if (!mono || !info.camera) return nullptr;
  return std::make_unique<ButtonPickerProcessor>(info, *info.camera, std::move(mono), controls_);
}

void ButtonPickerPresenter::Attach(QMainWindow* window) {
  MonoSlamPresenter::Attach(window);
  if (panel_dock_ == nullptr) {
    panel_ = new OperatorPanel(window);
    panel_dock_ = new QDockWidget(tr("Operator panel"), window);
    panel_dock_->setObjectName("button_operator_dock");
    panel_dock_->setWidget(panel_);
    connect(panel_, &OperatorPanel::Tapped, this, [this](QPointF px) {
      std::lock_guard<std::mutex> lock(controls_->mutex);
      controls_->tap = px;
    });
    connect(panel_, &OperatorPanel::Confirmed, this, [this] {
      std::lock_guard<std::mutex> lock(controls_->mutex);
      controls_->confirm = true;
    });
    connect(panel_, &OperatorPanel::Cancelled, this, [this] {
      std::lock_guard<std::mutex> lock(controls_->mutex);
      controls_->cancel = true;
    });
    connect(panel_, &OperatorPanel::StopPressed, this, &ButtonPickerPresenter::Stop);
    connect(panel_, &OperatorPanel::StartRequested, this, [this] {
      std::lock_guard<std::mutex> lock(controls_->mutex);
      controls_->start = true;
      if (controls_->server) controls_->server->Resume();
    });
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

void ButtonPickerPresenter::Stop() {
  std::lock_guard<std::mutex> lock(controls_->mutex);
  controls_->stop = true;
  if (controls_->server) controls_->server->PublishStop("operator");  // At once, not next frame.
}

void ButtonPickerPresenter::Show(const PlaybackResult& result) {
  MonoSlamPresenter::Show(result);
  const auto* view = dynamic_cast<const ButtonViewResult*>(result.pipeline.get());
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
  panel_->SetDistance(f.location ? f.location->button_in_camera.norm() : std::nan(""));
}

}  // namespace sightline
