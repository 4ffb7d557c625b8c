// Transport controls for recorded playback: play/pause, step, seek, speed and loop.
#pragma once

#include <QWidget>
#include <cstdint>

class QCheckBox;
class QComboBox;
class QLabel;
class QSlider;
class QToolButton;

namespace sightline {

// Emits requests; the player decides and reports back through the setters, which never emit
// requests themselves (so player -> bar -> player loops cannot happen).
//
//   connect(bar, &PlaybackBar::SeekRequested, player, &Player::Seek);
//   connect(player, &Player::PositionChanged, bar, &PlaybackBar::SetPosition);
class PlaybackBar : public QWidget {
  Q_OBJECT

 public:
  // Creates a bar for an empty recording (controls disabled until SetFrameCount).
  explicit PlaybackBar(QWidget* parent = nullptr);
  ~PlaybackBar() override;

  // Number of frames; the slider spans 0 .. count - 1. Also clamps the position. A negative
  // count is a live source (a camera, a replayed recording): Play and Step work, the slider
  // does not, and the label counts the frames received.
  void SetFrameCount(int64_t count);
  // Shows the player's current frame index without emitting SeekRequested. Ignored for the
  // slider while the user drags it.
  void SetPosition(int64_t index);
  // Shows the play/pause state without emitting PlayRequested / PauseRequested.
  void SetPlaying(bool playing);
  // Shows the loop state without emitting LoopChanged.
  void SetLoop(bool loop);

  // Frame count (-1 live), position (index from 0), playing state and speed factor (0 = as fast
  // as possible).
  int64_t frame_count() const { return frame_count_; }
  bool live() const { return frame_count_ < 0; }
  int64_t position() const { return position_; }
  bool playing() const { return playing_; }
  double speed() const;

  // The child controls, for keyboard shortcuts and tests.
  QToolButton* play_button() const { return play_button_; }
  QToolButton* step_button() const { return step_button_; }
  QSlider* slider() const { return slider_; }
  QComboBox* speed_box() const { return speed_box_; }
  QCheckBox* loop_box() const { return loop_box_; }
  QLabel* frame_label() const { return frame_label_; }

 signals:
  // The user pressed play.
  void PlayRequested();
  // The user pressed pause.
  void PauseRequested();
  // The user asked for exactly one more frame.
  void StepRequested();
  // The user moved the slider to a frame index.
  void SeekRequested(int64_t index);
  // The user picked a speed factor; 0 means as fast as possible.
  void SpeedChanged(double factor);
  // The user toggled looping at the end of the recording.
  void LoopChanged(bool loop);

 protected:
  // A click on the slider's groove jumps to the frame under the mouse.
  bool eventFilter(QObject* watched, QEvent* event) override;

 private:
  void UpdatePlayButton();
  void UpdateLabel();

  QToolButton* play_button_ = nullptr;
  QToolButton* step_button_ = nullptr;
  QSlider* slider_ = nullptr;
  QLabel* frame_label_ = nullptr;
  QComboBox* speed_box_ = nullptr;
  QCheckBox* loop_box_ = nullptr;
  int64_t frame_count_ = 0;
  int64_t position_ = 0;
  bool playing_ = false;
};

}  // namespace sightline
