// File > Connect to ROS master... / Disconnect, the "ROS node" dock (ros_node_view.h) and the
// node's operator panel (remote_operator_presenter.h).
#include <QAction>
#include <QDockWidget>
#include <QLabel>
#include <QMenu>
#include <QMessageBox>
#include <QStatusBar>

#include "app/sightline/main_window.h"
#include "app/sightline/remote_operator_presenter.h"
#include "app/sightline/ros_connect_dialog.h"
#include "app/sightline/ros_node_view.h"

namespace sightline {

void MainWindow::BuildRos(QMenu* file) {
  ros_node_ = new RosNodeView(scene_view_, this);
  addDockWidget(Qt::LeftDockWidgetArea, ros_node_->dock());
  tabifyDockWidget(secondary_dock_, ros_node_->dock());
  secondary_dock_->raise();
  statusBar()->addPermanentWidget(ros_node_->status_label());
  remote_operator_ = new RemoteOperatorPresenter(ros_node_, this);
  QAction* connect_action = file->addAction(tr("Connect to &ROS master..."));
  QAction* disconnect_action = file->addAction(tr("&Disconnect from ROS master"));
  disconnect_action->setEnabled(false);
  connect(connect_action, &QAction::triggered, this, [this, disconnect_action] {
    RosConnectDialog dialog(this);
    if (dialog.exec() != QDialog::Accepted) return;
    const Status connected = ConnectRos(dialog.master_uri(), dialog.ros_namespace());
    if (!connected.ok()) {
      QMessageBox::warning(this, tr("Connect to ROS master"),
                           QString::fromStdString(connected.message()));
    }
    disconnect_action->setEnabled(ros_node_->active());
  });
  connect(disconnect_action, &QAction::triggered, this, [this, disconnect_action] {
    ros_node_->Disconnect();
    disconnect_action->setEnabled(false);
    statusBar()->showMessage(tr("Disconnected from the ROS master"), 5000);
  });
}

Status MainWindow::ConnectRos(const QString& master_uri, const QString& ros_namespace) {
  const Status connected = ros_node_->Connect(master_uri, ros_namespace);
  if (connected.ok()) {
    ros_node_->dock()->show();
    ros_node_->dock()->raise();
  }
  return connected;
}

}  // namespace sightline
