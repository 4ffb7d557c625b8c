// The operator panel against a real sightline-node on the simulated arm-panel approach, through a
// real roscore (its own port): the GUI (in this process, under X) shows the node's button_image,
// the operator's tap at the true button's pixel and Yes give button_targets at the true button;
// STOP reaches the node while the picture is stale and while the master is gone (over the link
// the two still have; kept, latched, for a node that starts when the master is back); a master
// that dies makes the panel say "disconnected" and refuse taps.
#include <gtest/gtest.h>

#include <QApplication>
#include <QDockWidget>
#include <QLabel>
#include <QPushButton>
#include <QTest>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <thread>

#include "app/sightline/main_window.h"
#include "app/sightline/remote_operator_presenter.h"
#include "app/sightline/ros_node_view.h"
#include "core/io/dataset.h"
#include "core/io/hand_eye_file.h"
#include "core/pipeline/button_pipeline.h"
#include "tests/app/process.h"
#include "tests/ros/roscore_fixture.h"
#include "tests/support/test_data.h"
#include "widgets/operator_panel.h"
#include "widgets/tap_image_view.h"

namespace sightline {
namespace {

using testing::ChildProcess;
using testing::RoscoreFixture;

std::string Bin(const std::string& name) { return std::string(SIGHTLINE_BIN_DIR) + "/" + name; }

// Runs the GUI's event loop until `ready` (or `timeout_s`, a bound for a broken run only).
template <typename Pred>
bool PumpUntil(Pred ready, double timeout_s) {
  const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(timeout_s);
  while (std::chrono::steady_clock::now() < end) {
    QApplication::processEvents(QEventLoop::AllEvents, 20);
    if (ready()) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  return ready();
}

// The simulated approach to the arm panel (the node test's: 150 frames at 30 Hz), made once.
std::string PanelRecording() {
  static const std::string rec = [] {
    const std::string dir = testing::TempDir("ros_operator_panel") + "/rec";
    if (std::filesystem::exists(dir + "/buttons.csv")) return dir;
    const auto r = testing::RunProcess(Bin("sightline-cli") + " simulate panel --out " + dir +
                                       " --quiet --set sim.arm.sideways_m=0.12");
    return r.exit_code == 0 ? dir : std::string();
  }();
  return rec;
}

// The recording's frame shown at `stamp_s` (to a microsecond), or -1.
int FrameAt(const std::string& rec, double stamp_s) {
  StatusOr<std::unique_ptr<Source>> dataset = OpenDataset(rec, SourceKind::kMono);
  if (!dataset.ok()) return -1;
  for (int i = 0; (*dataset)->Grab().ok(); ++i) {
    StatusOr<Frame> frame = (*dataset)->Retrieve();
    if (!frame.ok()) return -1;
    const double t = std::get<MonoFrame>(*frame).stamp.sensor_time_s;
    if (std::abs(t - stamp_s) < 1e-6) return i;
  }
  return -1;
}

// A main window connected to a fresh roscore; the node is started by each test.
class RosOperatorGui : public ::testing::Test {
 protected:
  void SetUp() override {
    rec_ = PanelRecording();
    ASSERT_FALSE(rec_.empty());
    const std::string error = master_.Start();
    ASSERT_TRUE(error.empty()) << error;
    master_.ExportEnv();
    window_ = std::make_unique<MainWindow>();
    window_->show();
    ASSERT_TRUE(window_->ConnectRos(QString::fromStdString(master_.uri()), "/").ok());
    ASSERT_TRUE(PumpUntil([&] { return window_->ros_node()->connected(); }, 20));
    remote_ = window_->remote_operator();
    ASSERT_NE(remote_, nullptr);
    panel_ = remote_->panel();
  }
  void TearDown() override {
    if (window_ != nullptr) window_->ros_node()->Disconnect();
    node_.Kill();
    window_.reset();
  }

  bool StartNode(const std::string& name, const std::string& args) {
    log_ = testing::TempDir("ros_operator_" + name + "_log") + "/node.log";
    return node_.Start(master_.Env() + Bin("sightline-node") + " --pipeline button --source " +
                           rec_ + " --out " + testing::TempDir("ros_operator_" + name) + " " + args,
                       log_);
  }
  // A tap on the panel's picture at image pixel `px`.
  void TapAt(QPointF px) {
    const QPoint at = panel_->image_view()->ToWidget(px).toPoint();
    QTest::mouseClick(panel_->image_view(), Qt::LeftButton, {}, at);
  }

  std::string rec_;
  RoscoreFixture master_;
  ChildProcess node_;
  std::string log_;
  std::unique_ptr<MainWindow> window_;
  RemoteOperatorPresenter* remote_ = nullptr;
  OperatorPanel* panel_ = nullptr;
};

TEST_F(RosOperatorGui, TapAndYesOnTheNodesPictureGiveATargetAtTheTrueButton) {
  const StatusOr<std::vector<TrueButton>> buttons = ReadTrueButtons(rec_ + "/buttons.csv");
  ASSERT_TRUE(buttons.ok()) << buttons.status().ToString();
  const TrueButton* target = nullptr;
  for (const TrueButton& b : *buttons) target = b.id == 5 ? &b : target;
  ASSERT_NE(target, nullptr);
  const StatusOr<HandEye> hand_eye = ReadHandEyeFile(rec_ + "/hand_eye.yaml");
  ASSERT_TRUE(hand_eye.ok()) << hand_eye.status().ToString();
  ASSERT_TRUE(hand_eye->world_from_base.has_value());
  const Eigen::Vector3d truth_in_base =
      hand_eye->world_from_base->inverse() * target->center_in_world;

  ASSERT_TRUE(StartNode("tap", "--rate recorded --linger 1"));
  // The node's picture on the panel, live.
  ASSERT_TRUE(PumpUntil([&] { return remote_->images_shown() > 0; }, 120))
      << testing::ReadTextFile(log_);
  EXPECT_TRUE(remote_->dock()->isVisible());
  EXPECT_EQ(panel_->link(), OperatorLink::kLive);
  const QSize shown = panel_->image_view()->image_size();
  EXPECT_GT(shown.width(), 0);
  EXPECT_GT(shown.height(), 0);
  // The operator taps at once on what is on screen, a few pixels off the button's centre. On a
  // loaded machine the picture may be older than button.gui.max_tap_age_s in the node's data
  // time by the time the tap reaches it: the node says so, and the operator taps again.
  int frame = -1;
  for (int attempt = 1; attempt <= 5 && panel_->state() != OperatorState::kConfirm; ++attempt) {
    const double stamp = remote_->shown_stamp_s();
    frame = FrameAt(rec_, stamp);
    ASSERT_GE(frame, 0) << "no recorded frame at " << stamp;
    ASSERT_LT(frame, static_cast<int>(target->pixel.size()));
    ASSERT_TRUE(target->visible[frame]);
    TapAt(QPointF(target->pixel[frame].x() + 2, target->pixel[frame].y() - 2));
    ASSERT_EQ(remote_->taps_sent(), attempt) << panel_->detail_label()->text().toStdString();
    // The node's answer: it found the button (the panel asks; nothing is sent before Yes) or
    // the picture was too old.
    ASSERT_TRUE(PumpUntil(
        [&] {
          return panel_->state() == OperatorState::kConfirm || remote_->tap_answer() == "too_old";
        },
        30))
        << panel_->banner()->text().toStdString() << "\n"
        << testing::ReadTextFile(log_);
    if (panel_->state() != OperatorState::kConfirm) {
      EXPECT_EQ(panel_->state(), OperatorState::kRefused);
      EXPECT_EQ(panel_->detail_label()->text().toStdString(), "The picture was too old: tap again");
    }
  }
  ASSERT_EQ(panel_->state(), OperatorState::kConfirm) << testing::ReadTextFile(log_);
  EXPECT_EQ(remote_->tap_answer(), "found");
  // The question shows the outline of the button the node found (not a square about the tap):
  // around the true button's centre.
  const QPolygonF outline = panel_->image_view()->outline();
  EXPECT_GT(outline.size(), 5);
  const QPointF truth(target->pixel[frame].x(), target->pixel[frame].y());
  EXPECT_TRUE(outline.containsPoint(truth, Qt::OddEvenFill));
  EXPECT_LT(QLineF(outline.boundingRect().center(), truth).length(), 3.0)
      << outline.boundingRect().center().x() << ", " << outline.boundingRect().center().y();
  EXPECT_FALSE(remote_->last_target_m().has_value());
  QTest::mouseClick(panel_->yes_button(), Qt::LeftButton);
  // While the node tracks the button the panel rings it, on the frame the ring was found in.
  ASSERT_TRUE(PumpUntil([&] { return panel_->image_view()->ring_centre().has_value(); }, 60))
      << testing::ReadTextFile(log_);
  const int ring_frame = FrameAt(rec_, remote_->ring_stamp_s());
  ASSERT_GE(ring_frame, 0);
  const QPointF ring = *panel_->image_view()->ring_centre();
  EXPECT_LT(
      QLineF(ring, QPointF(target->pixel[ring_frame].x(), target->pixel[ring_frame].y())).length(),
      3.0)
      << "frame " << ring_frame;
  int code = -1;
  ASSERT_TRUE(PumpUntil(
      [&] {
        if (node_.pid() > 0) code = node_.Wait(0.06);
        return node_.pid() <= 0;
      },
      300));
  EXPECT_EQ(code, 0) << testing::ReadTextFile(log_);
  // What the node sent in its last moments reaches the panel before it says the node is gone.
  ASSERT_TRUE(PumpUntil([&] { return panel_->link() == OperatorLink::kDisconnected; }, 30));
  // The banner said "Target sent" while the node's gate let targets out.
  EXPECT_GT(remote_->target_sent_reports(), 0);
  ASSERT_TRUE(remote_->last_target_m().has_value()) << testing::ReadTextFile(log_);
  // The node test's tolerance: the CLI's run is within 3 mm, a tap a little later within 5 mm.
  EXPECT_LT((*remote_->last_target_m() - truth_in_base).norm(), 0.005)
      << remote_->last_target_m()->transpose() << " vs " << truth_in_base.transpose();
}

// The node answers every tap on the frame that takes it: a tap it refuses is worded as the
// refusal at once (not, after a while, as "no button here").
TEST_F(RosOperatorGui, ATapTheNodeRefusesAsTooOldIsWordedSoAtOnce) {
  // Every picture is too old by the node's next frame (1/30 s later in data time).
  ASSERT_TRUE(StartNode("too_old", "--rate recorded --set button.gui.max_tap_age_s=0.01"));
  ASSERT_TRUE(PumpUntil([&] { return remote_->images_shown() > 0; }, 120))
      << testing::ReadTextFile(log_);
  const QSize size = panel_->image_view()->image_size();
  TapAt(QPointF(size.width() / 2.0, size.height() / 2.0));
  ASSERT_EQ(remote_->taps_sent(), 1) << panel_->detail_label()->text().toStdString();
  ASSERT_TRUE(PumpUntil([&] { return !remote_->tap_answer().empty(); }, 30))
      << testing::ReadTextFile(log_);
  EXPECT_EQ(remote_->tap_answer(), "too_old");
  EXPECT_EQ(panel_->state(), OperatorState::kRefused);
  EXPECT_EQ(panel_->detail_label()->text().toStdString(), "The picture was too old: tap again");
  EXPECT_NE(testing::ReadTextFile(log_).find("refused"), std::string::npos)
      << testing::ReadTextFile(log_);
}

TEST_F(RosOperatorGui, StopReachesTheNodeWhileThePictureIsStale) {
  remote_->SetStaleAfter(1.0);
  ASSERT_TRUE(StartNode("stale", "--rate max --linger -1"));
  ASSERT_TRUE(PumpUntil([&] { return remote_->images_shown() > 0; }, 120))
      << testing::ReadTextFile(log_);
  // The recording ends; the node stays (lingers) but sends no picture: the view goes stale.
  ASSERT_TRUE(PumpUntil([&] { return panel_->link() == OperatorLink::kStale; }, 300))
      << testing::ReadTextFile(log_);
  EXPECT_NE(panel_->link_label()->text().indexOf("stale"), -1)
      << panel_->link_label()->text().toStdString();
  // A tap on the old picture is refused with words and never sent.
  const QSize size = panel_->image_view()->image_size();
  TapAt(QPointF(size.width() / 2.0, size.height() / 2.0));
  EXPECT_EQ(panel_->state(), OperatorState::kRefused);
  EXPECT_EQ(remote_->taps_sent(), 0);
  // STOP goes out at once and the node says it took it.
  QTest::mousePress(panel_->stop_button(), Qt::LeftButton);
  QTest::mouseRelease(panel_->stop_button(), Qt::LeftButton);
  EXPECT_EQ(panel_->state(), OperatorState::kStopped);
  ASSERT_TRUE(PumpUntil([&] { return remote_->stop_acknowledged(); }, 30))
      << testing::ReadTextFile(log_);
  EXPECT_EQ(panel_->detail_label()->text().toStdString(), "The robot confirmed STOP");
  EXPECT_NE(testing::ReadTextFile(log_).find("STOP on button_stop (operator)"), std::string::npos)
      << testing::ReadTextFile(log_);
  // The node goes away while the master stays: the panel says so.
  node_.Kill();
  ASSERT_TRUE(PumpUntil([&] { return panel_->link() == OperatorLink::kDisconnected; }, 30));
  EXPECT_NE(panel_->link_label()->text().indexOf("node is gone"), -1)
      << panel_->link_label()->text().toStdString();
  EXPECT_TRUE(window_->ros_node()->connected());
  EXPECT_FALSE(panel_->yes_button()->isEnabled());
}

TEST_F(RosOperatorGui, MasterGoneSaysDisconnectedRefusesTapsAndStopStillReachesTheNode) {
  remote_->SetStaleAfter(1.0);
  ASSERT_TRUE(StartNode("gone", "--rate max --linger -1"));
  ASSERT_TRUE(PumpUntil([&] { return remote_->images_shown() > 0; }, 120))
      << testing::ReadTextFile(log_);
  // The run ends (no more pictures); the node stays and serves its topics.
  ASSERT_TRUE(PumpUntil([&] { return panel_->link() == OperatorLink::kStale; }, 300))
      << testing::ReadTextFile(log_);
  const int port = master_.port();
  master_.Stop();
  ASSERT_TRUE(PumpUntil([&] { return panel_->link() == OperatorLink::kDisconnected; }, 20));
  EXPECT_NE(panel_->link_label()->text().indexOf("Disconnected"), -1)
      << panel_->link_label()->text().toStdString();
  // Taps, Yes and Cancel are off; STOP is not.
  const QSize size = panel_->image_view()->image_size();
  TapAt(QPointF(size.width() / 2.0, size.height() / 2.0));
  EXPECT_EQ(panel_->state(), OperatorState::kRefused);
  EXPECT_EQ(remote_->taps_sent(), 0);
  EXPECT_FALSE(panel_->yes_button()->isEnabled());
  EXPECT_FALSE(panel_->cancel_button()->isEnabled());
  EXPECT_TRUE(panel_->stop_button()->isEnabled());
  // STOP goes out on the link the node and the GUI still have without their master.
  QTest::mousePress(panel_->stop_button(), Qt::LeftButton);
  QTest::mouseRelease(panel_->stop_button(), Qt::LeftButton);
  EXPECT_EQ(panel_->state(), OperatorState::kStopped);
  EXPECT_FALSE(panel_->start_button()->isEnabled());  // A START could reach no one.
  ASSERT_TRUE(PumpUntil([&] { return remote_->stop_acknowledged(); }, 30))
      << testing::ReadTextFile(log_);
  EXPECT_NE(testing::ReadTextFile(log_).find("STOP on button_stop (operator)"), std::string::npos)
      << testing::ReadTextFile(log_);
  // The master comes back: the panel reconnects; a node started now gets the kept STOP at once.
  ASSERT_EQ(master_.Start(60, port), "");
  ASSERT_TRUE(PumpUntil([&] { return window_->ros_node()->connected(); }, 20));
  // No longer the master's absence: waiting for a picture, or (until the lingering node is on
  // the new master's books) "the robot's node is gone"; which of the two depends on timing.
  EXPECT_TRUE(PumpUntil(
      [&] {
        return panel_->link() != OperatorLink::kDisconnected ||
               panel_->link_label()->text().indexOf("node is gone") != -1;
      },
      20))
      << panel_->link_label()->text().toStdString();
  node_.Kill();
  ASSERT_TRUE(StartNode("back", "--rate max --linger -1"));
  ASSERT_TRUE(PumpUntil(
      [&] {
        return testing::ReadTextFile(log_).find("STOP on button_stop (operator)") !=
               std::string::npos;
      },
      120))
      << testing::ReadTextFile(log_);
}

}  // namespace
}  // namespace sightline
