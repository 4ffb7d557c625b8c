// The operator's button picker in the main window on the simulated panel approach: step until
// the metric scale converges, play, tap the approached button's true centre on the frame on
// screen, confirm, watch the target go out to a TCP client on loopback, press STOP and see the
// stop arrive and no target after it. (A tap counts only on a playing picture, and stepped
// frames hold the targets: see operator_gui_test.cpp.)
#include <gtest/gtest.h>

#include <QPushButton>
#include <QSignalSpy>
#include <QTest>
#include <cstdio>

#include "app/sightline/button_picker_presenter.h"
#include "app/sightline/main_window.h"
#include "app/sightline/playback_controller.h"
#include "core/button/arm_client.h"
#include "core/pipeline/button_pipeline.h"
#include "core/sim/simulate.h"
#include "tests/support/test_data.h"
#include "widgets/operator_panel.h"

namespace sightline {
namespace {

TEST(ButtonPickerPresenter, TapConfirmTargetSentAndStopOnTheSimulatedPanel) {
  const std::string dir = testing::TempDir("button_gui_panel");
  sim::SimulationOptions sim_options = sim::SimulationOptions::ForScene("panel");
  sim_options.arm.sideways_m = 0.12;
  ASSERT_TRUE(sim::Simulate(sim_options, dir).ok());
  StatusOr<std::vector<TrueButton>> buttons = ReadTrueButtons(dir + "/buttons.csv");
  ASSERT_TRUE(buttons.ok()) << buttons.status().ToString();
  const TrueButton* target = nullptr;
  for (const TrueButton& b : *buttons) {
    if (b.id == 5) target = &b;
  }
  ASSERT_NE(target, nullptr);

  ArmServerOptions server;
  server.port = 0;
  int port = 0;
  {  // A free loopback port.
    auto probe = ArmServer::Start(server);
    ASSERT_TRUE(probe.ok());
    port = (*probe)->port();
  }
  server.port = port;
  server.heartbeat_s = 0.05;
  MainWindow window;
  auto* picker =
      new ButtonPickerPresenter({"button.arm.port=" + std::to_string(port),
                                 "button.arm.heartbeat_s=0.05", "button.gui.serve=true"});
  window.AddPipeline(picker);
  ASSERT_TRUE(window.ActivatePipeline(picker->Title()));
  window.show();
  QSignalSpy opened(&window, &MainWindow::DatasetOpened);
  window.OpenPath(QString::fromStdString(dir));
  ASSERT_TRUE(QTest::qWaitFor([&] { return opened.count() == 1; }, 20000));
  QSignalSpy shown(&window, &MainWindow::FrameShown);
  int frames = 0;
  auto step = [&] {
    window.playback()->Step();
    const bool ok = QTest::qWaitFor([&] { return shown.count() == frames + 1; }, 30000);
    ++frames;
    return ok;
  };
  ASSERT_TRUE(step());
  std::optional<ArmClient> client;
  for (int attempt = 0; attempt < 100 && !client; ++attempt) {
    auto c = ArmClient::Connect("127.0.0.1", port, "", 1000);
    if (c.ok())
      client.emplace(std::move(*c));
    else
      QTest::qWait(50);
  }
  ASSERT_TRUE(client.has_value()) << "the picker does not serve on port " << port;

  while (!picker->scale_converged() && frames < 100) ASSERT_TRUE(step()) << "frame " << frames;
  ASSERT_TRUE(picker->scale_converged()) << "after " << frames << " frames";
  const int converged_frame = frames - 1;
  window.playback()->SetSpeed(0.5);
  window.playback()->Play();
  const int before_play = shown.count();
  ASSERT_TRUE(QTest::qWaitFor([&] { return shown.count() > before_play; }, 30000));
  const int tap_frame = int(shown.last().at(0).toLongLong());
  ASSERT_TRUE(target->visible.at(tap_frame));
  emit picker->panel()->Tapped(QPointF(target->pixel[tap_frame].x(), target->pixel[tap_frame].y()));
  ASSERT_TRUE(QTest::qWaitFor(
      [&] {
        return picker->panel()->state() == OperatorState::kConfirm ||
               picker->panel()->state() == OperatorState::kRefused ||
               picker->panel()->state() == OperatorState::kNoButton;
      },
      30000));
  ASSERT_EQ(picker->panel()->state(), OperatorState::kConfirm);
  picker->panel()->yes_button()->click();
  ASSERT_TRUE(QTest::qWaitFor(
      [&] {
        return picker->last_state() == PickerState::kTargetSent || !window.playback()->playing();
      },
      60000));
  ASSERT_EQ(picker->last_state(), PickerState::kTargetSent);
  EXPECT_EQ(picker->panel()->state(), OperatorState::kTargetSent);
  std::printf("scale converged at frame %d, tap on frame %d, target sent at frame %lld\n",
              converged_frame, tap_frame,
              static_cast<long long>(picker->last_result()->stamp.sequence_id));
  bool got_target = false;
  for (int i = 0; i < 1000 && !got_target; ++i) {
    StatusOr<std::string> line = client->ReadLine(5000);
    ASSERT_TRUE(line.ok()) << line.status().ToString();
    got_target = line->find("\"type\":\"target\"") != std::string::npos;
  }
  EXPECT_TRUE(got_target);

  QTest::mousePress(picker->panel()->stop_button(), Qt::LeftButton);
  bool got_stop = false;
  for (int i = 0; i < 1000 && !got_stop; ++i) {
    StatusOr<std::string> line = client->ReadLine(5000);
    ASSERT_TRUE(line.ok()) << line.status().ToString();
    got_stop = line->find("\"type\":\"stop\"") != std::string::npos;
  }
  EXPECT_TRUE(got_stop);
  QTest::mouseRelease(picker->panel()->stop_button(), Qt::LeftButton);
  for (int i = 0; i < 5; ++i) {
    const int before = shown.count();
    ASSERT_TRUE(QTest::qWaitFor([&] { return shown.count() > before; }, 30000));
  }
  window.playback()->Pause();
  EXPECT_EQ(picker->last_state(), PickerState::kStopped);
  EXPECT_EQ(picker->panel()->state(), OperatorState::kStopped);
  // Only heartbeats after the stop.
  for (int i = 0; i < 20; ++i) {
    StatusOr<std::string> line = client->ReadLine(200);
    if (!line.ok()) break;
    EXPECT_EQ(line->find("\"type\":\"target\""), std::string::npos) << *line;
  }
}

}  // namespace
}  // namespace sightline
