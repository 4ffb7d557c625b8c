// Where the button pipeline's metres come from, and its tracking-only mode without them. With
// the arm's poses (arm_poses.txt beside the images, a bag's tf, a live source's tf) the SLAM's
// map is scaled to metres and targets may go to the arm. Without an arm there is no metric
// scale: the pipeline still tracks the tapped button and locates it in the SLAM's map units,
// but never sends a target.
//
// How the mode is chosen (mono.run.metric_source): `arm` needs the arm's poses (an error names
// the missing file); `arm_stream` takes them from the arm's live pose stream (serving); `none`
// forces tracking only; `auto` (the default) uses arm_poses.txt when it is there (or the
// recording's own arm poses), else a live source's arm-pose channel (SourceInfo::
// arm_pose_channel: tf on ros://) when the camera's mount on the end effector is known
// (mono.run.hand_eye), else, while serving with a hand-eye (mono.run.hand_eye or hand_eye.yaml
// beside the images), the arm's pose stream. With a live channel or the stream under auto, the
// frames before the first arm pose, and a whole run without one, are tracking only; else it
// falls back to tracking only, saying so in the notes.
// Ground-truth displacements are no metric source for targets in the arm's base frame.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "core/button/button_picker.h"
#include "core/common/status.h"
#include "core/io/source.h"
#include "core/mono/mono_slam.h"
#include "core/pipeline/mono_inputs.h"

namespace sightline {

// The reason a run has no metric scale, as the CLI, the notes and metrics.json say it.
inline constexpr const char* kNoMetricScaleNote = "no metric scale: no arm motion";

// The chosen mode.
struct ButtonScaleMode {
  bool metric = true;  // Metres from the arm's poses; false: tracking only, map units.
  std::string how;     // How it was chosen, for the notes (which option, which file is missing).
};

// Checks button's mono.run.metric_source: auto, arm, arm_stream or none. InvalidArgument naming the
// key.
Status CheckButtonMetricSource(const MonoSlamRunOptions& run);

// How the arm's poses reach the button pipeline.
enum class ArmPoseInput {
  kRecorded,    // arm_poses.txt or the source's recorded poses (a bag's tf), read when it opens.
  kStream,      // The arm's pose stream to the arm-target server, frame by frame.
  kLiveSource,  // The live source's arm-pose channel (tf on ros://), frame by frame.
};

// The feed for a source (`source_arm`: it carries recorded arm poses, a bag's tf; `serve`:
// targets are served). kLiveSource for a live source with an arm-pose channel under `arm`, or
// under `auto` with mono.run.hand_eye set, unless mono.run.arm_poses names a file; kStream for
// `arm_stream`, or under `auto` while serving with a hand-eye and no other arm poses; else
// kRecorded.
ArmPoseInput ChooseArmPoseInput(const SourceInfo& info, const MonoSlamRunOptions& run, bool serve,
                                bool source_arm);

// The mode for a source (arm_poses.txt is looked for beside info.path or in its parent, or at
// mono.run.arm_poses) and its feed. `source_arm`: the source carries the arm's poses itself (a
// ROS bag's tf), as arm_poses.txt.
ButtonScaleMode ChooseButtonScaleMode(const SourceInfo& info, const MonoSlamRunOptions& run,
                                      ArmPoseInput feed, bool source_arm = false);

// The SLAM as the button picker sees it without a metric scale: the pose and map in map units
// (a scale of 1), never converged. The map's points are copied once per map.
class MapUnitsView {
 public:
  SlamView Update(const MonoSlamResult& result, const PinholeCamera& camera);

 private:
  std::shared_ptr<const MapSnapshot> map_;
  std::shared_ptr<const std::vector<Eigen::Vector3d>> points_;
};

}  // namespace sightline
