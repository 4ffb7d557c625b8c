// The "ROS node" dock: watches a sightline-node on a ROS master (core/ros/ros_remote.h) from the
// GUI. The node's map is shown as an occupancy image in the dock; its odometry, walls and clouds
// go to the main 3D view; the status bar says whether the master answers.
#pragma once

#include <QObject>
#include <QString>
#include <memory>

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

 signals:
  // The master answers (true) or stopped answering (false).
  void ConnectionChanged(bool connected, const QString& master_uri);
  // A map reached the dock's image view.
  void MapShown(int width, int height);

 private:
  void Apply(const std::shared_ptr<const RemoteUpdate>& update);
  void ShowStatus();

  struct Remote;
  std::unique_ptr<Remote> remote_;
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
