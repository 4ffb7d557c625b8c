#include "app/sightline/recording_controller.h"

#include <QAction>
#include <QDateTime>
#include <QDir>
#include <QFileDialog>
#include <QTimer>
#include <QWidget>

#include "app/sightline/playback_controller.h"

namespace sightline {

RecordingController::RecordingController(PlaybackController* playback, QWidget* dialog_parent)
    : QObject(dialog_parent), playback_(playback), dialog_parent_(dialog_parent) {
  record_action_ = new QAction(tr("&Record..."), this);
  record_action_->setObjectName("record_action");
  record_action_->setShortcut(Qt::CTRL | Qt::SHIFT | Qt::Key_R);
  record_action_->setToolTip(
      tr("Record what is playing (live sensor or recording) into a folder, in the formats "
         "Sightline reads"));
  stop_action_ = new QAction(tr("&Stop recording"), this);
  stop_action_->setObjectName("stop_recording_action");
  timer_ = new QTimer(this);
  timer_->setInterval(500);
  connect(record_action_, &QAction::triggered, this, &RecordingController::ChooseFolderAndStart);
  connect(stop_action_, &QAction::triggered, this, &RecordingController::Stop);
  connect(timer_, &QTimer::timeout, this, &RecordingController::Poll);
  // Another source replaces the recorded one: the recording ends with it.
  connect(playback_, &PlaybackController::Opened, this, &RecordingController::Stop);
  UpdateActions();
}

RecordingController::~RecordingController() {
  if (playback_) playback_->SetFrameTap(nullptr);
  if (recorder_) (void)recorder_->Stop();
}

void RecordingController::ChooseFolderAndStart() {
  const QString dir =
      QFileDialog::getExistingDirectory(dialog_parent_, tr("Record into folder"), QDir::homePath());
  if (!dir.isEmpty()) Start(FolderFor(dir));
}

QString RecordingController::FolderFor(const QString& chosen) {
  const QDir dir(chosen);
  if (!dir.exists() ||
      dir.isEmpty(QDir::AllEntries | QDir::NoDotAndDotDot | QDir::Hidden | QDir::System)) {
    return chosen;
  }
  const QString stamp = QDateTime::currentDateTime().toString("yyyyMMdd-HHmmss");
  QString name = "sightline-" + stamp;
  for (int n = 2; dir.exists(name); ++n) name = QString("sightline-%1-%2").arg(stamp).arg(n);
  return dir.filePath(name);
}

bool RecordingController::Start(const QString& dir) {
  if (recorder_) Stop();
  if (!playback_ || !playback_->is_open()) {
    emit Failed(tr("Nothing to record: open a sensor or a recording first."));
    return false;
  }
  const SourceInfo& info = *playback_->info();
  RecorderOptions options;
  options.block_when_full = !info.live;  // Recordings can wait for the disk; sensors cannot.
  StatusOr<std::unique_ptr<Recorder>> started = Recorder::Start(dir.toStdString(), info, options);
  if (!started.ok()) {
    emit Failed(QString::fromStdString(started.status().ToString()));
    return false;
  }
  recorder_ = std::move(*started);
  folder_ = QString::fromStdString(recorder_->folder());
  const std::optional<SensorStats> sensor = playback_->live_stats();
  source_dropped_at_start_ = sensor ? sensor->frames_dropped : 0;
  // The tap runs on the reading thread and holds its own reference to the recorder.
  std::shared_ptr<Recorder> recorder = recorder_;
  playback_->SetFrameTap([recorder](const Frame& frame) { recorder->Push(frame); });
  timer_->start();
  UpdateActions();
  Poll();
  return true;
}

void RecordingController::Stop() {
  if (!recorder_) return;
  if (playback_) playback_->SetFrameTap(nullptr);
  timer_->stop();
  const Status stopped = recorder_->Stop();
  last_stats_ = recorder_->stats();
  recorder_.reset();
  UpdateActions();
  if (!stopped.ok()) emit Failed(QString::fromStdString(stopped.ToString()));
  emit Finished(Summary());
}

RecorderStats RecordingController::stats() const {
  return recorder_ ? recorder_->stats() : last_stats_;
}

QString RecordingController::Summary() const {
  const RecorderStats s = stats();
  return tr("Recorded %1 frames into %2 (%3 dropped by the recorder), %4 MB at %5 MB/s")
      .arg(s.frames_written)
      .arg(folder_)
      .arg(s.frames_dropped)
      .arg(static_cast<double>(s.bytes_written) / 1e6, 0, 'f', 1)
      .arg(s.write_mb_per_s, 0, 'f', 1);
}

void RecordingController::Poll() {
  if (!recorder_) return;
  if (!recorder_->status().ok()) {  // Disk full or similar: the recorder has stopped writing.
    Stop();
    return;
  }
  const RecorderStats s = recorder_->stats();
  const std::optional<SensorStats> sensor =
      playback_ ? playback_->live_stats() : std::optional<SensorStats>();
  const uint64_t source_dropped =
      sensor ? sensor->frames_dropped - std::min(sensor->frames_dropped, source_dropped_at_start_)
             : 0;
  emit Progress(tr("REC %1 written, %2 dropped, %3 MB/s")
                    .arg(s.frames_written)
                    .arg(s.frames_dropped + source_dropped)
                    .arg(s.write_mb_per_s, 0, 'f', 1));
}

void RecordingController::UpdateActions() {
  record_action_->setEnabled(!recorder_);
  stop_action_->setEnabled(static_cast<bool>(recorder_));
}

}  // namespace sightline
