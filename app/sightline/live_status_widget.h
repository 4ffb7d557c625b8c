// The status bar's live-sensor indicator: connection state, frame rate, dropped frames and
// latency of the open live source, refreshed while it runs.
#pragma once

#include <QLabel>
#include <QPointer>
#include <optional>

#include "core/sensors/sensor_stats.h"

class QTimer;

namespace sightline {

class PlaybackController;

// Polls PlaybackController::live_stats() twice a second (a cheap locked copy) and shows e.g.
// "● streaming  29.8 fps  dropped 3  latency 4.2 ms"; hidden when no live source is open. The
// tooltip lists every counter of SensorStatValues().
class LiveStatusWidget : public QLabel {
  Q_OBJECT

 public:
  explicit LiveStatusWidget(PlaybackController* playback, QWidget* parent = nullptr);

  // The snapshot shown last (nullopt when no live source is open).
  const std::optional<SensorStats>& shown() const { return shown_; }
  // Reads the counters now (the timer calls it).
  void Refresh();

  // The one-line text for a snapshot.
  static QString Describe(const SensorStats& stats);

 private:
  QPointer<PlaybackController> playback_;  // A sibling; may go first when the window closes.
  QTimer* timer_;
  std::optional<SensorStats> shown_;
};

}  // namespace sightline
