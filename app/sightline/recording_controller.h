// Records what the window plays (a live sensor or a recording) to disk: the Record / Stop
// actions, a chosen folder, and frames written / dropped while it runs.
#pragma once

#include <QObject>
#include <QPointer>
#include <QString>
#include <memory>

#include "core/record/recorder.h"

class QAction;
class QTimer;
class QWidget;

namespace sightline {

class PlaybackController;

// Taps the playback's reading thread (PlaybackController::SetFrameTap) and feeds a Recorder,
// whose bounded queue and writer thread keep the disk off that thread. Live sources drop the
// oldest queued frame when the disk falls behind; recordings wait for it. A write error (disk
// full) stops the recording, and Failed() carries the message naming the file.
//
//   auto* recording = new RecordingController(playback, window);
//   menu->addAction(recording->record_action());
//   connect(recording, &RecordingController::Progress, label, &QLabel::setText);
class RecordingController : public QObject {
  Q_OBJECT

 public:
  RecordingController(PlaybackController* playback, QWidget* dialog_parent);
  ~RecordingController() override;

  // Record... (asks for a folder) and Stop recording; enabled as the state allows.
  QAction* record_action() const { return record_action_; }
  QAction* stop_action() const { return stop_action_; }

  // Starts recording the open source into `dir` (created). False, with Failed(), when nothing
  // is open or the folder cannot be written.
  bool Start(const QString& dir);
  // Where Record... records when the operator picks `chosen`: the folder itself when it is empty
  // or new, otherwise a new sub-folder "sightline-YYYYMMDD-HHMMSS" in it, so that nothing in a
  // used folder is overwritten (Start refuses a folder that holds files).
  static QString FolderFor(const QString& chosen);
  // Writes what is queued and closes the recording; emits Finished(). No-op when idle.
  void Stop();
  bool recording() const { return static_cast<bool>(recorder_); }
  // Counters of the current or last recording.
  RecorderStats stats() const;
  // The sensor folder of the current or last recording.
  const QString& folder() const { return folder_; }

 signals:
  // About twice a second while recording, e.g. "REC 120 written, 0 dropped, 4.1 MB/s".
  void Progress(const QString& text);
  // The recording ended (Stop or a write error); `summary` gives the counts.
  void Finished(const QString& summary);
  // A recording could not start or a write failed; the message names the file.
  void Failed(const QString& message);

 private:
  void ChooseFolderAndStart();
  void Poll();
  void UpdateActions();
  QString Summary() const;

  QPointer<PlaybackController> playback_;  // A sibling; may go first when the window closes.
  QWidget* dialog_parent_;
  QAction* record_action_;
  QAction* stop_action_;
  QTimer* timer_;
  std::shared_ptr<Recorder> recorder_;
  RecorderStats last_stats_;
  uint64_t source_dropped_at_start_ = 0;
  QString folder_;
};

}  // namespace sightline
