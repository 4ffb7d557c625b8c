// The "ROS node" dock: watches a sightline-node on a ROS master (core/ros/ros_remote.h) from the
// GUI. The node's map is shown as an occupancy image in the dock; its odometry, walls and clouds
// go to the main 3D view; the status bar says whether the master answers. The button pipeline's
// picture, gate and STOP state are handed on (ButtonUpdate) to the remote operator panel, whose
// commands go to the node through Send*.
#pragma once

#include <QObject>
#include <QString>
#include <memory>
#include <string>

#include "core/common/status.h"
#include "core/common/trajectory.h"

class QDockWidget;
class QLabel;

namespace sightline {

class ImageView;
class SceneView;
struct RemoteUpdate;

// Owns the connection (one at a time) and shows what arrives; updates reach the GUI thread as
// queued calls. Without SIGHTLINE_WITH_ROS Connect fails with a message saying so.
//
//   auto* node = new RosNodeView(scene, window);
//   window->addDockWidget(Qt::LeftDockWidgetArea, node->dock());
//   Status s = node->Connect("http://robot:11311", "/");
class RosNodeView : public QObject {
  Q_OBJECT

 public:
  RosNodeView(SceneView* scene, QWidget* parent);
  ~RosNodeView() override;

  // Validates the URI and namespace (the error names the bad one) and connects; the master need
  // not answer yet (the status says "reconnecting" until it does).
  Status Connect(const QString& master_uri, const QString& ros_namespace);
  // Drops the connection and the node's layers in the 3D view.
  void Disconnect();
  bool connected() const { return connected_; }
  // Whether a connection (answering or not) is open.
  bool active() const;
  QDockWidget* dock() const { return dock_; }
  // The status bar's indicator ("ROS: connected to URI").
  QLabel* status_label() const { return status_label_; }
  // Maps received since Connect.
  int maps_shown() const { return maps_shown_; }

  // The operator's commands to the node's button topics (core/ros/ros_remote.h); kUnavailable,
  // with the reason, when they cannot go out.
  Status SendTap(double x, double y, double image_stamp_s);
  Status SendConfirm();
  Status SendCancel();
  // STOP, latched: kept for the node across reconnections (and a new Connect) until a START
  // reaches a node (SendStart Ok). kUnavailable when no node has it yet (it is still kept).
  Status SendStop(const std::string& reason);
  Status SendStart();
  // Whether the node's button pipeline subscribes to the operator's taps now.
  bool node_listening() const;

 signals:
  // The master answers (true) or stopped answering (false).
  void ConnectionChanged(bool connected, const QString& master_uri);
  // A map reached the dock's image view.
  void MapShown(int width, int height);
  // The button pipeline's picture (latest wins: older ones not yet shown are dropped), gate,
  // STOP state and target, on the GUI thread.
  void ButtonUpdate(std::shared_ptr<const RemoteUpdate> update);

 private:
  void Apply(const std::shared_ptr<const RemoteUpdate>& update);
  void ShowStatus();

  struct Remote;
  std::unique_ptr<Remote> remote_;
  std::string stop_reason_;  // The STOP kept for the node, or empty.
  bool stop_kept_ = false;
  SceneView* scene_;
  QDockWidget* dock_;
  ImageView* map_view_;
  QLabel* status_label_;
  QString uri_;
  bool connected_ = false;
  int maps_shown_ = 0;
  Trajectory trajectory_;
};

}  // namespace sightline
