// The built-in demo: simulated recordings made once into the user's cache folder, so that
// `sightline --demo` needs no data from outside the program.
#pragma once

#include <QFuture>
#include <QObject>
#include <QString>
#include <atomic>

namespace sightline {

// Generates (or finds, when already complete) the demo recordings in the background:
// corridor/ (a robot driving an office corridor: RGB-D, stereo, wheel odometry, ground truth)
// and panel/ (an arm camera approaching a lift button panel: mono, arm poses, button truth).
//
//   auto* demo = new DemoGenerator(DemoGenerator::DefaultFolder(), this);
//   connect(demo, &DemoGenerator::Ready, window, [](const QString& corridor) { ... });
//   demo->Start();
class DemoGenerator : public QObject {
  Q_OBJECT

 public:
  // Frame counts are for tests; the demo uses the defaults.
  explicit DemoGenerator(QString folder, QObject* parent = nullptr, int corridor_frames = 450,
                         int panel_frames = 150);
  ~DemoGenerator() override;

  // <cache>/sightline/demo-v1 in the user's cache folder (~/.cache on Linux).
  static QString DefaultFolder();
  // Starts generating in a worker thread (or reports Ready at once when complete).
  void Start();
  // The recording folders (valid once Ready was emitted).
  QString corridor_path() const;
  QString panel_path() const;

 signals:
  // Frames rendered so far out of the total, for a progress display.
  void Progress(int done, int total);
  void Ready(const QString& corridor_path);
  void Failed(const QString& message);

 private:
  QString folder_;
  int corridor_frames_;
  int panel_frames_;
  std::atomic<bool> cancel_{false};
  QFuture<void> future_;
};

}  // namespace sightline
