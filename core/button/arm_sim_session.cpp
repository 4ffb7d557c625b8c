#include "core/button/arm_sim_session.h"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "core/button/arm_client.h"
#include "core/button/arm_pose_stream.h"
#include "core/button/server_lines.h"

namespace sightline {
namespace {

// Reads every line that arrives before `until_s` (at least those already there) and hands it to
// the arm at once. False when the server closed the connection.
bool ReadUntil(double until_s, ArmClient* client, ArmSimulator* arm) {
  while (true) {
    const double left_s = until_s - WallClockS();
    StatusOr<std::string> line = client->ReadLine(std::max(1, int(std::ceil(left_s * 1000))));
    if (line.ok()) {
      arm->OnLine(*line, WallClockS());
      continue;
    }
    if (line.status().code() == StatusCode::kOutOfRange) return true;
    if (line.status().code() == StatusCode::kParseError) {  // Over-long: dropped whole.
      arm->OnLine("", WallClockS());                        // Counted as malformed.
      continue;
    }
    return false;
  }
}

}  // namespace

double WallClockS() {
  return std::chrono::duration<double>(std::chrono::system_clock::now().time_since_epoch()).count();
}

StatusOr<ArmSimSessionResult> RunArmSimSession(
    const std::string& host, int port, const std::string& token, ArmSimulator* arm,
    const std::atomic<bool>* cancel,
    const std::function<void(double, const Eigen::Isometry3d&)>& on_pose) {
  StatusOr<ArmClient> client = ArmClient::Connect(host, port, token);
  if (!client.ok()) return client.status();
  ArmSimSessionResult result;
  const double period = arm->options().control_period_s;
  const double start = WallClockS();
  arm->Start(start, "connected to " + host + ":" + std::to_string(port));
  double next = start;
  while (true) {
    if (cancel != nullptr && cancel->load()) {
      result.end_reason = "cancelled";
      break;
    }
    if (!ReadUntil(next, &*client, arm)) {
      result.end_reason = "closed";
      break;
    }
    const double now = WallClockS();
    const Eigen::Isometry3d pose = arm->Step(now);
    ArmPoseMessage message;
    message.stamp_s = now;
    message.base_from_end_effector = pose;
    if (!client->Send(ArmPoseLine(message) + "\n").ok()) {
      result.end_reason = "closed";
      break;
    }
    ++result.poses_sent;
    if (on_pose) on_pose(now, pose);
    if (arm->Finished(now)) {
      result.end_reason = "finished";
      break;
    }
    if (now - start > arm->options().max_time_s) {
      result.end_reason = "max_time_s";
      break;
    }
    next = std::max(next + period, now + 0.5 * period);  // Late steps: no burst.
  }
  result.outcome = arm->Outcome();
  return result;
}

}  // namespace sightline
