// File > Connect to ROS master...: the master's URI (default $ROS_MASTER_URI) and the node's
// namespace.
#pragma once

#include <QDialog>

class QLineEdit;

namespace sightline {

class RosConnectDialog : public QDialog {
  Q_OBJECT

 public:
  explicit RosConnectDialog(QWidget* parent = nullptr);
  QString master_uri() const;
  QString ros_namespace() const;

 private:
  QLineEdit* uri_;
  QLineEdit* namespace_;
};

}  // namespace sightline
