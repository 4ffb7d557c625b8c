#include "app/sightline/remote_operator_presenter.h"

#include <QDockWidget>
#include <QLabel>
#include <QMainWindow>
#include <QPolygonF>
#include <QTimer>
#include <cmath>

#include "app/sightline/button_picker_presenter.h"
#include "app/sightline/ros_node_view.h"
#include "core/button/safety_gate.h"
#include "core/common/timing.h"
#include "core/ros/ros_remote.h"
#include "widgets/operator_panel.h"

namespace sightline {

namespace {

// Gate reports after a tap without its answer (the gate's `tap` key on the frame that took
// it): the tap or the answer was lost on the way. The node answers on its next frame; these
// allow for frames already in flight.
constexpr int kGatesWithoutAnswer = 30;
// Half the side of the square drawn around the tapped point while the question is open, when
// the node sent no outline of the button it found [image pixels].
constexpr double kTapMarkPx = 18;

// The gate's reason from its key ("tracking_lost"), or nullopt for a key this build does not know.
std::optional<GateReason> ReasonOfKey(const std::string& key) {
  for (int r = 0; r <= static_cast<int>(GateReason::kOutsideWorkspace); ++r) {
    if (key == GateReasonKey(static_cast<GateReason>(r))) return static_cast<GateReason>(r);
  }
  return std::nullopt;
}

bool IsTracking(OperatorState s) {
  return s == OperatorState::kSearching || s == OperatorState::kTracking ||
         s == OperatorState::kLocating || s == OperatorState::kTargetSent ||
         s == OperatorState::kLost || s == OperatorState::kHolding ||
         s == OperatorState::kTrackingOnly;
}

}  // namespace

RemoteOperatorPresenter::RemoteOperatorPresenter(RosNodeView* node, QMainWindow* window)
    : QObject(window), node_(node), window_(window) {
  panel_ = new OperatorPanel(window);
  panel_->SetLink(OperatorLink::kDisconnected);
  dock_ = new QDockWidget(tr("Operator panel (ROS node)"), window);
  dock_->setObjectName("ros_operator_dock");
  dock_->setWidget(panel_);
  window->addDockWidget(Qt::RightDockWidgetArea, dock_);
  dock_->hide();  // Until the node shows it runs the button pipeline (View lists the dock).
  stale_timer_ = new QTimer(this);
  stale_timer_->setInterval(250);
  connect(stale_timer_, &QTimer::timeout, this, &RemoteOperatorPresenter::CheckStale);
  stale_timer_->start();
  connect(node_, &RosNodeView::ConnectionChanged, this,
          [this](bool connected, const QString&) { OnConnection(connected); });
  connect(node_, &RosNodeView::ButtonUpdate, this, &RemoteOperatorPresenter::OnUpdate);
  ConnectPanel();
}

void RemoteOperatorPresenter::ConnectPanel() {
  connect(panel_, &OperatorPanel::Tapped, this, &RemoteOperatorPresenter::OnTapped);
  // STOP first, whatever the link: RosNodeView keeps it for the node until Start again.
  connect(panel_, &OperatorPanel::StopPressed, this, &RemoteOperatorPresenter::OnStop);
  connect(panel_, &OperatorPanel::Confirmed, this, [this] {
    answered_ = true;
    const Status sent = node_->SendConfirm();
    if (!sent.ok()) panel_->Refuse(QString::fromStdString(sent.message()));
  });
  connect(panel_, &OperatorPanel::Cancelled, this, [this] {
    answered_ = true;
    tap_pending_ = false;
    (void)node_->SendCancel();  // Nothing goes to the arm without Yes anyway.
  });
  connect(panel_, &OperatorPanel::StartRequested, this, [this] {
    const Status sent = node_->SendStart();
    if (sent.ok()) {
      stop_acknowledged_ = false;
      return;
    }
    // The robot did not hear START: it stays stopped, and so does the panel.
    panel_->ReturnToStop(tr("Start did not reach the robot: still stopped"));
    panel_->detail_label()->setToolTip(QString::fromStdString(sent.message()));
  });
}

void RemoteOperatorPresenter::ShowDock() {
  if (dock_shown_) return;
  dock_shown_ = true;
  dock_->show();
  dock_->raise();
}

void RemoteOperatorPresenter::OnConnection(bool connected) {
  connected_ = connected;
  tap_pending_ = false;
  // After a reconnection the picture on screen is old until the node sends a new one.
  panel_->SetLink(connected ? OperatorLink::kWaiting : OperatorLink::kDisconnected);
}

void RemoteOperatorPresenter::OnStop() {
  stop_acknowledged_ = false;
  tap_pending_ = false;
  const Status sent = node_->SendStop("operator");
  panel_->SetDetailText(sent.ok() ? tr("STOP sent: waiting for the robot")
                                  : tr("STOP kept: sent as soon as the robot is reachable"));
  panel_->detail_label()->setToolTip(QString::fromStdString(sent.message()));
}

void RemoteOperatorPresenter::OnTapped(QPointF image_px) {
  const Status sent = node_->SendTap(image_px.x(), image_px.y(), shown_stamp_s_);
  if (!sent.ok()) return panel_->Refuse(QString::fromStdString(sent.message()));
  ++taps_sent_;
  tap_pending_ = true;
  tap_stamp_s_ = shown_stamp_s_;
  tap_answer_.clear();
  candidate_.clear();
  answered_ = false;
  gates_since_tap_ = 0;
  tap_px_ = image_px;
  panel_->SetState(OperatorState::kSearching);
}

void RemoteOperatorPresenter::OnUpdate(const std::shared_ptr<const RemoteUpdate>& update) {
  switch (update->kind) {
    case RemoteUpdate::Kind::kButtonImage:
      ShowDock();
      panel_->SetImage(update->image);
      ++images_shown_;
      shown_stamp_s_ = update->stamp_s;
      shown_receive_s_ = update->receive_s;
      ShowRing();
      if (connected_) panel_->SetLink(OperatorLink::kLive);
      break;
    case RemoteUpdate::Kind::kGate:
      ShowDock();
      ring_stamp_s_ = update->stamp_s;
      ring_centre_.reset();
      if (update->gate.ring) {
        ring_centre_ = QPointF(update->gate.ring->x, update->gate.ring->y);
        ring_radius_px_ = update->gate.ring->z;
      }
      ShowGate(*update);
      ShowRing();
      break;
    case RemoteUpdate::Kind::kStopState:
      if (update->stopped && panel_->state() == OperatorState::kStopped && !stop_acknowledged_) {
        stop_acknowledged_ = true;
        panel_->SetDetailText(tr("The robot confirmed STOP"));
        emit StopAcknowledged();
      }
      break;
    case RemoteUpdate::Kind::kTarget: {
      const Eigen::Vector3d p = update->target.pose.translation();
      last_target_m_ = p;
      if (panel_->state() == OperatorState::kTargetSent) {
        panel_->SetDetailText(tr("Target %1, %2, %3 m (%4)")
                                  .arg(p.x(), 0, 'f', 3)
                                  .arg(p.y(), 0, 'f', 3)
                                  .arg(p.z(), 0, 'f', 3)
                                  .arg(QString::fromStdString(update->target.frame_id)));
      }
      emit TargetReceived(p.x(), p.y(), p.z());
      break;
    }
    default:
      break;
  }
}

// The node's picker state and gate verdict, in the panel's words.
void RemoteOperatorPresenter::ShowGate(const RemoteUpdate& update) {
  const RemoteGate& gate = update.gate;
  const OperatorState shown = panel_->state();
  if (shown == OperatorState::kStopped) return;  // Only "Start again" leaves STOP.
  if (tap_pending_ && ShowTapAnswer(gate)) return;
  if (gate.state == "confirm") {
    tap_pending_ = false;
    // Frames the node reported before it heard Yes or Cancel do not ask again.
    if (!answered_ && shown != OperatorState::kConfirm) {
      // The node's outline of the button it found; a square about the tap from a node that
      // sent none.
      const QPointF d(kTapMarkPx, kTapMarkPx);
      panel_->ShowCandidate(candidate_.size() >= 3 ? candidate_
                                                   : QPolygonF(QRectF(tap_px_ - d, tap_px_ + d)));
    }
    return;
  }
  if (tap_pending_) {
    if (++gates_since_tap_ < kGatesWithoutAnswer) return;
    tap_pending_ = false;
    return panel_->Refuse(tr("The robot did not answer the tap: tap again"));
  }
  if (gate.state == "idle" || gate.state == "stopped") {
    if (IsTracking(shown) || shown == OperatorState::kConfirm)
      panel_->SetState(OperatorState::kIdle);
    return;
  }
  panel_->detail_label()->setToolTip(QString::fromStdString(gate.message));
  if (gate.tracking_only) {
    return panel_->SetState(OperatorState::kTrackingOnly,
                            ButtonPickerPresenter::tr("No metric scale (no arm motion)"));
  }
  if (gate.reason == "send") {
    ++target_sent_reports_;
    if (shown != OperatorState::kTargetSent) panel_->SetState(OperatorState::kTargetSent);
    return;
  }
  if (gate.held) {
    return panel_->SetState(OperatorState::kHolding, ButtonPickerPresenter::tr("Paused"));
  }
  const std::optional<GateReason> reason = ReasonOfKey(gate.reason);
  const QString why = reason ? OperatorReasonText(*reason) : QString();
  panel_->SetState(OperatorState::kHolding,
                   why.isEmpty() ? ButtonPickerPresenter::tr("Waiting") : why);
}

void RemoteOperatorPresenter::ShowRing() {
  const OperatorState s = panel_->state();
  if (s == OperatorState::kConfirm) return;  // The question's outline stays alone.
  // The ring of another frame than the one on screen would sit off the button while it moves;
  // it waits for its picture (or the picture for its gate).
  if (std::abs(ring_stamp_s_ - shown_stamp_s_) > 1e-6) return;
  const bool tracking = IsTracking(s) && s != OperatorState::kSearching;
  if (tracking && ring_centre_) {
    panel_->SetRing(*ring_centre_, ring_radius_px_);
    drawn_ring_stamp_s_ = ring_stamp_s_;
  } else {
    panel_->SetRing(std::nullopt);
  }
}

bool RemoteOperatorPresenter::ShowTapAnswer(const RemoteGate& gate) {
  // An answer to an earlier tap (the operator tapped again since) is not this tap's.
  if (gate.tap.empty() || std::abs(gate.tap_stamp_s - tap_stamp_s_) > 1e-6) return false;
  tap_answer_ = gate.tap;
  tap_pending_ = false;
  if (gate.tap == "found") {  // The same frame's state asks ("confirm") about this outline.
    candidate_.clear();
    for (const cv::Point& p : gate.candidate) candidate_ << QPointF(p.x, p.y);
    return false;
  }
  if (gate.tap == "no_button") {
    panel_->SetState(OperatorState::kNoButton);
    return true;
  }
  const std::optional<TapRefusal> refusal = TapRefusalOfKey(gate.tap);
  const QString why = refusal ? TapRefusalText(*refusal) : QString();
  panel_->Refuse(why.isEmpty() ? tr("The robot did not take the tap: tap again") : why);
  return true;
}

void RemoteOperatorPresenter::CheckStale() {
  if (!connected_ || images_shown_ == 0) return;
  // The master answers but the node that sent the pictures is gone (ended, crashed).
  if (!node_->node_listening()) {
    node_gone_ = true;
    return panel_->SetLink(OperatorLink::kDisconnected, tr("The robot's node is gone"));
  }
  if (node_gone_) {  // A node is back: live again with its first picture.
    node_gone_ = false;
    panel_->SetLink(OperatorLink::kWaiting);
  }
  const double age_s = HostTimeS() - shown_receive_s_;
  if (age_s > stale_after_s_) {
    panel_->SetLink(OperatorLink::kStale, tr("No picture for %1 s").arg(std::floor(age_s)));
  }
}

}  // namespace sightline
