// The operator's panel in the main window, driven as an operator would on the simulated panel
// approach, with a real arm-target server on loopback and the project's arm client as the arm:
// taps on a paused picture are refused with words and never applied; tap, Yes and targets flow
// ("Target sent"); pausing holds at once and sends nothing; STOP survives serving off and on
// (and the SLAM map survives it too); only Start lifts it; every exit path (quit, pipeline
// switch, serving off, the source's end) sends the arm a stop line; operator mode is full
// screen with 15 mm buttons and a layout that does not move with the words.
#include <gtest/gtest.h>

#include <QCheckBox>
#include <QLabel>
#include <QMessageBox>
#include <QPointingDevice>
#include <QPushButton>
#include <QScreen>
#include <QSignalSpy>
#include <QTest>
#include <optional>
#include <string>
#include <thread>

#include "app/sightline/button_picker_presenter.h"
#include "app/sightline/main_window.h"
#include "app/sightline/playback_controller.h"
#include "core/button/arm_client.h"
#include "core/button/arm_server.h"
#include "core/button/arm_sim_session.h"
#include "core/pipeline/button_pipeline.h"
#include "core/pipeline/sim_panel_source.h"
#include "core/sim/simulate.h"
#include "tests/support/test_data.h"
#include "widgets/operator_panel.h"
#include "widgets/parameter_panel.h"
#include "widgets/tap_image_view.h"

namespace sightline {
namespace {

constexpr int kWaitMs = 60000;  // Generous: the machine may be loaded; never a time assertion.

int FreePort() {
  ArmServerOptions options;
  options.port = 0;
  auto probe = ArmServer::Start(options);
  return probe.ok() ? (*probe)->port() : 0;
}

std::optional<ArmClient> ConnectArm(int port) {
  for (int attempt = 0; attempt < 200; ++attempt) {
    auto c = ArmClient::Connect("127.0.0.1", port, "", 1000);
    if (c.ok()) return std::move(*c);
    QTest::qWait(50);
  }
  return std::nullopt;
}

bool IsType(const std::string& line, const char* type) {
  return line.find(std::string("\"type\":\"") + type + "\"") != std::string::npos;
}

// Reads lines until one of `type` (true) or the connection ends or stays silent (false). Lines
// read are appended to `seen`.
bool ReadUntil(ArmClient* client, const char* type, std::vector<std::string>* seen = nullptr) {
  for (int i = 0; i < 5000; ++i) {
    StatusOr<std::string> line = client->ReadLine(10000);
    if (!line.ok()) return false;
    if (seen != nullptr) seen->push_back(*line);
    if (IsType(*line, type)) return true;
  }
  return false;
}

// Reads `heartbeats` heartbeats and returns the targets among the lines read (-1: the stream
// ended or went silent).
int TargetsWithin(ArmClient* client, int heartbeats) {
  int targets = 0;
  for (int beats = 0; beats < heartbeats;) {
    StatusOr<std::string> line = client->ReadLine(10000);
    if (!line.ok()) return -1;
    if (IsType(*line, "heartbeat")) ++beats;
    if (IsType(*line, "target")) ++targets;
  }
  return targets;
}

class OperatorGui : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = new std::string(testing::TempDir("operator_gui_panel"));
    sim::SimulationOptions options = sim::SimulationOptions::ForScene("panel");
    options.arm.sideways_m = 0.12;
    ASSERT_TRUE(sim::Simulate(options, *dir_).ok());
    short_dir_ = new std::string(testing::TempDir("operator_gui_short"));
    options.frames = 12;
    ASSERT_TRUE(sim::Simulate(options, *short_dir_).ok());
  }
  static void TearDownTestSuite() {
    delete dir_;
    delete short_dir_;
  }

  // A window with the button picker serving on a free loopback port, opened on `dir`.
  void Open(const std::string& dir) {
    port_ = FreePort();
    ASSERT_GT(port_, 0);
    window_ = std::make_unique<MainWindow>();
    picker_ = new ButtonPickerPresenter({"button.arm.port=" + std::to_string(port_),
                                         "button.arm.heartbeat_s=0.05", "button.gui.serve=true"});
    window_->AddPipeline(picker_);
    ASSERT_TRUE(window_->ActivatePipeline(picker_->Title()));
    window_->show();
    QSignalSpy opened(window_.get(), &MainWindow::DatasetOpened);
    window_->OpenPath(QString::fromStdString(dir));
    ASSERT_TRUE(QTest::qWaitFor([&] { return opened.count() == 1; }, kWaitMs));
    shown_ = std::make_unique<QSignalSpy>(window_.get(), &MainWindow::FrameShown);
  }

  void TearDown() override {
    shown_.reset();
    window_.reset();
  }

  // One frame, paused (Step).
  bool Step() {
    const int before = shown_->count();
    window_->playback()->Step();
    return QTest::qWaitFor([&] { return shown_->count() > before; }, kWaitMs);
  }
  // Waits for the next frame shown.
  bool NextFrame() {
    const int before = shown_->count();
    return QTest::qWaitFor([&] { return shown_->count() > before; }, kWaitMs);
  }

  OperatorPanel* panel() const { return picker_->panel(); }

  // The operator's finger (the mouse) on an image pixel of the panel.
  void TapAt(const Eigen::Vector2d& pixel) {
    const QPoint at = panel()->image_view()->ToWidget(QPointF(pixel.x(), pixel.y())).toPoint();
    QTest::mouseClick(panel()->image_view(), Qt::LeftButton, {}, at);
  }

  const TrueButton& Approached() {
    static const std::vector<TrueButton> buttons = *ReadTrueButtons(*dir_ + "/buttons.csv");
    for (const TrueButton& b : buttons) {
      if (b.id == 5) return b;
    }
    return buttons.front();
  }

  // Plays, taps the approached button on the frame on screen, answers Yes and waits until the
  // panel says "Target sent".
  void PlayTapYesUntilTargetSent() {
    window_->playback()->SetSpeed(0.5);
    window_->playback()->Play();
    ASSERT_TRUE(NextFrame());
    const int64_t frame = picker_->last_result()->stamp.sequence_id;
    ASSERT_TRUE(Approached().visible.at(frame));
    TapAt(Approached().pixel[frame]);
    ASSERT_TRUE(QTest::qWaitFor(
        [&] {
          const OperatorState s = panel()->state();
          return s == OperatorState::kConfirm || s == OperatorState::kRefused ||
                 s == OperatorState::kNoButton || !window_->playback()->playing();
        },
        kWaitMs));
    ASSERT_EQ(panel()->state(), OperatorState::kConfirm)
        << panel()->detail_label()->text().toStdString();
    QTest::mouseClick(panel()->yes_button(), Qt::LeftButton);
    ASSERT_TRUE(QTest::qWaitFor(
        [&] {
          return panel()->state() == OperatorState::kTargetSent || !window_->playback()->playing();
        },
        kWaitMs));
    ASSERT_EQ(panel()->state(), OperatorState::kTargetSent)
        << panel()->detail_label()->text().toStdString();
  }

  // Sets button.gui.serve through the parameter panel's check box, as a user would, and waits
  // for the frame the pipeline shows again with it.
  void SetServe(bool on) {
    auto* parameters = window_->findChild<ParameterPanel*>();
    ASSERT_NE(parameters, nullptr);
    auto* box = qobject_cast<QCheckBox*>(parameters->InputFor("button.gui.serve"));
    ASSERT_NE(box, nullptr);
    ASSERT_NE(box->isChecked(), on);
    const int before = shown_->count();
    box->click();
    ASSERT_TRUE(QTest::qWaitFor([&] { return shown_->count() > before; }, kWaitMs));
  }

  static std::string* dir_;
  static std::string* short_dir_;
  int port_ = 0;
  std::unique_ptr<MainWindow> window_;
  ButtonPickerPresenter* picker_ = nullptr;
  std::unique_ptr<QSignalSpy> shown_;
};
std::string* OperatorGui::dir_ = nullptr;
std::string* OperatorGui::short_dir_ = nullptr;

TEST_F(OperatorGui, PausedTapRefusedTargetsFlowPauseHoldsStopSurvivesServingStartResumes) {
  ASSERT_NO_FATAL_FAILURE(Open(*dir_));
  ASSERT_TRUE(Step());
  std::optional<ArmClient> client = ConnectArm(port_);
  ASSERT_TRUE(client.has_value()) << "the picker does not serve on port " << port_;
  for (int i = 0; i < 100 && !picker_->scale_converged(); ++i) ASSERT_TRUE(Step());
  ASSERT_TRUE(picker_->scale_converged());

  // A tap on the paused picture: refused in words, and never applied to a later frame.
  const int64_t paused_frame = picker_->last_result()->stamp.sequence_id;
  TapAt(Approached().pixel.at(paused_frame));
  EXPECT_EQ(panel()->state(), OperatorState::kRefused);
  EXPECT_EQ(panel()->detail_label()->text(), "The picture is paused: press Play, then tap");
  for (int i = 0; i < 3; ++i) {
    ASSERT_TRUE(Step());
    EXPECT_FALSE(picker_->last_result()->tap_answered);
    EXPECT_EQ(picker_->last_state(), PickerState::kIdle);
  }
  EXPECT_EQ(TargetsWithin(&*client, 5), 0);

  // Play, tap, Yes: targets flow to the arm.
  ASSERT_NO_FATAL_FAILURE(PlayTapYesUntilTargetSent());
  ASSERT_TRUE(ReadUntil(&*client, "target"));

  // Pause: "Holding: nothing sent" (paused) at once, and no target after the frames in flight.
  window_->playback()->Pause();
  EXPECT_EQ(panel()->state(), OperatorState::kHolding);
  EXPECT_EQ(panel()->banner()->text(), "Holding: nothing sent");
  EXPECT_EQ(panel()->detail_label()->text(), "Paused");
  ASSERT_GE(TargetsWithin(&*client, 10), 0);  // Drains what was sent before the pause.
  EXPECT_EQ(TargetsWithin(&*client, 10), 0);
  EXPECT_EQ(panel()->state(), OperatorState::kHolding);

  // STOP, then serving off (a stop line, the socket closes) and on again: still stopped, the
  // map kept, no target.
  QTest::mousePress(panel()->stop_button(), Qt::LeftButton);
  QTest::mouseRelease(panel()->stop_button(), Qt::LeftButton);
  ASSERT_TRUE(ReadUntil(&*client, "stop"));
  const double map_points = picker_->last_result()->Stat("mono/map_points").value_or(0);
  ASSERT_GT(map_points, 0);
  ASSERT_NO_FATAL_FAILURE(SetServe(false));
  std::vector<std::string> lines;
  EXPECT_TRUE(ReadUntil(&*client, "stop", &lines));
  EXPECT_NE(lines.back().find("serving turned off"), std::string::npos) << lines.back();
  EXPECT_FALSE(client->ReadLine(10000).ok());  // Closed.
  ASSERT_NO_FATAL_FAILURE(SetServe(true));
  EXPECT_EQ(picker_->last_result()->Stat("mono/map_points").value_or(0), map_points)
      << "serving on or off must not start the SLAM again";
  EXPECT_TRUE(picker_->last_result()->stopped);
  EXPECT_EQ(panel()->state(), OperatorState::kStopped);
  client = ConnectArm(port_);
  ASSERT_TRUE(client.has_value());
  EXPECT_TRUE(ReadUntil(&*client, "stop"));  // A client joining while stopped hears it.
  window_->playback()->Play();
  for (int i = 0; i < 4; ++i) ASSERT_TRUE(NextFrame());
  window_->playback()->Pause();
  EXPECT_EQ(panel()->state(), OperatorState::kStopped);
  EXPECT_EQ(picker_->last_state(), PickerState::kStopped);
  EXPECT_GT(picker_->last_result()->Stat("mono/map_points").value_or(0), 0.5 * map_points);
  EXPECT_EQ(picker_->last_result()->Stat("mono/tracked").value_or(0), 1);
  EXPECT_EQ(TargetsWithin(&*client, 10), 0);

  // Start: the operator picks again and targets flow again.
  ASSERT_TRUE(panel()->start_button()->isVisible());
  QTest::mouseClick(panel()->start_button(), Qt::LeftButton);
  ASSERT_NO_FATAL_FAILURE(PlayTapYesUntilTargetSent());
  EXPECT_TRUE(ReadUntil(&*client, "target"));
  // The ring sits on the tracked centre.
  const PickerFrame& tracked = picker_->last_result()->picker;
  ASSERT_TRUE(tracked.track.found);
  ASSERT_TRUE(panel()->image_view()->ring_centre().has_value());

  // Switching the pipeline away: the arm hears a stop before the socket closes.
  ASSERT_TRUE(window_->ActivatePipeline(QString()));
  lines.clear();
  EXPECT_TRUE(ReadUntil(&*client, "stop", &lines));
  EXPECT_NE(lines.back().find("pipeline switched"), std::string::npos) << lines.back();
}

TEST_F(OperatorGui, TheRingFollowsTheTrackedCentreOnEveryFrame) {
  ASSERT_NO_FATAL_FAILURE(Open(*dir_));
  ASSERT_TRUE(Step());
  for (int i = 0; i < 100 && !picker_->scale_converged(); ++i) ASSERT_TRUE(Step());
  std::optional<ArmClient> client = ConnectArm(port_);
  ASSERT_TRUE(client.has_value());
  ASSERT_NO_FATAL_FAILURE(PlayTapYesUntilTargetSent());
  int checked = 0;
  for (int i = 0; i < 5; ++i) {
    ASSERT_TRUE(NextFrame());
    const PickerFrame& f = picker_->last_result()->picker;
    if (!f.track.found) continue;
    const std::optional<QPointF> ring = panel()->image_view()->ring_centre();
    ASSERT_TRUE(ring.has_value());
    EXPECT_NEAR(ring->x(), f.track.center.x, 1e-6);
    EXPECT_NEAR(ring->y(), f.track.center.y, 1e-6);
    ++checked;
  }
  window_->playback()->Pause();
  EXPECT_GT(checked, 0);
}

TEST_F(OperatorGui, QuittingSendsTheArmAStop) {
  ASSERT_NO_FATAL_FAILURE(Open(*short_dir_));
  ASSERT_TRUE(Step());
  std::optional<ArmClient> client = ConnectArm(port_);
  ASSERT_TRUE(client.has_value());
  ASSERT_TRUE(window_->close());
  std::vector<std::string> lines;
  EXPECT_TRUE(ReadUntil(&*client, "stop", &lines));
  EXPECT_NE(lines.back().find("quit"), std::string::npos) << lines.back();
}

TEST_F(OperatorGui, TheSourcesEndSendsTheArmAStopAndRefusesTaps) {
  ASSERT_NO_FATAL_FAILURE(Open(*short_dir_));
  ASSERT_TRUE(Step());
  std::optional<ArmClient> client = ConnectArm(port_);
  ASSERT_TRUE(client.has_value());
  QSignalSpy ended(window_->playback(), &PlaybackController::EndOfStream);
  window_->playback()->Play();
  ASSERT_TRUE(QTest::qWaitFor([&] { return ended.count() > 0; }, kWaitMs));
  std::vector<std::string> lines;
  EXPECT_TRUE(ReadUntil(&*client, "stop", &lines));
  EXPECT_NE(lines.back().find("source ended"), std::string::npos) << lines.back();
  EXPECT_EQ(panel()->state(), OperatorState::kHolding);
  EXPECT_EQ(panel()->detail_label()->text(), "End of the recording");
  TapAt({320, 240});
  EXPECT_EQ(panel()->state(), OperatorState::kRefused);
  EXPECT_EQ(panel()->detail_label()->text(), "The recording has ended: nothing to tap");
}

// The operator loop closed through the GUI, as README's command runs it: the live simulated
// camera in the arm's hand (sim://panel, seed 4) played by the window, the picker serving with a
// token, the tap on true button 5 given as button.run.tap, and the simulated arm streaming its
// pose to the window's server, following the targets and pressing. Outcomes against the scene's
// truth; no time assertion (a loaded machine only makes it slower).
// Under load the window drops live frames (the source hands out its newest): the pipeline must
// go on through the gaps (it was reset on every gap and never initialised, 2026-11-26).
TEST_F(OperatorGui, TheLiveLoopThroughTheWindowPressesTheTappedButton) {
  const std::string uri = "sim://panel?seed=4&fps=4";
  port_ = FreePort();
  ASSERT_GT(port_, 0);
  window_ = std::make_unique<MainWindow>();
  picker_ = new ButtonPickerPresenter({"button.arm.port=" + std::to_string(port_),
                                       "button.arm.token=gui-loop", "button.gui.serve=true",
                                       "button.run.tap=button:5"});
  window_->AddPipeline(picker_);
  ASSERT_TRUE(window_->ActivatePipeline(picker_->Title()));
  window_->show();
  QSignalSpy opened(window_.get(), &MainWindow::DatasetOpened);
  window_->OpenPath(QString::fromStdString(uri));
  ASSERT_TRUE(QTest::qWaitFor([&] { return opened.count() == 1; }, kWaitMs));

  ArmSimOptions arm_options;  // Slow enough for a SLAM at a few frames per second.
  arm_options.max_speed_mps = 0.02;
  arm_options.max_angular_speed_dps = 5;
  arm_options.max_time_s = 400;
  StatusOr<ArmSimWorld> world = BuildArmSimWorld(4, arm_options);
  ASSERT_TRUE(world.ok()) << world.status().ToString();
  ArmSimulator arm(arm_options, std::move(*world));
  std::atomic<bool> cancel{false}, done{false};
  StatusOr<ArmSimSessionResult> result = Unavailable("not run");
  std::thread arm_thread([&] {
    for (int attempt = 0; attempt < 300 && !cancel; ++attempt) {
      result = RunArmSimSession("127.0.0.1", port_, "gui-loop", &arm, &cancel);
      if (result.ok()) break;
      std::this_thread::sleep_for(std::chrono::milliseconds(200));  // Not serving yet.
    }
    done = true;
  });
  window_->playback()->Play();
  const bool finished = QTest::qWaitFor([&] { return done.load(); }, 600000);
  cancel = true;
  arm_thread.join();
  ASSERT_TRUE(finished) << "the arm did not finish within 10 minutes";
  ASSERT_TRUE(result.ok()) << result.status().ToString();
  const ArmSimOutcome& o = result->outcome;
  std::printf(
      "GUI loop, seed 4: end %s, nearest button %d, %.2f mm (across %.2f, along %+.2f), "
      "approach %.2f deg\n",
      result->end_reason.c_str(), o.nearest_button, o.distance_mm, o.lateral_mm, o.depth_mm,
      o.approach_error_deg);
  EXPECT_EQ(result->end_reason, "finished");
  EXPECT_EQ(o.nearest_button, 5);
  EXPECT_LT(o.lateral_mm, 9.0);          // On the button's axis (radius 18 mm).
  EXPECT_LT(o.approach_error_deg, 5.0);  // The goal; 0.1-0.2 deg from the arm's motion.
  EXPECT_GT(arm.counts().count("targets") ? arm.counts().at("targets") : 0, 10);
  EXPECT_EQ(arm.counts().count("malformed"), 0u);
}

TEST_F(OperatorGui, OperatorModeIsFullScreenWithLargeButtonsAndAFixedLayout) {
  MainWindow window;
  auto* picker = new ButtonPickerPresenter();
  window.AddPipeline(picker);
  ASSERT_TRUE(window.ActivatePipeline(picker->Title()));
  picker->EnterOperatorMode();
  OperatorPanel* panel = picker->panel();
  ASSERT_TRUE(QTest::qWaitForWindowExposed(panel));
  EXPECT_FALSE(window.isVisible());
  EXPECT_TRUE(panel->isWindow());
  EXPECT_TRUE(panel->isFullScreen());
  const QRect screen = panel->screen()->geometry();
  ASSERT_TRUE(QTest::qWaitFor([&] { return panel->geometry().size() == screen.size(); }, 10000))
      << panel->width() << "x" << panel->height();

  // 15 mm on this screen (96 dpi when it does not know its size).
  double dpi = panel->screen()->physicalDotsPerInch();
  if (!(dpi >= 50 && dpi <= 1000)) dpi = 96;
  const double min_px = 15.0 / 25.4 * dpi;
  panel->ShowCandidate(QPolygonF({{10, 10}, {30, 10}, {30, 30}}));
  for (QPushButton* b : {panel->stop_button(), panel->yes_button(), panel->cancel_button()}) {
    EXPECT_TRUE(b->isVisible()) << b->text().toStdString();
    EXPECT_GE(b->width(), min_px) << b->text().toStdString();
    EXPECT_GE(b->height(), min_px) << b->text().toStdString();
  }

  // The regions stay where they are whatever the words.
  QTest::mouseClick(panel->yes_button(), Qt::LeftButton);
  panel->SetState(OperatorState::kTargetSent);
  QCoreApplication::processEvents();
  const QRect banner = panel->banner()->geometry(), detail = panel->detail_label()->geometry();
  const QRect stop = panel->stop_button()->geometry();
  const QRect image = panel->image_view()->geometry();
  panel->SetState(OperatorState::kHolding, "Button out of reach: move the chair a little closer");
  QCoreApplication::processEvents();
  EXPECT_EQ(panel->banner()->geometry(), banner);
  EXPECT_EQ(panel->detail_label()->geometry(), detail);
  EXPECT_EQ(panel->stop_button()->geometry(), stop);
  EXPECT_EQ(panel->image_view()->geometry(), image);

  // Touch works: a finger on STOP stops at once.
  QPointingDevice* device = QTest::createTouchDevice();
  QSignalSpy stops(panel, &OperatorPanel::StopPressed);
  QTest::touchEvent(panel->stop_button(), device).press(0, panel->stop_button()->rect().center());
  QTest::touchEvent(panel->stop_button(), device).release(0, panel->stop_button()->rect().center());
  EXPECT_EQ(stops.count(), 1);
  EXPECT_EQ(panel->state(), OperatorState::kStopped);

  // F11: a normal window and back; Esc asks before leaving.
  QTest::keyClick(panel, Qt::Key_F11);
  EXPECT_FALSE(panel->isFullScreen());
  QTest::keyClick(panel, Qt::Key_F11);
  EXPECT_TRUE(panel->isFullScreen());
  QSignalSpy left(picker, &ButtonPickerPresenter::OperatorLeft);
  QTest::keyClick(panel, Qt::Key_Escape);
  ASSERT_NE(panel->leave_question(), nullptr);
  EXPECT_EQ(left.count(), 0);
  panel->leave_question()->button(QMessageBox::Cancel)->click();
  EXPECT_EQ(left.count(), 0);
  QTest::keyClick(panel, Qt::Key_Escape);
  ASSERT_NE(panel->leave_question(), nullptr);
  panel->leave_question()->button(QMessageBox::Yes)->click();
  EXPECT_EQ(left.count(), 1);
}

TEST_F(OperatorGui, TheDockedPanelGoesFullScreenWithF11AndBack) {
  MainWindow window;
  auto* picker = new ButtonPickerPresenter();
  window.AddPipeline(picker);
  ASSERT_TRUE(window.ActivatePipeline(picker->Title()));
  window.show();
  window.activateWindow();
  ASSERT_TRUE(QTest::qWaitForWindowActive(&window));
  OperatorPanel* panel = picker->panel();
  EXPECT_FALSE(panel->isWindow());
  QTest::keyClick(&window, Qt::Key_F11);
  ASSERT_TRUE(QTest::qWaitForWindowExposed(panel));
  EXPECT_TRUE(panel->isWindow());
  EXPECT_TRUE(panel->isFullScreen());
  EXPECT_TRUE(QTest::qWaitFor(
      [&] { return panel->geometry().size() == panel->screen()->geometry().size(); }, 10000));
  QTest::keyClick(panel, Qt::Key_F11);  // Back into the dock.
  EXPECT_FALSE(panel->isWindow());
  EXPECT_FALSE(picker->panel_windowed());
}

}  // namespace
}  // namespace sightline
