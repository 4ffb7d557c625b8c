#include "app/sightline/live_status_widget.h"

#include <QTimer>

#include "app/sightline/playback_controller.h"

namespace sightline {

LiveStatusWidget::LiveStatusWidget(PlaybackController* playback, QWidget* parent)
    : QLabel(parent), playback_(playback), timer_(new QTimer(this)) {
  setObjectName("live_status");
  setTextFormat(Qt::RichText);
  timer_->setInterval(500);
  connect(timer_, &QTimer::timeout, this, &LiveStatusWidget::Refresh);
  timer_->start();
  hide();
}

namespace {

// The state in the operator's language (SensorStateName is the key the CLI and logs print).
QString StateText(SensorState state) {
  switch (state) {
    case SensorState::kClosed:
      return LiveStatusWidget::tr("closed");
    case SensorState::kStreaming:
      return LiveStatusWidget::tr("streaming");
    case SensorState::kDisconnected:
      return LiveStatusWidget::tr("disconnected");
  }
  return QString::fromUtf8(SensorStateName(state));
}

}  // namespace

QString LiveStatusWidget::Describe(const SensorStats& s) {
  const char* colour = s.state == SensorState::kStreaming      ? "#2a2"
                       : s.state == SensorState::kDisconnected ? "#d22"
                                                               : "#888";
  return tr("<span style='color:%1'>&#9679;</span> %2 &nbsp;%3 fps &nbsp;dropped %4 &nbsp;"
            "latency %5 ms")
      .arg(QString::fromLatin1(colour), StateText(s.state))
      .arg(s.receive_rate_hz, 0, 'f', 1)
      .arg(s.frames_dropped)
      .arg(s.mean_latency_ms, 0, 'f', 1);
}

void LiveStatusWidget::Refresh() {
  shown_ = playback_ ? playback_->live_stats() : std::nullopt;
  if (!shown_) {
    hide();
    return;
  }
  setText(Describe(*shown_));
  QString tip = QString::fromStdString(shown_->message);
  for (const auto& [key, value] : SensorStatValues(*shown_)) {
    tip += QStringLiteral("\n%1 = %2").arg(QString::fromStdString(key)).arg(value);
  }
  setToolTip(tip);
  show();
}

}  // namespace sightline
