// The `button` pipeline: the operator's button picker, the same object in the CLI and the GUI.
// Monocular SLAM (the mono-slam pipeline), the metric scale from the arm's poses (recorded in
// arm_poses.txt or a bag's tf, read by a live source from tf at each frame's stamp, or
// streamed live by the arm client to the arm-target server: metric_source arm_stream, chosen
// by auto when serving without arm_poses.txt), the
// operator's tap and answer (ButtonCommands: the GUI's operator panel, or --tap X,Y[@FRAME]
// confirmed at once), tracking, 3D location and the safety gate per frame, in data time (the
// frames' sensor timestamps); targets optionally published through the arm-target server
// (--serve HOST:PORT, button.gui.serve). Finish writes button.csv, the overlay of the track
// and, with the simulator's buttons.csv beside the images, the accuracy against the true centre
// of the tapped button. Without an arm (button_scale_mode.h) it tracks and locates the button in
// map units only and never sends a target.
#pragma once

#include <Eigen/Geometry>
#include <deque>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/button/button_picker.h"
#include "core/common/status.h"
#include "core/options/option_table.h"
#include "core/pipeline/button_overlay.h"
#include "core/pipeline/button_result.h"
#include "core/pipeline/button_scale_mode.h"
#include "core/pipeline/button_target_output.h"
#include "core/pipeline/metric_slam_view.h"
#include "core/pipeline/mono_slam_pipeline.h"
#include "core/pipeline/pipeline_registry.h"

namespace sightline {

// Run-level options of the button pipeline. Keys "button.run.*".
struct ButtonRunOptions {
  std::string tap;             // "X,Y" or "X,Y@FRAME" (frame index; default 0). Required.
  bool serve = false;          // Publish targets through the arm-target server (button.arm.*).
  int wait_clients = 0;        // With serve: wait for this many clients before the first frame.
  double wait_clients_s = 30;  // ... at most this long [s].
  double linger_s = 0.5;       // With serve: keep serving this long after the last frame [s].

  bool IsValid(std::string* error) const;
  static OptionTable<ButtonRunOptions> Describe();
};

// The operator panel's options. Keys "button.gui.*". Serving is on when button.gui.serve or
// button.run.serve is set; switching it on or off while a run goes on keeps the run (the SLAM
// map, the tracked button and the operator's STOP).
struct ButtonGuiOptions {
  bool serve = false;
  double max_tap_age_s = 0.5;  // An operator's tap on a frame older than this is refused [s].

  static OptionTable<ButtonGuiOptions> Describe();
};

// A parsed tap.
struct ButtonTap {
  double x = 0, y = 0;
  int64_t frame = 0;
};
// Parses "X,Y" or "X,Y@FRAME". InvalidArgument naming button.run.tap otherwise.
StatusOr<ButtonTap> ParseButtonTap(const std::string& text);

// One row of button.csv.
struct ButtonRunRow {
  PickerFrame picker;
  double slam_ms = 0;
  bool slam_tracking = false;
  bool scale_converged = false;
  double lambda_ml = 0;
  bool metric = true;  // False: tracking only, the *_m columns are empty.
  // The located button and the camera in the SLAM's map frame, map units (unscaled); NaN when
  // not located / not tracked.
  Eigen::Vector3d button_in_map = Eigen::Vector3d::Constant(std::nan(""));
  Eigen::Vector3d camera_in_map = Eigen::Vector3d::Constant(std::nan(""));
};

// A true button of the simulator's buttons.csv: its centre (map frame) and its projection per
// frame (NaN when not visible).
struct TrueButton {
  int id = -1;
  Eigen::Vector3d center_in_world = Eigen::Vector3d::Zero();
  // Out of the panel, toward the viewer (scene.yaml); NaN when unknown.
  Eigen::Vector3d normal_in_world = Eigen::Vector3d::Constant(std::nan(""));
  std::vector<Eigen::Vector2d> pixel;  // Indexed by frame.
  std::vector<bool> visible;
};
// Reads buttons.csv. NotFound / ParseError naming the file and line.
StatusOr<std::vector<TrueButton>> ReadTrueButtons(const std::string& path);

// Sets the buttons' normals from the simulator's scene.yaml ("- {id: N, ..., normal: [x, y, z]").
// NotFound / ParseError naming the file and line.
Status AddTrueButtonNormals(const std::string& scene_yaml, std::vector<TrueButton>* buttons);

// Writes button.csv (one row per frame from the tap on).
Status WriteButtonCsv(const std::vector<ButtonRunRow>& rows, const std::string& path);

// Where a frame that sent a target was: for the final error and its single-ratio relocation.
struct SentTarget {
  int64_t index = -1;
  ArmTarget target;
  ButtonTrack track;
  Eigen::Isometry3d map_from_camera = Eigen::Isometry3d::Identity();
  std::shared_ptr<const MapSnapshot> map;
  Eigen::Isometry3d base_from_camera = Eigen::Isometry3d::Identity();
  Eigen::Vector3d unfused_in_base = Eigen::Vector3d::Constant(std::nan(""));
  Eigen::Vector3d arm_in_base = Eigen::Vector3d::Constant(std::nan(""));  // PickerFrame's.
};

// What the run's figures need besides button.csv.
struct ButtonRunLog {
  std::vector<ButtonRunRow> rows;  // One per frame from the first tap on.
  std::vector<SentTarget> sent;    // Every frame that sent a target.
  std::optional<cv::Point2d> tapped_centre;
  int64_t tap_index = -1, first_target_index = -1;
  double tap_stamp_s = 0, first_target_stamp_s = 0, processing_ms_to_first = 0;
  // Tracking only: frames whose located button the gate held back only for the missing metric
  // scale (each would have been a candidate target); none is ever published.
  int64_t suppressed_targets = 0;
};

// The simulator's truth beside a recording: its buttons and the arm's base in its map frame.
struct ButtonTruth {
  std::vector<TrueButton> buttons;
  std::optional<Eigen::Isometry3d> world_from_base;
  std::optional<Trajectory> camera_in_world;  // The camera's true poses (groundtruth.txt).
};

// The button pipeline. Process runs the SLAM, applies the operator's commands, tracks, locates,
// gates and publishes; every age and staleness decision uses the frames' sensor timestamps.
class ButtonPipeline : public Pipeline {
 public:
  // Headless without `commands` (button.run.tap is required and confirmed at once).
  explicit ButtonPipeline(std::shared_ptr<ButtonCommands> commands = nullptr,
                          std::shared_ptr<MonoSlamCommands> mono_commands = nullptr);
  ~ButtonPipeline() override;

  Status Configure(const OptionSet& options) override;
  Status Open(const PipelineSource& source) override;
  int64_t FrameLimit() const override { return mono_.FrameLimit(); }
  StatusOr<std::shared_ptr<const PipelineResult>> Process(const Frame& frame) override;
  // New options on a paused picture: unless they started the run again, the shown frame keeps
  // its result (the SLAM never sees a frame twice, no command is taken, nothing is published).
  StatusOr<std::shared_ptr<const PipelineResult>> Reprocess(const Frame& frame) override;
  void Reset() override;
  void Abort(const std::string& reason) override;
  StatusOr<RunResult> Finish(const std::string& out_dir) override;
  const StatisticTable& Statistics() const override { return ButtonStatistics(); }

  // For tests: sleeps this long inside every Process (a slow or loaded host). The outputs must
  // not change, since no decision reads the host clock.
  void SetHostDelayForTest(double seconds) { host_delay_s_ = seconds; }

 private:
  struct Config {
    MonoSlamOptions slam;
    MonoSlamRunOptions mono_run;
    ButtonPickerOptions picker;
    ButtonRunOptions run;
    MetricViewOptions view;
    ArmServerOptions server;
    ArmPoseStreamOptions arm_pose;
    ButtonOverlayOptions overlay;
    bool serve = false;
    double max_tap_age_s = 0.5;    // button.gui.max_tap_age_s.
    std::optional<ButtonTap> tap;  // button.run.tap.
  };
  // A frame already processed, kept for the operator's tap on it.
  struct SeenFrame {
    int64_t id = -1;
    double stamp_s = 0;
    cv::Mat image;
  };
  // How many frames of the run got a pose from the arm's stream or the live source.
  struct ArmStreamCounts {
    int64_t with_pose = 0, without_pose = 0, waited = 0;
    std::string first_missing;  // Live source: why the first frame without a pose had none.
    bool last_missing = false;  // Live source: the last frame had no pose.
  };
  static StatusOr<Config> Parse(const OptionSet& options);
  // The SLAM's run options: no metric source of its own when the arm's poses come frame by frame.
  MonoSlamRunOptions MonoRun() const;
  // Chooses the recorded poses, the live source's or the stream for `source` (reconfiguring the
  // SLAM when that changed) and reads the hand-eye transform a frame-by-frame feed needs.
  Status ChooseMetricSource(const PipelineSource& source);
  // The arm's pose at this frame's stamp (streamed, or the live source's), times
  // end_effector_from_camera, into metric_. A frame without one: `out`->arm_pose_missing says
  // why (live source).
  void FeedArmPose(double stamp_s, ButtonFrameResult* out);
  // The live source's arm pose at exactly this frame's stamp (it looks each frame's up before
  // handing the frame on), or nullopt: never another frame's.
  std::optional<Eigen::Isometry3d> LiveArmPose(double stamp_s) const;
  // A frame without the live source's arm pose: `out` says why (the channel's frames, the
  // stamp); stderr says it when the poses stop coming.
  void NoteMissingLivePose(double stamp_s, ButtonFrameResult* out);
  // Why nothing was sent, when the arm's stream gave no pose; "" otherwise.
  std::string NoArmPoses() const;
  // The run had no metric scale: tracking only (no metric source, or auto while serving and no
  // arm streamed a pose).
  bool TrackedOnly() const;
  // The stream's counts and a note on where the scale came from.
  void AddArmStreamFigures(RunResult* result, std::vector<std::string>* notes) const;
  // Starts the arm-target server when serving is on (STOP stays on for a new one); closes it
  // with a stop line when serving is off.
  Status StartOutput();
  // Every client gets a stop line naming `reason`, then the server closes.
  void StopOutput(const std::string& reason);
  // Serving a recording: says so on stderr and in the notes (targets from recorded frames).
  void NoteReplay();
  void StartRun();
  Status ApplyCommands(const MonoSlamResult& r, int64_t index, ButtonFrameResult* out);
  Status HandleTap(const ButtonTapRequest& tap, const MonoSlamResult& r, int64_t index,
                   ButtonFrameResult* out);
  // The frame an operator's tap was made on, or why the tap is refused.
  TapRefusal FindTapped(const ButtonTapRequest& tap, double now_s, const SeenFrame** seen) const;
  void Remember(const MonoSlamResult& r, int64_t index);
  void RunPicker(const MonoSlamResult& r, SlamView view, int64_t index, ButtonFrameResult* out);
  void Publish(ButtonFrameResult* out);
  void AddLinkState(ButtonFrameResult* out) const;
  double SendTimeS(const FrameStamp& stamp) const;
  void Record(const ButtonFrameResult& out, bool slam_tracking, int64_t index, double slam_ms,
              double frame_ms);
  // The frame's row in the SLAM's map frame (map units) and on the overlay.
  void AddMapUnits(const ButtonFrameResult& out, ButtonRunRow* row) const;
  Status AddOverlay(const ButtonFrameResult& out);
  // Tracking only: the notes and counts of a run without a metric scale; nothing_achieved only
  // when the button was never tracked after the tap.
  void AddTrackingOnlyFigures(RunResult* result, std::vector<std::string>* notes) const;
  void AddStats(const std::vector<std::pair<std::string, double>>& mono, double slam_ms,
                bool picker_ran, ButtonFrameResult* out) const;
  // Angle to the tapped true button's push direction [deg]; NaN without the simulator's truth.
  double ApproachErrorDeg(const Eigen::Vector3d& approach_in_base) const;

  bool headless_;  // No operator: the tap comes from button.run.tap.
  std::shared_ptr<ButtonCommands> commands_;
  Config config_;
  std::optional<OptionSet> options_;  // As last configured.
  std::optional<PipelineSource> source_;
  MonoSlamPipeline mono_;
  std::unique_ptr<ButtonPicker> picker_;
  std::unique_ptr<MetricSlamView> metric_;
  ButtonScaleMode scale_mode_;  // Chosen by Open.
  MapUnitsView map_units_;      // The SLAM's view without a metric scale.
  std::unique_ptr<ButtonOverlayWriter> overlay_;
  std::shared_ptr<ButtonTargetOutput> output_;
  // Where the scale and base frame come from: recorded poses (through the SLAM's metric
  // poses), or frame by frame from the arm's pose stream or the live source.
  ArmPoseInput feed_ = ArmPoseInput::kRecorded;
  // For a frame-by-frame feed.
  Eigen::Isometry3d end_effector_from_camera_ = Eigen::Isometry3d::Identity();
  ArmStreamCounts arm_stream_;
  std::optional<ButtonTruth> truth_;
  const TrueButton* true_button_ = nullptr;  // The tapped one, in truth_.
  ButtonRunLog log_;
  int64_t frames_ = 0;
  double host_delay_s_ = 0;
  std::deque<SeenFrame> seen_;  // Recent frames, oldest first (max_tap_age_s of data time).
  std::shared_ptr<const ButtonFrameResult> last_;  // The last frame's result.
  bool fresh_run_ = true;                          // No frame processed since the run started.
  std::vector<std::string> run_notes_;             // Hand-eye sigmas stated, replay.
};

// The true button nearest the tapped candidate in the tap frame, and its distance [px]; null
// when none is visible there.
const TrueButton* TappedTrueButton(const ButtonRunLog& log, const ButtonTruth& truth,
                                   double* distance_px);

// The angle between `approach_in_base` and the true push direction of `button` (against its
// normal) [deg]; NaN when either is unknown.
double ApproachAngleDeg(const Eigen::Vector3d& approach_in_base, const TrueButton& button,
                        const Eigen::Isometry3d& world_from_base);

// The figures of a finished button run: targets, scale, tap-to-target, server counts and, with
// the simulator's truth, the errors against the tapped button. Notes explain figures left out.
void AddButtonFigures(const ButtonRunLog& log, const MetricSlamView& metric,
                      const PinholeCamera& camera, const ButtonPickerOptions& picker,
                      const ScaleEstimatorOptions& scale, const std::optional<ButtonTruth>& truth,
                      RunResult* result, std::vector<std::string>* notes);

}  // namespace sightline
