// File > Connect to ROS master...: the master's URI (default $ROS_MASTER_URI) and the node's
// namespace.
#pragma once

#include <QDialog>

class QLineEdit;

namespace sightline {

// Asks for the master and the namespace; MainWindow::ConnectRos checks and uses them.
class RosConnectDialog : public QDialog {
  Q_OBJECT

 public:
  explicit RosConnectDialog(QWidget* parent = nullptr);
  // The master's URI as typed (trimmed), e.g. http://robot:11311.
  QString master_uri() const;
  // The node's namespace as typed ("/" by default).
  QString ros_namespace() const;

 private:
  QLineEdit* uri_;
  QLineEdit* namespace_;
};

}  // namespace sightline
