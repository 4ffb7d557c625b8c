// The operator panel (widgets/operator_panel.h) against a sightline-node on another machine,
// through the ROS master (File > Connect to ROS master): the node's button_image live (latest
// wins; marked stale, and taps refused, when none arrived for `stale_after_s`), the operator's tap
// with that picture's stamp, Yes / Cancel, and STOP to the node's button topics; the node's gate
// (diagnostics), its `stop` acknowledgement and its button_target on the panel. Master or node
// gone: "Disconnected", taps, Yes and Cancel off, STOP kept and sent on reconnection. The dock
// ("Operator panel (ROS node)") appears when the connected node runs the button pipeline.
// Draw-only: the node decides; the panel sends what the operator asks for.
//
//   auto* remote_panel = new RemoteOperatorPresenter(ros_node_view, window);
//   remote_panel->panel();  // The OperatorPanel in its dock.
#pragma once

#include <Eigen/Geometry>
#include <QObject>
#include <QPointF>
#include <QPolygonF>
#include <QString>
#include <memory>
#include <optional>
#include <string>

class QDockWidget;
class QMainWindow;
class QTimer;

namespace sightline {

class OperatorPanel;
class RosNodeView;
struct RemoteGate;
struct RemoteUpdate;

class RemoteOperatorPresenter : public QObject {
  Q_OBJECT

 public:
  RemoteOperatorPresenter(RosNodeView* node, QMainWindow* window);

  OperatorPanel* panel() const { return panel_; }
  QDockWidget* dock() const { return dock_; }
  // A picture older than this (host time since it arrived) is stale: taps are refused [s].
  void SetStaleAfter(double seconds) { stale_after_s_ = seconds; }
  double stale_after_s() const { return stale_after_s_; }

  // For tests and the status line: pictures shown, the stamp of the one on screen, taps sent,
  // whether the node acknowledged STOP, the node's last target (arm base frame).
  int images_shown() const { return images_shown_; }
  double shown_stamp_s() const { return shown_stamp_s_; }
  int taps_sent() const { return taps_sent_; }
  bool stop_acknowledged() const { return stop_acknowledged_; }
  // Gate reports the panel showed as "Target sent".
  int target_sent_reports() const { return target_sent_reports_; }
  std::optional<Eigen::Vector3d> last_target_m() const { return last_target_m_; }
  // The node's answer to the last tap sent ("found", "no_button", "too_old", ... as the gate's
  // `tap` key), "" while none came.
  const std::string& tap_answer() const { return tap_answer_; }
  // The stamp of the frame whose tracked button the ring on the panel shows.
  double ring_stamp_s() const { return drawn_ring_stamp_s_; }

 signals:
  // The node took STOP (its latched `stop` says so).
  void StopAcknowledged();
  // A button_target arrived (position in metres, in its frame).
  void TargetReceived(double x_m, double y_m, double z_m);

 private:
  void ConnectPanel();
  void OnConnection(bool connected);
  void OnUpdate(const std::shared_ptr<const RemoteUpdate>& update);
  void OnTapped(QPointF image_px);
  void OnStop();
  void ShowGate(const RemoteUpdate& update);
  // The node's answer to the pending tap, when `gate` carries it; returns whether it did.
  bool ShowTapAnswer(const RemoteGate& gate);
  // Rings the tracked button on the picture on screen, with the gate of that very frame.
  void ShowRing();
  void CheckStale();
  void ShowDock();

  RosNodeView* node_;
  QMainWindow* window_;
  QDockWidget* dock_ = nullptr;
  OperatorPanel* panel_ = nullptr;
  QTimer* stale_timer_ = nullptr;
  double stale_after_s_ = 2.0;
  bool connected_ = false;
  bool dock_shown_ = false;
  bool node_gone_ = false;  // The master answers, no node listens to taps.
  int images_shown_ = 0;
  double shown_stamp_s_ = 0;
  double shown_receive_s_ = 0;  // Host time the picture on screen arrived.
  int taps_sent_ = 0;
  bool tap_pending_ = false;  // A tap went out; the node's answer not yet in.
  double tap_stamp_s_ = 0;    // The stamp of the picture it was made on (names its answer).
  int gates_since_tap_ = 0;   // Gate reports since the tap, still without its answer.
  std::string tap_answer_;
  QPolygonF candidate_;  // The node's outline of the button found at the tap (image pixels).
  // The tracked button of the last gate (centre, radius; image pixels) and that frame's stamp.
  std::optional<QPointF> ring_centre_;
  double ring_radius_px_ = 0;
  double ring_stamp_s_ = -1;
  double drawn_ring_stamp_s_ = -1;
  bool answered_ = false;  // Yes or Cancel went out for the tap's candidate.
  QPointF tap_px_;
  bool stop_acknowledged_ = false;
  int target_sent_reports_ = 0;
  std::optional<Eigen::Vector3d> last_target_m_;
};

}  // namespace sightline
