// Drives the main window for --screenshot: step N frames, save the window as PNG, quit.
#pragma once

#include <QObject>
#include <QPointer>
#include <QString>
#include <QWidget>

namespace sightline {

class MainWindow;

// Steps the open dataset frame by frame (deterministic: every frame is shown), then grabs the
// window, or `subject` when given (the operator panel in operator mode, which plays instead of
// stepping: the panel holds while paused, so a stepped picture would only say "Paused"). Exits
// the application with 0 on success, 1 with a message on stderr on failure.
class ScreenshotDriver : public QObject {
  Q_OBJECT

 public:
  ScreenshotDriver(MainWindow* window, QString output_path, int frames, int timeout_s,
                   QWidget* subject = nullptr);

 private:
  void OnFrameShown(int64_t sequence_id);
  void Capture();
  void Fail(const QString& message);

  MainWindow* window_;
  QPointer<QWidget> subject_;
  QString output_path_;
  int frames_wanted_;
  int frames_seen_ = 0;
  bool done_ = false;
};

}  // namespace sightline
