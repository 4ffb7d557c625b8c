// The operator panel without an arm: on a plain folder of the simulator's panel frames (no arm
// poses) the tapped and confirmed button is tracked with the panel saying "Tracking only" and
// "No metric scale (no arm motion)", never "Target sent", while a TCP client of the served
// arm link receives heartbeats and no target.
#include <gtest/gtest.h>

#include <QLabel>
#include <QPushButton>
#include <QSignalSpy>
#include <QTest>
#include <cstdio>

#include "app/sightline/button_picker_presenter.h"
#include "app/sightline/main_window.h"
#include "app/sightline/playback_controller.h"
#include "core/button/arm_client.h"
#include "core/button/arm_server.h"
#include "core/pipeline/button_pipeline.h"
#include "core/sim/simulate.h"
#include "tests/support/plain_frames.h"
#include "tests/support/test_data.h"
#include "widgets/operator_panel.h"

namespace sightline {
namespace {

TEST(TrackingOnlyGui, ThePanelSaysTrackingOnlyAndNeverTargetSentWithoutAnArm) {
  const std::string sim_dir = testing::TempDir("tracking_only_gui_sim");
  sim::SimulationOptions sim_options = sim::SimulationOptions::ForScene("panel");
  sim_options.arm.sideways_m = 0.12;
  ASSERT_TRUE(sim::Simulate(sim_options, sim_dir).ok());
  const std::string plain = testing::TempDir("tracking_only_gui_plain") + "/frames";
  ASSERT_GT(testing::MakePlainFrameFolder(sim_dir, plain), 50);
  StatusOr<std::vector<TrueButton>> buttons = ReadTrueButtons(sim_dir + "/buttons.csv");
  ASSERT_TRUE(buttons.ok()) << buttons.status().ToString();
  const TrueButton* target = nullptr;
  for (const TrueButton& b : *buttons) target = b.id == 5 ? &b : target;
  ASSERT_NE(target, nullptr);

  int port = 0;
  {  // A free loopback port.
    ArmServerOptions probe;
    probe.port = 0;
    auto server = ArmServer::Start(probe);
    ASSERT_TRUE(server.ok());
    port = (*server)->port();
  }
  MainWindow window;
  auto* picker =
      new ButtonPickerPresenter({"button.arm.port=" + std::to_string(port),
                                 "button.arm.heartbeat_s=0.05", "button.gui.serve=true"});
  window.AddPipeline(picker);
  ASSERT_TRUE(window.ActivatePipeline(picker->Title()));
  window.show();
  QSignalSpy opened(&window, &MainWindow::DatasetOpened);
  window.OpenPath(QString::fromStdString(plain));
  ASSERT_TRUE(QTest::qWaitFor([&] { return opened.count() == 1; }, 20000));
  QSignalSpy shown(&window, &MainWindow::FrameShown);
  window.playback()->Step();
  ASSERT_TRUE(QTest::qWaitFor([&] { return shown.count() == 1; }, 30000));
  std::optional<ArmClient> client;
  for (int attempt = 0; attempt < 100 && !client; ++attempt) {
    auto c = ArmClient::Connect("127.0.0.1", port, "", 1000);
    if (c.ok())
      client.emplace(std::move(*c));
    else
      QTest::qWait(50);
  }
  ASSERT_TRUE(client.has_value()) << "the picker does not serve on port " << port;

  // Every state the panel shows from here on, frame by frame.
  std::vector<OperatorState> states;
  int tracking_only_frames = 0, ringed = 0, distance_shown = 0;
  QString banner, detail;
  QObject::connect(&window, &MainWindow::FrameShown, [&] {
    states.push_back(picker->panel()->state());
    if (picker->panel()->state() != OperatorState::kTrackingOnly) return;
    ++tracking_only_frames;
    banner = picker->panel()->banner()->text();
    detail = picker->panel()->detail_label()->text();
    distance_shown += picker->panel()->distance_label()->isVisible() ? 1 : 0;
    const auto r = picker->last_result();
    ringed += r && r->tracking_only && r->picker.track.found ? 1 : 0;
  });
  window.playback()->SetSpeed(0.5);
  window.playback()->Play();
  const int before_play = shown.count();
  ASSERT_TRUE(QTest::qWaitFor([&] { return shown.count() > before_play; }, 30000));
  const int tap_frame = int(shown.last().at(0).toLongLong());
  ASSERT_TRUE(target->visible.at(tap_frame));
  emit picker->panel()->Tapped(QPointF(target->pixel[tap_frame].x(), target->pixel[tap_frame].y()));
  ASSERT_TRUE(QTest::qWaitFor(
      [&] {
        const OperatorState s = picker->panel()->state();
        return s == OperatorState::kConfirm || s == OperatorState::kRefused ||
               s == OperatorState::kNoButton;
      },
      30000));
  ASSERT_EQ(picker->panel()->state(), OperatorState::kConfirm);
  picker->panel()->yes_button()->click();
  ASSERT_TRUE(QTest::qWaitFor([&] { return tracking_only_frames >= 20; }, 60000))
      << "frames shown as tracking only: " << tracking_only_frames;
  window.playback()->Pause();
  std::printf("tap on frame %d; %d frames shown as tracking only, %d with the ring\n", tap_frame,
              tracking_only_frames, ringed);
  EXPECT_GE(ringed, 18);
  EXPECT_EQ(std::count(states.begin(), states.end(), OperatorState::kTargetSent), 0);
  EXPECT_NE(picker->last_state(), PickerState::kTargetSent);
  EXPECT_TRUE(picker->last_result()->tracking_only);
  EXPECT_FALSE(picker->scale_converged());
  EXPECT_EQ(banner, QString("Tracking only"));
  EXPECT_EQ(detail, QString("No metric scale (no arm motion)"));
  EXPECT_EQ(distance_shown, 0);  // No metres to show.
  int heartbeats = 0;
  for (int i = 0; i < 2000; ++i) {
    StatusOr<std::string> line = client->ReadLine(200);
    if (!line.ok()) break;
    EXPECT_EQ(line->find("\"type\":\"target\""), std::string::npos) << *line;
    heartbeats += line->find("\"type\":\"heartbeat\"") != std::string::npos;
  }
  EXPECT_GT(heartbeats, 0);
}

}  // namespace
}  // namespace sightline
