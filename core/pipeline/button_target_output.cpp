#include "core/pipeline/button_target_output.h"

#include <chrono>
#include <thread>

namespace sightline {

StatusOr<std::shared_ptr<ButtonTargetOutput>> ButtonTargetOutput::Start(
    const ArmServerOptions& options, const ArmPoseStreamOptions& pose_options) {
  auto poses = std::make_shared<ArmPoseFeed>(pose_options);
  StatusOr<std::unique_ptr<ArmServer>> started = ArmServer::Start(
      options, [poses](const ArmPoseMessage& pose) { poses->Add(pose); }, pose_options);
  if (!started.ok()) return started.status();
  return std::shared_ptr<ButtonTargetOutput>(
      new ButtonTargetOutput(std::move(poses), std::move(*started)));
}

Status ButtonTargetOutput::WaitForClients(int clients, double timeout_s) {
  const auto start = std::chrono::steady_clock::now();
  while (server_->Stats().authorised < clients) {
    const double waited =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (waited > timeout_s) {
      return Unavailable("button.run.wait_clients: " + std::to_string(server_->Stats().authorised) +
                         " of " + std::to_string(clients) + " arm clients connected within " +
                         std::to_string(timeout_s) + " s");
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  clients_at_start_ = server_->Stats().authorised;
  return Status::Ok();
}

void ButtonTargetOutput::Linger(double seconds) {
  if (lingered_ || seconds <= 0) return;
  lingered_ = true;
  std::this_thread::sleep_for(std::chrono::duration<double>(seconds));
}

}  // namespace sightline
