// The playback habits of the window: a seek that would wipe a pipeline's map asks first, and a
// newly opened source starts from empty views.
#include <QDialog>
#include <QMessageBox>
#include <QPushButton>
#include <QSlider>

#include "app/sightline/evaluation_panel.h"
#include "app/sightline/main_window.h"
#include "app/sightline/pipeline_presenter.h"
#include "app/sightline/playback_controller.h"
#include "widgets/image_view.h"
#include "widgets/playback_bar.h"
#include "widgets/time_series_plot.h"

namespace sightline {

namespace {

// Pipelines whose result grows over the run (a map, a trajectory) and starts over at a seek.
bool BuildsAMap(const PipelinePresenter* presenter) {
  const std::string& name = presenter->info().name;
  return name == "mono-slam" || name == "stereo-vo";
}

}  // namespace

void MainWindow::OnSeekRequested(int64_t index) {
  const bool asks =
      active_pipeline_ != nullptr && BuildsAMap(active_pipeline_) && pipeline_frames_ > 0;
  if (asks && playback_bar_->slider()->isSliderDown()) {
    pending_seek_ = index;  // Asked once, when the drag ends.
    return;
  }
  if (asks && !ConfirmMapReset()) {
    playback_bar_->SetPosition(last_shown_id_);  // The slider goes back to the frame shown.
    return;
  }
  pipeline_frames_ = 0;  // The pipeline starts over from the frame sought.
  playback_->Seek(index);
}

bool MainWindow::ConfirmMapReset() {
  QMessageBox box(QMessageBox::Question, tr("Reset the map?"),
                  tr("%1 has built its map over %2 frames. Seeking starts it over from the "
                     "frame you seek to: the map and the trajectory so far are lost.")
                      .arg(active_pipeline_->Title())
                      .arg(pipeline_frames_),
                  QMessageBox::NoButton, this);
  box.setObjectName("seek_reset_question");
  QPushButton* reset = box.addButton(tr("Seek and reset the map"), QMessageBox::AcceptRole);
  reset->setObjectName("seek_reset_yes");
  QPushButton* keep = box.addButton(tr("Keep the map"), QMessageBox::RejectRole);
  keep->setObjectName("seek_reset_no");
  box.setDefaultButton(keep);
  box.exec();
  return box.clickedButton() == reset;
}

void MainWindow::ClearRunViews() {
  // Every image and plot of the window, the pipelines' docks and the evaluation included: none
  // may show the previous source's run next to the new one.
  // Dialogs (the calibration's) keep theirs: they are about their own files.
  const auto in_dialog = [](const QWidget* w) { return qobject_cast<QDialog*>(w->window()); };
  for (ImageView* view : findChildren<ImageView*>()) {
    if (!in_dialog(view)) view->Clear();
  }
  for (TimeSeriesPlot* plot : findChildren<TimeSeriesPlot*>()) {
    if (!in_dialog(plot)) plot->Clear();
  }
  evaluation_panel_->Clear();
}

}  // namespace sightline
