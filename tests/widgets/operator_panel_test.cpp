// The operator's panel clicked through as an operator would: tap -> outline and question ->
// Yes -> state banners and distance -> STOP at any time -> Start again; touch works like the
// mouse; touch targets are at least 15 mm; the regions never move with the words; holding and
// refused taps say why; F11 and Esc as a window of its own.
#include "widgets/operator_panel.h"

#include <gtest/gtest.h>

#include <QLabel>
#include <QMessageBox>
#include <QPointingDevice>
#include <QPushButton>
#include <QScreen>
#include <QTest>
#include <cmath>
#include <vector>

#include "widgets/tap_image_view.h"

namespace sightline {
namespace {

class OperatorPanelTest : public ::testing::Test {
 protected:
  void SetUp() override {
    panel_.resize(1024, 600);
    panel_.SetImage(cv::Mat(480, 640, CV_8UC3, cv::Scalar(90, 90, 90)));
    panel_.show();
    ASSERT_TRUE(QTest::qWaitForWindowExposed(&panel_));
    QObject::connect(&panel_, &OperatorPanel::Tapped, [this](QPointF p) { taps_.push_back(p); });
    QObject::connect(&panel_, &OperatorPanel::Confirmed, [this] { ++confirmed_; });
    QObject::connect(&panel_, &OperatorPanel::Cancelled, [this] { ++cancelled_; });
    QObject::connect(&panel_, &OperatorPanel::StopPressed, [this] { ++stops_; });
    QObject::connect(&panel_, &OperatorPanel::StartRequested, [this] { ++starts_; });
  }

  // Clicks the image view at an image pixel.
  void TapImage(QPointF image_px) {
    QTest::mouseClick(panel_.image_view(), Qt::LeftButton, {},
                      panel_.image_view()->ToWidget(image_px).toPoint());
  }

  OperatorPanel panel_;
  std::vector<QPointF> taps_;
  int confirmed_ = 0, cancelled_ = 0, stops_ = 0, starts_ = 0;
};

TEST_F(OperatorPanelTest, TapConfirmTrackAndStop) {
  EXPECT_EQ(panel_.banner()->text(), "Tap a button");
  TapImage({412, 230});
  ASSERT_EQ(taps_.size(), 1u);
  EXPECT_NEAR(taps_[0].x(), 412, 1.5);  // Mapped back to image pixels.
  EXPECT_NEAR(taps_[0].y(), 230, 1.5);

  panel_.ShowCandidate(QPolygonF({{400, 220}, {425, 220}, {425, 242}, {400, 242}}));
  EXPECT_EQ(panel_.banner()->text(), "Press this button?");
  EXPECT_TRUE(panel_.yes_button()->isVisible());
  EXPECT_TRUE(panel_.cancel_button()->isVisible());
  TapImage({100, 100});  // Taps wait while the question is open.
  EXPECT_EQ(taps_.size(), 1u);

  QTest::mouseClick(panel_.yes_button(), Qt::LeftButton);
  EXPECT_EQ(confirmed_, 1);
  EXPECT_FALSE(panel_.yes_button()->isVisible());
  EXPECT_EQ(panel_.banner()->text(), "Searching");

  panel_.SetState(OperatorState::kTracking);
  EXPECT_EQ(panel_.banner()->text(), "Tracking");
  panel_.SetState(OperatorState::kLocating, "metric scale not converged");
  EXPECT_EQ(panel_.banner()->text(), "Locating");
  EXPECT_EQ(panel_.detail_label()->text(), "metric scale not converged");
  EXPECT_TRUE(panel_.detail_label()->isVisible());
  panel_.SetDistance(0.234);
  EXPECT_EQ(panel_.distance_label()->text(), "23 cm");
  EXPECT_TRUE(panel_.distance_label()->isVisible());
  panel_.SetState(OperatorState::kTargetSent);
  EXPECT_EQ(panel_.banner()->text(), "Target sent");
  panel_.SetState(OperatorState::kLost);
  EXPECT_EQ(panel_.banner()->text(), "Lost - hold still");

  // STOP acts on press, before any release.
  QTest::mousePress(panel_.stop_button(), Qt::LeftButton);
  EXPECT_EQ(stops_, 1);
  QTest::mouseRelease(panel_.stop_button(), Qt::LeftButton);
  EXPECT_EQ(panel_.state(), OperatorState::kStopped);
  EXPECT_EQ(panel_.banner()->text(), "Stopped");
  EXPECT_FALSE(panel_.distance_label()->isVisible());
  panel_.SetState(OperatorState::kTargetSent);  // The pipeline cannot leave STOP.
  EXPECT_EQ(panel_.state(), OperatorState::kStopped);
  TapImage({200, 200});
  EXPECT_EQ(taps_.size(), 1u);  // No picking while stopped.

  ASSERT_TRUE(panel_.start_button()->isVisible());
  QTest::mouseClick(panel_.start_button(), Qt::LeftButton);
  EXPECT_EQ(starts_, 1);
  EXPECT_EQ(panel_.banner()->text(), "Tap a button");
  TapImage({200, 200});
  EXPECT_EQ(taps_.size(), 2u);
}

TEST_F(OperatorPanelTest, StopIsVisibleAndWorksInEveryState) {
  for (OperatorState s :
       {OperatorState::kIdle, OperatorState::kConfirm, OperatorState::kNoButton,
        OperatorState::kSearching, OperatorState::kTracking, OperatorState::kLocating,
        OperatorState::kTargetSent, OperatorState::kLost}) {
    if (panel_.state() == OperatorState::kStopped) {
      QTest::mouseClick(panel_.start_button(), Qt::LeftButton);
    }
    panel_.SetState(s);
    EXPECT_TRUE(panel_.stop_button()->isVisible());
    EXPECT_TRUE(panel_.stop_button()->isEnabled());
    const int before = stops_;
    QTest::mouseClick(panel_.stop_button(), Qt::LeftButton);
    EXPECT_EQ(stops_, before + 1);
    EXPECT_EQ(panel_.state(), OperatorState::kStopped);
  }
}

TEST_F(OperatorPanelTest, CancelAndNoButtonAskAgain) {
  panel_.ShowCandidate(QPolygonF({{10, 10}, {30, 10}, {30, 30}}));
  QTest::mouseClick(panel_.cancel_button(), Qt::LeftButton);
  EXPECT_EQ(cancelled_, 1);
  EXPECT_EQ(panel_.banner()->text(), "Tap a button");
  panel_.SetState(OperatorState::kNoButton);
  EXPECT_EQ(panel_.banner()->text(), "No button here - tap again");
  TapImage({50, 60});
  EXPECT_EQ(taps_.size(), 1u);
}

TEST_F(OperatorPanelTest, TouchTapsLikeTheMouse) {
  QPointingDevice* device = QTest::createTouchDevice();
  const QPoint at = panel_.image_view()->ToWidget({320, 240}).toPoint();
  QTest::touchEvent(panel_.image_view(), device).press(0, at);
  QTest::touchEvent(panel_.image_view(), device).release(0, at);
  ASSERT_EQ(taps_.size(), 1u);
  EXPECT_NEAR(taps_[0].x(), 320, 1.5);
  EXPECT_NEAR(taps_[0].y(), 240, 1.5);
}

TEST_F(OperatorPanelTest, TouchTargetsAreAtLeastFifteenMillimetres) {
  panel_.ShowCandidate(QPolygonF({{10, 10}, {30, 10}, {30, 30}}));
  const int min_px = panel_.MinTouchTargetPx();
  double dpi = panel_.screen()->physicalDotsPerInch();
  if (!(dpi >= 50 && dpi <= 1000)) dpi = 96;  // A screen that does not know its size.
  EXPECT_GE(min_px, 15.0 / 25.4 * dpi - 0.5);
  for (QPushButton* b : {panel_.stop_button(), panel_.yes_button(), panel_.cancel_button()}) {
    EXPECT_GE(b->width(), min_px) << b->text().toStdString();
    EXPECT_GE(b->height(), min_px) << b->text().toStdString();
  }
  EXPECT_GE(panel_.stop_button()->height(), 2 * min_px);
}

TEST_F(OperatorPanelTest, TapsOutsideTheImageAreIgnored) {
  // The image keeps its aspect: a 1024x600 panel leaves bars; a tap there is not a pixel.
  const QRect r = panel_.image_view()->rect();
  QTest::mouseClick(panel_.image_view(), Qt::LeftButton, {}, QPoint(r.width() / 2, 1));
  QTest::mouseClick(panel_.image_view(), Qt::LeftButton, {}, QPoint(r.width() / 2, r.height() - 2));
  for (const QPointF& p : taps_) {
    EXPECT_GE(p.y(), -0.5);
    EXPECT_LE(p.y(), 480);
  }
}

TEST_F(OperatorPanelTest, HoldingAndRefusedTapsSayWhy) {
  panel_.SetState(OperatorState::kHolding, "Paused");
  EXPECT_EQ(panel_.banner()->text(), "Holding: nothing sent");
  EXPECT_EQ(panel_.detail_label()->text(), "Paused");
  panel_.Refuse("The picture is paused: press Play, then tap");
  EXPECT_EQ(panel_.state(), OperatorState::kRefused);
  EXPECT_EQ(panel_.banner()->text(), "Tap not taken");
  EXPECT_EQ(panel_.detail_label()->text(), "The picture is paused: press Play, then tap");
  TapImage({100, 100});  // The operator may tap again.
  EXPECT_EQ(taps_.size(), 1u);
}

TEST_F(OperatorPanelTest, RegionsStayPutWhateverTheWords) {
  panel_.SetState(OperatorState::kTargetSent);
  panel_.SetDistance(0.5);
  QCoreApplication::processEvents();
  const QRect banner = panel_.banner()->geometry(), detail = panel_.detail_label()->geometry();
  const QRect stop = panel_.stop_button()->geometry(), image = panel_.image_view()->geometry();
  const QRect distance = panel_.distance_label()->geometry();
  for (const QString& words :
       {QString("Button out of reach: move a little closer, please, and hold still"), QString()}) {
    panel_.SetState(OperatorState::kHolding, words);
    panel_.SetDistance(std::nan(""));
    QCoreApplication::processEvents();
    EXPECT_EQ(panel_.banner()->geometry(), banner);
    EXPECT_EQ(panel_.detail_label()->geometry(), detail);
    EXPECT_EQ(panel_.distance_label()->geometry(), distance);
    EXPECT_EQ(panel_.stop_button()->geometry(), stop);
    EXPECT_EQ(panel_.image_view()->geometry(), image);
  }
  panel_.ShowCandidate(QPolygonF({{10, 10}, {30, 10}, {30, 30}}));  // Yes / Cancel appear.
  QCoreApplication::processEvents();
  EXPECT_EQ(panel_.banner()->geometry(), banner);
  EXPECT_EQ(panel_.stop_button()->geometry(), stop);
  EXPECT_EQ(panel_.image_view()->geometry(), image);
}

TEST_F(OperatorPanelTest, TheRingIsDrawnWhereItIsSet) {
  panel_.SetRing(QPointF(320, 240), 20);
  ASSERT_TRUE(panel_.image_view()->ring_centre().has_value());
  EXPECT_EQ(*panel_.image_view()->ring_centre(), QPointF(320, 240));
  const QImage shot = panel_.image_view()->grab().toImage();
  const QPointF c = panel_.image_view()->ToWidget({320, 240});
  const double r = 20 * panel_.image_view()->width() / 640.0;
  // Yellow on the ring, the grey image at its centre.
  const QColor on_ring = shot.pixelColor(QPointF(c.x() + r + 4, c.y()).toPoint());
  EXPECT_GT(on_ring.red(), 200);
  EXPECT_GT(on_ring.green(), 180);
  EXPECT_LT(on_ring.blue(), 80);
  EXPECT_LT(shot.pixelColor(c.toPoint()).red(), 120);
  panel_.SetRing(std::nullopt);
  EXPECT_FALSE(panel_.image_view()->ring_centre().has_value());
}

TEST(OperatorPanelWindow, F11AsksForFullScreenAndEscAsksBeforeLeaving) {
  OperatorPanel panel;
  panel.SetFullScreenMode(true);
  ASSERT_TRUE(QTest::qWaitForWindowExposed(&panel));
  EXPECT_TRUE(panel.isFullScreen());
  int toggles = 0, leaves = 0;
  QObject::connect(&panel, &OperatorPanel::FullScreenToggleRequested, [&] { ++toggles; });
  QObject::connect(&panel, &OperatorPanel::LeaveRequested, [&] { ++leaves; });
  QTest::keyClick(&panel, Qt::Key_F11);
  EXPECT_EQ(toggles, 1);
  QTest::keyClick(&panel, Qt::Key_Escape);
  ASSERT_NE(panel.leave_question(), nullptr);
  panel.leave_question()->button(QMessageBox::Cancel)->click();
  EXPECT_EQ(leaves, 0);
  EXPECT_EQ(panel.leave_question(), nullptr);
  QTest::keyClick(&panel, Qt::Key_Escape);
  ASSERT_NE(panel.leave_question(), nullptr);
  panel.leave_question()->button(QMessageBox::Yes)->click();
  EXPECT_EQ(leaves, 1);
}

}  // namespace
}  // namespace sightline
