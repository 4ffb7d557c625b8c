#include "core/pipeline/button_scale_mode.h"

namespace sightline {

Status CheckButtonMetricSource(const MonoSlamRunOptions& run) {
  const std::string& s = run.metric_source;
  if (s == "auto" || s == "arm" || s == "arm_stream" || s == "none") return Status::Ok();
  return InvalidArgument("mono.run.metric_source = " + s +
                         ": the button pipeline takes auto, arm, arm_stream or none (the targets "
                         "are in the arm's base frame; none tracks without sending targets)");
}

namespace {

// The camera's mount on the end effector is given: mono.run.hand_eye, or hand_eye.yaml beside
// the images.
bool HasHandEye(const MonoSlamRunOptions& run, const std::string& path) {
  return !run.hand_eye.empty() || !FindBeside(path, "hand_eye.yaml").empty();
}

}  // namespace

ArmPoseInput ChooseArmPoseInput(const SourceInfo& info, const MonoSlamRunOptions& run, bool serve,
                                bool source_arm) {
  const std::string& s = run.metric_source;
  if (s == "arm_stream") return ArmPoseInput::kStream;
  if (s != "auto" && s != "arm") return ArmPoseInput::kRecorded;
  const bool arm_file = !run.arm_poses.empty() || !FindBeside(info.path, "arm_poses.txt").empty();
  if (info.live && !info.arm_pose_channel.empty() && !arm_file && !source_arm) {
    // auto also needs the camera's mount on the arm: without one it tracks only.
    if (s == "arm" || HasHandEye(run, info.path)) return ArmPoseInput::kLiveSource;
  }
  if (s == "auto" && serve && HasHandEye(run, info.path) && !arm_file && !source_arm)
    return ArmPoseInput::kStream;
  return ArmPoseInput::kRecorded;
}

ButtonScaleMode ChooseButtonScaleMode(const SourceInfo& info, const MonoSlamRunOptions& run,
                                      ArmPoseInput feed, bool source_arm) {
  const std::string& path = info.path;
  ButtonScaleMode mode;
  if (run.metric_source == "none") {
    mode.metric = false;
    mode.how = "tracking only: mono.run.metric_source = none";
    return mode;
  }
  if (feed == ArmPoseInput::kLiveSource) {
    mode.how = "metric scale from the arm's poses of the live source: " + info.arm_pose_channel;
    return mode;
  }
  const bool streamed_arm = feed == ArmPoseInput::kStream;
  const bool arm_file =
      !run.arm_poses.empty() || !FindBeside(path, "arm_poses.txt").empty() || source_arm;
  if (run.metric_source == "arm" || run.metric_source == "arm_stream" || arm_file || streamed_arm) {
    mode.how = streamed_arm && !arm_file ? "metric scale from the streamed arm poses"
                                         : "metric scale from the arm's poses";
    return mode;
  }
  mode.metric = false;
  if (info.live && !info.arm_pose_channel.empty()) {
    mode.how = "tracking only: the live source gives the arm's poses (" + info.arm_pose_channel +
               ") but the camera's mount on the end effector is unknown; set mono.run.hand_eye "
               "to a hand_eye.yaml (end_effector_from_camera), or to none when the camera is the "
               "end effector";
    return mode;
  }
  mode.how = "tracking only: mono.run.metric_source = auto found no arm_poses.txt beside " + path +
             " (nor in its parent folder) and no streamed arm; set mono.run.arm_poses or "
             "mono.run.metric_source = arm to require one";
  return mode;
}

SlamView MapUnitsView::Update(const MonoSlamResult& result, const PinholeCamera& camera) {
  if (result.map && result.map != map_) {
    map_ = result.map;
    auto points = std::make_shared<std::vector<Eigen::Vector3d>>();
    points->reserve(map_->points.size());
    for (const MapSnapshot::Point& p : map_->points) points->push_back(p.position);
    points_ = std::move(points);
  }
  SlamView view;
  view.camera = camera;
  view.tracking = result.tracked && points_ != nullptr;
  view.scale_converged = false;  // Never: nothing may go to the arm.
  view.camera_from_world = result.map_from_camera.inverse();
  view.map_points_in_world = points_;
  return view;
}

}  // namespace sightline
