#include "widgets/playback_bar.h"

#include <gtest/gtest.h>

#include <QCheckBox>
#include <QComboBox>
#include <QLabel>
#include <QSlider>
#include <QTest>
#include <QToolButton>
#include <vector>

namespace sightline {
namespace {

class PlaybackBarTest : public ::testing::Test {
 protected:
  void SetUp() override {
    QObject::connect(&bar_, &PlaybackBar::SeekRequested,
                     [this](int64_t index) { seeks_.push_back(index); });
    QObject::connect(&bar_, &PlaybackBar::PlayRequested, [this] { ++plays_; });
    QObject::connect(&bar_, &PlaybackBar::PauseRequested, [this] { ++pauses_; });
    QObject::connect(&bar_, &PlaybackBar::StepRequested, [this] { ++steps_; });
    QObject::connect(&bar_, &PlaybackBar::SpeedChanged,
                     [this](double factor) { speeds_.push_back(factor); });
    QObject::connect(&bar_, &PlaybackBar::LoopChanged,
                     [this](bool loop) { loops_.push_back(loop); });
  }

  PlaybackBar bar_;
  std::vector<int64_t> seeks_;
  std::vector<double> speeds_;
  std::vector<bool> loops_;
  int plays_ = 0;
  int pauses_ = 0;
  int steps_ = 0;
};

TEST_F(PlaybackBarTest, SetPositionDoesNotRequestASeek) {
  bar_.SetFrameCount(51);
  bar_.SetPosition(11);
  EXPECT_TRUE(seeks_.empty());
  EXPECT_EQ(bar_.slider()->value(), 11);
  EXPECT_EQ(bar_.slider()->maximum(), 50);
  EXPECT_EQ(bar_.frame_label()->text(), "12 / 51");
  bar_.SetPosition(1000);  // Clamped to the last frame.
  EXPECT_EQ(bar_.position(), 50);
  EXPECT_TRUE(seeks_.empty());
}

TEST_F(PlaybackBarTest, MovingTheSliderRequestsASeek) {
  bar_.SetFrameCount(51);
  bar_.slider()->setValue(20);
  ASSERT_EQ(seeks_, std::vector<int64_t>{20});
  EXPECT_EQ(bar_.frame_label()->text(), "21 / 51");
  bar_.slider()->triggerAction(QSlider::SliderSingleStepAdd);
  EXPECT_EQ(seeks_, (std::vector<int64_t>{20, 21}));
  bar_.show();
  QTest::keyClick(bar_.slider(), Qt::Key_End);
  EXPECT_EQ(seeks_.back(), 50);
}

TEST_F(PlaybackBarTest, PlayPauseFollowsThePlayersState) {
  bar_.SetFrameCount(10);
  bar_.play_button()->click();
  EXPECT_EQ(plays_, 1);
  bar_.SetPlaying(true);
  EXPECT_EQ(plays_ + pauses_, 1) << "SetPlaying must not emit";
  bar_.play_button()->click();
  EXPECT_EQ(pauses_, 1);
  bar_.step_button()->click();
  EXPECT_EQ(steps_, 1);
}

TEST_F(PlaybackBarTest, SpeedAndLoop) {
  EXPECT_DOUBLE_EQ(bar_.speed(), 1.0);
  bar_.speed_box()->setCurrentIndex(bar_.speed_box()->findText("max"));
  bar_.speed_box()->setCurrentIndex(bar_.speed_box()->findText("0.25x"));
  EXPECT_EQ(speeds_, (std::vector<double>{0.0, 0.25}));
  bar_.loop_box()->setChecked(true);
  bar_.SetLoop(false);
  EXPECT_EQ(loops_, std::vector<bool>{true});
  EXPECT_FALSE(bar_.loop_box()->isChecked());
}

TEST_F(PlaybackBarTest, EmptyRecordingDisablesTheControls) {
  EXPECT_FALSE(bar_.slider()->isEnabled());
  EXPECT_FALSE(bar_.play_button()->isEnabled());
  EXPECT_EQ(bar_.frame_label()->text(), "0 / 0");
  bar_.SetFrameCount(3);
  EXPECT_TRUE(bar_.play_button()->isEnabled());
  EXPECT_EQ(bar_.frame_label()->text(), "1 / 3");
}

// A click on the groove jumps to the frame under the mouse, not a page step towards it (Qt's
// default), as in every video player.
TEST_F(PlaybackBarTest, AClickOnTheGrooveSeeksToTheFrameUnderTheMouse) {
  bar_.resize(600, 40);
  bar_.show();
  ASSERT_TRUE(QTest::qWaitForWindowExposed(&bar_));
  bar_.SetFrameCount(101);
  QSlider* slider = bar_.slider();
  ASSERT_EQ(slider->pageStep(), 10);
  QTest::mouseClick(slider, Qt::LeftButton, {},
                    QPoint(slider->width() * 3 / 4, slider->height() / 2));
  ASSERT_EQ(seeks_.size(), 1u);
  EXPECT_NEAR(seeks_[0], 75, 4) << "a page step would give 10";
  QTest::mouseClick(slider, Qt::LeftButton, {}, QPoint(slider->width() / 4, slider->height() / 2));
  ASSERT_EQ(seeks_.size(), 2u);
  EXPECT_NEAR(seeks_[1], 25, 4) << "a page step back would give " << seeks_[0] - 10;
  EXPECT_EQ(bar_.position(), seeks_[1]);
}

// A live source (a camera, replay://) has no frame count: Play and Step work, the slider does
// not, and the label shows the newest frame's number.
TEST_F(PlaybackBarTest, ALiveSourcePlaysAndCountsItsFrames) {
  bar_.SetFrameCount(-1);
  EXPECT_TRUE(bar_.live());
  EXPECT_TRUE(bar_.play_button()->isEnabled());
  EXPECT_TRUE(bar_.step_button()->isEnabled());
  EXPECT_FALSE(bar_.slider()->isEnabled());
  EXPECT_EQ(bar_.frame_label()->text(), "frame 0");
  bar_.SetPosition(41);
  EXPECT_EQ(bar_.frame_label()->text(), "frame 42");
  bar_.SetPosition(1000);  // No end to clamp to.
  EXPECT_EQ(bar_.frame_label()->text(), "frame 1001");
  EXPECT_TRUE(seeks_.empty());
  bar_.play_button()->click();
  EXPECT_EQ(plays_, 1);
  bar_.SetFrameCount(5);  // A recording again.
  EXPECT_EQ(bar_.frame_label()->text(), "1 / 5");
}

}  // namespace
}  // namespace sightline
