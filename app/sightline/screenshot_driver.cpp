#include "app/sightline/screenshot_driver.h"

#include <QApplication>
#include <QPixmap>
#include <QTimer>
#include <cstdio>

#include "app/sightline/main_window.h"
#include "app/sightline/playback_controller.h"

namespace sightline {

ScreenshotDriver::ScreenshotDriver(MainWindow* window, QString output_path, int frames,
                                   int timeout_s, QWidget* subject)
    : QObject(window),
      window_(window),
      subject_(subject),
      output_path_(std::move(output_path)),
      frames_wanted_(frames < 1 ? 1 : frames) {
  connect(window_, &MainWindow::DatasetOpened, this, [this] {
    if (subject_ != nullptr) {
      window_->playback()->Play();
    } else {
      window_->playback()->Step();
    }
  });
  connect(window_, &MainWindow::DatasetFailed, this, &ScreenshotDriver::Fail);
  connect(window_, &MainWindow::FrameShown, this, &ScreenshotDriver::OnFrameShown);
  connect(window_->playback(), &PlaybackController::EndOfStream, this, [this] {
    if (!done_) QTimer::singleShot(300, this, &ScreenshotDriver::Capture);  // Fewer frames.
  });
  connect(window_->playback(), &PlaybackController::ReadError, this, &ScreenshotDriver::Fail);
  QTimer::singleShot(timeout_s * 1000, this, [this, timeout_s] {
    Fail(QStringLiteral("no frame shown within %1 s").arg(timeout_s));
  });
}

void ScreenshotDriver::OnFrameShown(int64_t) {
  if (done_) return;
  if (++frames_seen_ >= frames_wanted_) {
    // Let the views render the last frame before grabbing.
    QTimer::singleShot(300, this, &ScreenshotDriver::Capture);
  } else if (subject_ == nullptr) {
    window_->playback()->Step();
  }
}

void ScreenshotDriver::Capture() {
  if (done_) return;
  done_ = true;
  QWidget* subject = subject_ ? subject_.data() : window_;
  const QPixmap shot = subject->grab();
  if (shot.isNull() || !shot.save(output_path_, "PNG")) {
    std::fprintf(stderr, "sightline: could not write screenshot %s\n", qPrintable(output_path_));
    QApplication::exit(1);
    return;
  }
  std::printf("sightline: wrote %s (%d frames shown)\n", qPrintable(output_path_), frames_seen_);
  QApplication::exit(0);
}

void ScreenshotDriver::Fail(const QString& message) {
  if (done_) return;
  done_ = true;
  std::fprintf(stderr, "sightline: screenshot failed: %s\n", qPrintable(message));
  QApplication::exit(1);
}

}  // namespace sightline
