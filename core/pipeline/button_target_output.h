// Where the button pipeline's targets go: the arm-target server (core/button/arm_server.h) when
// button.run.serve / button.gui.serve is on. Publishing is thread-safe, so the operator's STOP
// reaches the arm at once from any thread. The server's arm client streams the arm's poses back
// (`arm_pose`); they arrive in poses() (core/pipeline/arm_pose_feed.h).
#pragma once

#include <functional>
#include <memory>
#include <string>

#include "core/button/arm_server.h"
#include "core/common/status.h"
#include "core/pipeline/arm_pose_feed.h"

namespace sightline {

class ButtonTargetOutput {
 public:
  // Starts the server; the arm's poses (within `pose_options`) go to poses(). Errors name the
  // address and port that could not be bound.
  static StatusOr<std::shared_ptr<ButtonTargetOutput>> Start(
      const ArmServerOptions& options, const ArmPoseStreamOptions& pose_options = {});

  // Live device guard by the host clock: waits until `clients` arm clients are authorised, at
  // most `timeout_s` seconds (Unavailable saying how many came).
  Status WaitForClients(int clients, double timeout_s);
  // Whether the server took the target (false while stopped or closed).
  bool Publish(const ArmTarget& target) { return server_->PublishTarget(target) >= 0; }
  void PublishStop(const std::string& reason) { server_->PublishStop(reason); }
  void Resume() { server_->Resume(); }
  // Live device guard by the host clock: keeps serving `seconds` so that queued lines reach the
  // clients before the run ends. Waits only the first time.
  void Linger(double seconds);

  // Sends every client a stop line naming `reason` and closes the server (any exit path: the
  // source ended, the run was cancelled or failed). Later calls do nothing.
  void Close(const std::string& reason) { server_->SendStopAndClose(reason); }

  ArmServerStats Stats() const { return server_->Stats(); }
  int clients_at_start() const { return clients_at_start_; }
  // The arm's poses received so far (thread-safe).
  ArmPoseFeed& poses() { return *poses_; }

 private:
  ButtonTargetOutput(std::shared_ptr<ArmPoseFeed> poses, std::unique_ptr<ArmServer> server)
      : poses_(std::move(poses)), server_(std::move(server)) {}

  std::shared_ptr<ArmPoseFeed> poses_;  // Outlives server_ (its sink).
  std::unique_ptr<ArmServer> server_;
  int clients_at_start_ = 0;
  bool lingered_ = false;
};

}  // namespace sightline
