// MainWindow's File > Save results and Tools > Evaluate current run: the running pipeline
// writes exactly what `sightline-cli run` writes, and the evaluation compares its trajectory with
// the open dataset's ground truth.
#include <QDateTime>
#include <QDir>
#include <QDockWidget>
#include <QFileDialog>
#include <QFileInfo>
#include <QMenu>
#include <QStandardPaths>
#include <QStatusBar>
#include <QTemporaryDir>

#include "app/sightline/evaluation_panel.h"
#include "app/sightline/main_window.h"
#include "app/sightline/pipeline_presenter.h"
#include "app/sightline/playback_controller.h"
#include "core/common/trajectory.h"
#include "widgets/log_panel.h"

namespace sightline {

namespace {

// The registry's name of a presenter's pipeline ("stereo-vo"), for metrics.json.
QString PipelineName(const PipelinePresenter* presenter) {
  if (presenter == nullptr) return QString();
  if (!presenter->info().name.empty()) return QString::fromStdString(presenter->info().name);
  return QString::fromUtf8(presenter->TitleSource());
}

}  // namespace

void MainWindow::BuildResults(QMenu* file) {
  QAction* save = file->addAction(tr("&Save results..."));
  save->setShortcut(QKeySequence::Save);
  save->setToolTip(
      tr("Writes the running pipeline's results as sightline-cli run does: "
         "metrics.json, trajectory, maps, clouds and tables."));
  connect(save, &QAction::triggered, this, [this] {
    const QString base = QStandardPaths::writableLocation(QStandardPaths::HomeLocation) +
                         "/sightline-runs/" + PipelineName(active_pipeline_) + "-" +
                         QDateTime::currentDateTime().toString("yyyyMMdd-HHmmss");
    const QString folder = QFileDialog::getSaveFileName(this, tr("Save results into folder"), base);
    if (!folder.isEmpty()) SaveResultsTo(folder);
  });
  connect(playback_, &PlaybackController::ResultsSaved, this,
          [this](const QString& folder, const QStringList& files) {
            if (evaluation_folder_ && folder == evaluation_folder_->path()) {
              EvaluateSavedRun(folder);
              return;
            }
            log_panel_->AddMessage(
                LogPanel::Severity::kInfo,
                tr("Saved %1 in %2").arg(files.join(", "), QDir::toNativeSeparators(folder)));
            statusBar()->showMessage(tr("Results saved in %1").arg(folder), 10000);
            emit ResultsSaved(folder);
          });
  connect(playback_, &PlaybackController::SaveFailed, this, [this](const QString& message) {
    log_panel_->AddMessage(LogPanel::Severity::kError,
                           tr("Could not save results: %1").arg(message));
    emit ResultsSaveFailed(message);
  });
}

void MainWindow::SaveResultsTo(const QString& folder) {
  playback_->SaveResults(folder, PipelineName(active_pipeline_));
}

void MainWindow::EvaluateCurrentRun() {
  evaluation_dock_->show();
  evaluation_dock_->raise();
  if (active_pipeline_ == nullptr || playback_->ground_truth() == nullptr) {
    log_panel_->AddMessage(LogPanel::Severity::kWarning,
                           tr("Evaluate current run needs a running pipeline on a dataset with "
                              "ground truth; choose two trajectory files instead."));
    return;
  }
  evaluation_folder_ = std::make_unique<QTemporaryDir>();
  if (!evaluation_folder_->isValid()) {
    log_panel_->AddMessage(LogPanel::Severity::kError,
                           tr("Could not make a temporary folder for the evaluation."));
    return;
  }
  SaveResultsTo(evaluation_folder_->path());  // EvaluateSavedRun follows.
}

void MainWindow::EvaluateSavedRun(const QString& folder) {
  const QString estimate = folder + "/trajectory.txt";
  const QString ground_truth = folder + "/ground_truth.txt";
  const Trajectory* truth = playback_->ground_truth();
  if (!QFileInfo::exists(estimate) || truth == nullptr) {
    log_panel_->AddMessage(LogPanel::Severity::kWarning,
                           tr("%1 writes no trajectory to evaluate.")
                               .arg(active_pipeline_ ? active_pipeline_->Title() : QString()));
    return;
  }
  const Status written = WriteTumTrajectory(*truth, ground_truth.toStdString());
  if (!written.ok()) {
    log_panel_->AddMessage(LogPanel::Severity::kError, QString::fromStdString(written.ToString()));
    return;
  }
  // A monocular estimate has no metric scale of its own.
  const bool monocular = PipelineName(active_pipeline_) == "mono-slam";
  evaluation_panel_->Evaluate(estimate, ground_truth, monocular ? "sim3" : "se3");
}

}  // namespace sightline
