#include "app/sightline/ros_connect_dialog.h"

#include <QDialogButtonBox>
#include <QFormLayout>
#include <QLabel>
#include <QLineEdit>
#include <QVBoxLayout>

namespace sightline {

RosConnectDialog::RosConnectDialog(QWidget* parent) : QDialog(parent) {
  setWindowTitle(tr("Connect to ROS master"));
  uri_ = new QLineEdit(qEnvironmentVariable("ROS_MASTER_URI", "http://localhost:11311"), this);
  uri_->setObjectName("ros_master_uri");
  namespace_ = new QLineEdit("/", this);
  namespace_->setObjectName("ros_namespace");
  auto* form = new QFormLayout;
  form->addRow(tr("Master URI:"), uri_);
  form->addRow(tr("Node namespace:"), namespace_);
  auto* hint = new QLabel(
      tr("The robot's master, e.g. http://robot:11311. The robot must reach this computer "
         "too: set ROS_IP (or ROS_HOSTNAME) before starting Sightline."),
      this);
  hint->setWordWrap(true);
  auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
  connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
  connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
  auto* layout = new QVBoxLayout(this);
  layout->addLayout(form);
  layout->addWidget(hint);
  layout->addWidget(buttons);
}

QString RosConnectDialog::master_uri() const { return uri_->text().trimmed(); }
QString RosConnectDialog::ros_namespace() const { return namespace_->text().trimmed(); }

}  // namespace sightline
