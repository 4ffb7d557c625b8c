// MainWindow's recording wiring, kept apart from the views and pipelines.
#include <QLabel>
#include <QMenu>
#include <QStatusBar>
#include <QToolBar>

#include "app/sightline/live_status_widget.h"
#include "app/sightline/main_window.h"
#include "app/sightline/recording_controller.h"
#include "widgets/log_panel.h"

namespace sightline {

void MainWindow::BuildRecording(QMenu* sensors) {
  recording_ = new RecordingController(playback_, this);
  sensors->addSeparator();
  sensors->addAction(recording_->record_action());
  sensors->addAction(recording_->stop_action());
  auto* bar = new QToolBar(tr("Recording"), this);
  bar->setObjectName("recording_toolbar");
  bar->addAction(recording_->record_action());
  bar->addAction(recording_->stop_action());
  addToolBar(Qt::TopToolBarArea, bar);

  live_status_ = new LiveStatusWidget(playback_, this);
  statusBar()->addPermanentWidget(live_status_);
  auto* progress = new QLabel(this);
  progress->setObjectName("recording_status");
  statusBar()->addPermanentWidget(progress);
  connect(recording_, &RecordingController::Progress, progress, &QLabel::setText);
  connect(recording_, &RecordingController::Finished, this, [this, progress](const QString& text) {
    progress->clear();
    log_panel_->AddMessage(LogPanel::Severity::kInfo, text);
    statusBar()->showMessage(text, 10000);
  });
  connect(recording_, &RecordingController::Failed, this, [this](const QString& message) {
    log_panel_->AddMessage(LogPanel::Severity::kError, tr("Recording: %1").arg(message));
  });
}

}  // namespace sightline
