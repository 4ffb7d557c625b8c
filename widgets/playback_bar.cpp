#include "widgets/playback_bar.h"

#include <QCheckBox>
#include <QComboBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QMouseEvent>
#include <QSignalBlocker>
#include <QSlider>
#include <QStyle>
#include <QStyleOptionSlider>
#include <QToolButton>
#include <algorithm>
#include <climits>

namespace sightline {

PlaybackBar::PlaybackBar(QWidget* parent) : QWidget(parent) {
  auto* layout = new QHBoxLayout(this);
  layout->setContentsMargins(4, 2, 4, 2);

  play_button_ = new QToolButton(this);
  play_button_->setAutoRaise(true);
  connect(play_button_, &QToolButton::clicked, this, [this] {
    // The bar only asks; the icon changes when the player confirms with SetPlaying.
    if (playing_) {
      emit PauseRequested();
    } else {
      emit PlayRequested();
    }
  });
  layout->addWidget(play_button_);

  step_button_ = new QToolButton(this);
  step_button_->setAutoRaise(true);
  step_button_->setIcon(style()->standardIcon(QStyle::SP_MediaSkipForward));
  step_button_->setToolTip(tr("Step one frame"));
  connect(step_button_, &QToolButton::clicked, this, &PlaybackBar::StepRequested);
  layout->addWidget(step_button_);

  slider_ = new QSlider(Qt::Horizontal, this);
  slider_->setRange(0, 0);
  slider_->installEventFilter(this);  // Click-to-seek (eventFilter).
  connect(slider_, &QSlider::valueChanged, this, [this](int value) {
    position_ = value;
    UpdateLabel();
    emit SeekRequested(value);
  });
  layout->addWidget(slider_, 1);

  frame_label_ = new QLabel(this);
  frame_label_->setMinimumWidth(frame_label_->fontMetrics().horizontalAdvance("000000 / 000000"));
  frame_label_->setAlignment(Qt::AlignRight | Qt::AlignVCenter);
  layout->addWidget(frame_label_);

  speed_box_ = new QComboBox(this);
  speed_box_->setToolTip(tr("Playback speed relative to the recording's timestamps"));
  for (double factor : {0.25, 0.5, 1.0, 2.0, 4.0}) {
    speed_box_->addItem(QStringLiteral("%1x").arg(factor), factor);
  }
  speed_box_->addItem(tr("max"), 0.0);
  speed_box_->setCurrentIndex(2);
  connect(speed_box_, &QComboBox::currentIndexChanged, this,
          [this](int) { emit SpeedChanged(speed()); });
  layout->addWidget(speed_box_);

  loop_box_ = new QCheckBox(tr("Loop"), this);
  connect(loop_box_, &QCheckBox::toggled, this, &PlaybackBar::LoopChanged);
  layout->addWidget(loop_box_);

  UpdatePlayButton();
  SetFrameCount(0);
}

PlaybackBar::~PlaybackBar() = default;

void PlaybackBar::SetFrameCount(int64_t count) {
  if (live()) position_ = 0;  // A live source's frame numbers mean nothing in a recording.
  frame_count_ = std::max<int64_t>(-1, count);
  const QSignalBlocker blocker(slider_);
  // QSlider holds an int; recordings beyond 2^31 frames do not exist in practice.
  slider_->setRange(0, static_cast<int>(std::clamp<int64_t>(frame_count_ - 1, 0, INT_MAX)));
  position_ =
      live() ? -1 : std::clamp<int64_t>(position_, 0, std::max<int64_t>(0, frame_count_ - 1));
  slider_->setValue(static_cast<int>(position_));
  const bool playable = frame_count_ != 0;
  play_button_->setEnabled(playable);
  step_button_->setEnabled(playable);
  slider_->setEnabled(frame_count_ > 0);  // A live source cannot seek.
  UpdateLabel();
}

void PlaybackBar::SetPosition(int64_t index) {
  if (live()) {
    position_ = std::max<int64_t>(0, index);
    UpdateLabel();
    return;
  }
  if (slider_->isSliderDown()) return;  // The user's drag wins over playback progress.
  position_ = std::clamp<int64_t>(index, 0, std::max<int64_t>(0, frame_count_ - 1));
  const QSignalBlocker blocker(slider_);
  slider_->setValue(static_cast<int>(position_));
  UpdateLabel();
}

void PlaybackBar::SetPlaying(bool playing) {
  playing_ = playing;
  UpdatePlayButton();
}

void PlaybackBar::SetLoop(bool loop) {
  const QSignalBlocker blocker(loop_box_);
  loop_box_->setChecked(loop);
}

double PlaybackBar::speed() const { return speed_box_->currentData().toDouble(); }

void PlaybackBar::UpdatePlayButton() {
  play_button_->setIcon(
      style()->standardIcon(playing_ ? QStyle::SP_MediaPause : QStyle::SP_MediaPlay));
  play_button_->setToolTip(playing_ ? tr("Pause") : tr("Play"));
}

bool PlaybackBar::eventFilter(QObject* watched, QEvent* event) {
  if (watched != slider_ || event->type() != QEvent::MouseButtonPress || !slider_->isEnabled())
    return QWidget::eventFilter(watched, event);
  const auto* press = static_cast<QMouseEvent*>(event);
  if (press->button() != Qt::LeftButton) return QWidget::eventFilter(watched, event);
  QStyleOptionSlider option;
  option.initFrom(slider_);
  option.orientation = slider_->orientation();
  option.minimum = slider_->minimum();
  option.maximum = slider_->maximum();
  option.sliderPosition = slider_->sliderPosition();
  option.sliderValue = slider_->value();
  const QRect handle = slider_->style()->subControlRect(QStyle::CC_Slider, &option,
                                                        QStyle::SC_SliderHandle, slider_);
  if (handle.contains(press->position().toPoint())) return false;  // A drag of the handle.
  // The groove: jump to the frame under the mouse rather than a page step towards it.
  const QRect groove = slider_->style()->subControlRect(QStyle::CC_Slider, &option,
                                                        QStyle::SC_SliderGroove, slider_);
  const int half = handle.width() / 2;
  const int value = QStyle::sliderValueFromPosition(
      slider_->minimum(), slider_->maximum(),
      static_cast<int>(press->position().x()) - groove.left() - half,
      std::max(1, groove.width() - handle.width()));
  slider_->setValue(value);  // Emits SeekRequested through valueChanged.
  return true;
}

void PlaybackBar::UpdateLabel() {
  // Frames are counted from 1 for people; indices (SeekRequested) from 0. A live source has no
  // end: the label shows the newest frame's number (0 before the first).
  if (live()) {
    frame_label_->setText(tr("frame %1").arg(position_ + 1));
    return;
  }
  const int64_t shown = frame_count_ > 0 ? position_ + 1 : 0;
  frame_label_->setText(QStringLiteral("%1 / %2").arg(shown).arg(frame_count_));
}

}  // namespace sightline
