// The button pipeline's messages: the gated target and the gate's verdict.
#include <cstdio>

#include "core/ros/ros_publish.h"

namespace sightline {

geometry_msgs::PoseStamped ButtonTargetMessage(const ArmTarget& target) {
  geometry_msgs::PoseStamped out;
  out.header.stamp = RosTimeFromSeconds(target.stamp_s);
  out.header.frame_id = target.frame_id;
  out.pose.position.x = target.position_m.x();
  out.pose.position.y = target.position_m.y();
  out.pose.position.z = target.position_m.z();
  const Eigen::Quaterniond q =
      Eigen::Quaterniond::FromTwoVectors(Eigen::Vector3d::UnitX(), target.approach.normalized());
  out.pose.orientation.x = q.x();
  out.pose.orientation.y = q.y();
  out.pose.orientation.z = q.z();
  out.pose.orientation.w = q.w();
  return out;
}

namespace {

diagnostic_msgs::KeyValue Pair(const std::string& key, const std::string& value) {
  diagnostic_msgs::KeyValue out;
  out.key = key;
  out.value = value;
  return out;
}

}  // namespace

std::string OutlineText(const std::vector<cv::Point>& outline) {
  std::string text;
  for (const cv::Point& p : outline) {
    if (!text.empty()) text += ' ';
    text += std::to_string(p.x) + ',' + std::to_string(p.y);
  }
  return text;
}

std::string TapAnswerKey(const ButtonFrameResult& result) {
  if (result.tap_status.ok()) return "found";
  if (result.tap_refused != TapRefusal::kNone) return TapRefusalKey(result.tap_refused);
  return "no_button";
}

diagnostic_msgs::DiagnosticStatus ButtonGateStatus(const ButtonFrameResult& result) {
  diagnostic_msgs::DiagnosticStatus out;
  out.name = "sightline/button/gate";
  out.hardware_id = "sightline";
  const GateVerdict& verdict = result.picker.verdict;
  const bool sent = result.picker.target.has_value();
  out.level =
      sent ? diagnostic_msgs::DiagnosticStatus::OK : diagnostic_msgs::DiagnosticStatus::WARN;
  // A frame without the arm's pose (tf lacks the end effector at its stamp) says that first.
  out.message = sent                               ? "target sent"
                : !result.arm_pose_missing.empty() ? result.arm_pose_missing
                                                   : verdict.message;
  out.values = {Pair("reason", GateReasonKey(verdict.reason)),
                Pair("state", PickerStateKey(result.picker.state)),
                Pair("stopped", result.stopped ? "true" : "false"),
                Pair("held", result.held ? "true" : "false"),
                Pair("tracking_only", result.tracking_only ? "true" : "false"),
                Pair("target_published", result.target_published ? "true" : "false")};
  if (!result.arm_pose_missing.empty())
    out.values.push_back(Pair("arm_pose_missing", result.arm_pose_missing));
  const PickerFrame& f = result.picker;
  if (f.track.found && f.state != PickerState::kIdle && f.state != PickerState::kConfirm &&
      f.state != PickerState::kStopped) {  // The tracked button, for a remote panel's ring.
    char ring[96];
    std::snprintf(ring, sizeof(ring), "%.1f,%.1f,%.1f", f.track.center.x, f.track.center.y,
                  f.track.radius_px);
    out.values.push_back(Pair("ring", ring));
  }
  if (result.tap_answered) {  // The answer to a tap, on the frame that handled it.
    out.values.push_back(Pair("tap", TapAnswerKey(result)));
    char stamp[32];
    std::snprintf(stamp, sizeof(stamp), "%.9f", result.tap_stamp_s);
    out.values.push_back(Pair("tap_stamp", stamp));
    if (result.tap_status.ok() && !result.candidate_outline.empty()) {
      out.values.push_back(Pair("candidate", OutlineText(result.candidate_outline)));
    }
  }
  return out;
}

}  // namespace sightline
