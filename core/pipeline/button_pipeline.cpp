#include "core/pipeline/button_pipeline.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <thread>

#include "core/io/hand_eye_file.h"
#include "core/pipeline/hand_eye_check.h"
#include "core/pipeline/mono_inputs.h"

namespace sightline {

namespace fs = std::filesystem;

bool ButtonRunOptions::IsValid(std::string* error) const {
  auto fail = [&](const std::string& m) {
    if (error) *error = "button.run." + m;
    return false;
  };
  if (wait_clients < 0) return fail("wait_clients must be >= 0");
  if (!(wait_clients_s >= 0)) return fail("wait_clients_s must be >= 0");
  if (!(linger_s >= 0)) return fail("linger_s must be >= 0");
  return true;
}

OptionTable<ButtonRunOptions> ButtonRunOptions::Describe() {
  using O = ButtonRunOptions;
  return OptionTable<O>("button.run")
      .String("tap", &O::tap,
              "The operator's tap: X,Y in pixels, optionally @FRAME (frame index, default 0); "
              "confirmed at once. sightline-cli run button --tap X,Y[@FRAME] sets it.")
      .Bool("serve", &O::serve,
            "Publish the targets through the arm-target server (button.arm.*); --serve HOST:PORT.")
      .Int("wait_clients", &O::wait_clients, "clients", 0, 1000, 1,
           "With serve: wait for this many connected clients before the first frame.")
      .Double("wait_clients_s", &O::wait_clients_s, "s", 0, 3600, 1,
              "With serve: give up waiting for clients after this long.")
      .Double("linger_s", &O::linger_s, "s", 0, 60, 0.1,
              "With serve: keep serving this long after the last frame so queued targets go out.");
}

OptionTable<ButtonGuiOptions> ButtonGuiOptions::Describe() {
  using O = ButtonGuiOptions;
  return OptionTable<O>("button.gui")
      .Bool("serve", &O::serve,
            "Serve the targets to the arm over TCP (button.arm.bind_address, port, token); "
            "127.0.0.1:5757 by default. The same as button.run.serve. Switching it keeps the "
            "run (map, button, STOP); switching it off sends the arm a stop line.")
      .Double("max_tap_age_s", &O::max_tap_age_s, "s", 0.01, 10, 0.1,
              "The operator's tap is refused when the frame it was made on is older than this "
              "(data time) by the time the pipeline takes it.");
}

StatusOr<ButtonTap> ParseButtonTap(const std::string& text) {
  const auto bad = [&] {
    return InvalidArgument("button.run.tap = '" + text + "': expected X,Y or X,Y@FRAME (--tap)");
  };
  if (text.empty()) return InvalidArgument("button.run.tap is required: --tap X,Y[@FRAME]");
  ButtonTap tap;
  const char* s = text.c_str();
  char* end = nullptr;
  tap.x = std::strtod(s, &end);
  if (end == s || *end != ',') return bad();
  s = end + 1;
  tap.y = std::strtod(s, &end);
  if (end == s) return bad();
  if (*end == '@') {
    s = end + 1;
    const long long frame = std::strtoll(s, &end, 10);
    if (end == s || frame < 0) return bad();
    tap.frame = frame;
  }
  if (*end != '\0' || !std::isfinite(tap.x) || !std::isfinite(tap.y)) return bad();
  return tap;
}

const StatisticTable& ButtonStatistics() {
  static const StatisticTable kTable = [] {
    StatisticTable table;
    for (const StatisticInfo& s : MonoSlamStatistics()) {
      if (s.unit != "ms") table.push_back(s);  // The SLAM's time is button/slam_ms.
    }
    const StatisticTable button = {
        {"button/slam_ms", "ms", "Monocular SLAM of the frame."},
        {"button/tracking_ms", "ms", "Button tracker of the frame (frames after the tap)."},
        {"button/scale_converged", "", "The metric scale counts as converged."},
        {"button/scale_ml", "", "Map units per metre (ML estimate), 0 = unknown."},
        {"button/track_confidence", "", "Confidence of the button's track, 0..1."},
        {"button/fused_estimates", "count", "Positions in the fused target."},
        {"button/uncertainty_m", "m",
         "1-sigma uncertainty of the target (fit, scale, tracking, hand-eye, spread)."},
        {"button/distance_m", "m", "Distance from the camera to the located button."},
        {"button/target_sent", "", "The safety gate let a target out."},
        {"button/approach_sigma_deg", "deg",
         "1-sigma of the approach direction (the averaged panel normal)."},
        {"button/approach_err_deg", "deg",
         "Angle between the approach and the tapped button's true push direction (simulator)."},
    };
    table.insert(table.end(), button.begin(), button.end());
    return table;
  }();
  return kTable;
}

ButtonPipeline::ButtonPipeline(std::shared_ptr<ButtonCommands> commands,
                               std::shared_ptr<MonoSlamCommands> mono_commands)
    : headless_(commands == nullptr),
      commands_(commands ? std::move(commands) : std::make_shared<ButtonCommands>()),
      mono_(std::move(mono_commands)) {}

ButtonPipeline::~ButtonPipeline() { commands_->ClearImmediate(this); }

StatusOr<ButtonPipeline::Config> ButtonPipeline::Parse(const OptionSet& options) {
  Config c;
  c.slam = options.Extract(MonoSlamOptions::Describe());
  c.mono_run = options.Extract(MonoSlamRunOptions::Describe());
  c.picker = options.Extract(ButtonPickerOptions::Describe());
  c.run = options.Extract(ButtonRunOptions::Describe());
  c.view = options.Extract(MetricViewOptions::Describe());
  c.server = options.Extract(ArmServerOptions::Describe());
  c.arm_pose = options.Extract(ArmPoseStreamOptions::Describe());
  c.overlay = options.Extract(ButtonOverlayOptions::Describe());
  const ButtonGuiOptions gui = options.Extract(ButtonGuiOptions::Describe());
  c.serve = c.run.serve || gui.serve;
  c.max_tap_age_s = gui.max_tap_age_s;
  std::string error;
  if (!c.run.IsValid(&error) || !c.view.IsValid(&error) || !c.picker.IsValid(&error) ||
      !c.arm_pose.IsValid(&error) || !c.overlay.IsValid(&error)) {
    return InvalidArgument(error);
  }
  if (!c.run.tap.empty()) {
    StatusOr<ButtonTap> tap = ParseButtonTap(c.run.tap);
    if (!tap.ok()) return tap.status();
    c.tap = *tap;
  }
  SIGHTLINE_RETURN_IF_ERROR(CheckButtonMetricSource(c.mono_run));
  if (c.mono_run.metric_source == "arm_stream" && !c.serve) {
    return InvalidArgument(
        "mono.run.metric_source = arm_stream needs serving (--serve, button.run.serve or "
        "button.gui.serve): the arm streams its poses to the arm-target server");
  }
  return c;
}

namespace {

// Options of the arm-target server and of the operator panel: changing them keeps the run.
bool IsLinkKey(const std::string& key) {
  return key.rfind("button.arm.", 0) == 0 || key.rfind("button.arm_pose.", 0) == 0 ||
         key.rfind("button.gui.", 0) == 0 || key == "button.run.serve" ||
         key == "button.run.wait_clients" || key == "button.run.wait_clients_s" ||
         key == "button.run.linger_s";
}

// The server's and the pose stream's: changing them starts a new server.
bool IsArmKey(const std::string& key) {
  return key.rfind("button.arm.", 0) == 0 || key.rfind("button.arm_pose.", 0) == 0;
}

// Whether `a` and `b` differ in a key for which `pick(key) == picked`.
bool Differ(const OptionSet& a, const OptionSet& b, bool (*pick)(const std::string&), bool picked) {
  for (const OptionSpec& spec : b.specs()) {
    if (pick(spec.key) != picked) continue;
    StatusOr<OptionValue> x = a.Get(spec.key), y = b.Get(spec.key);
    if (x.ok() != y.ok() || (x.ok() && *x != *y)) return true;
  }
  return false;
}

}  // namespace

Status ButtonPipeline::Configure(const OptionSet& options) {
  StatusOr<Config> parsed = Parse(options);
  if (!parsed.ok()) return parsed.status();
  if (headless_ && !parsed->tap) return ParseButtonTap("").status();  // "--tap is required".
  const bool run_changed = !options_ || Differ(*options_, options, IsLinkKey, false);
  const bool arm_changed = options_ && Differ(*options_, options, IsArmKey, true);
  config_ = std::move(*parsed);
  options_ = options;
  if (run_changed) SIGHTLINE_RETURN_IF_ERROR(mono_.Configure(config_.slam, MonoRun()));
  if (!source_) return Status::Ok();
  if (arm_changed) StopOutput("arm settings changed");
  if (!run_changed) return StartOutput();  // Serving switched: the map and the button stay.
  return Open(*source_);                   // New options start the run again.
}

namespace {

// The simulator's buttons.csv and the arm's base in its map frame (hand_eye.yaml), when there.
StatusOr<std::optional<ButtonTruth>> LoadTruth(const std::string& path,
                                               const MonoSlamRunOptions& run) {
  const std::string file = FindBeside(path, "buttons.csv");
  if (file.empty()) return std::optional<ButtonTruth>();
  StatusOr<std::vector<TrueButton>> read = ReadTrueButtons(file);
  if (!read.ok()) return read.status();
  ButtonTruth truth;
  truth.buttons = std::move(*read);
  const std::string scene = FindBeside(path, "scene.yaml");
  if (!scene.empty()) SIGHTLINE_RETURN_IF_ERROR(AddTrueButtonNormals(scene, &truth.buttons));
  std::string hand_eye = run.hand_eye;
  if (hand_eye.empty()) hand_eye = FindBeside(path, "hand_eye.yaml");
  if (!hand_eye.empty() && hand_eye != "none") {
    StatusOr<HandEye> he = ReadHandEyeFile(hand_eye);
    if (!he.ok()) return he.status();
    truth.world_from_base = he->world_from_base;
  }
  return std::optional<ButtonTruth>(std::move(truth));
}

int64_t FrameId(const FrameStamp& stamp, int64_t index) {
  return stamp.sequence_id >= 0 ? stamp.sequence_id : index;
}

}  // namespace

MonoSlamRunOptions ButtonPipeline::MonoRun() const {
  MonoSlamRunOptions run = config_.mono_run;
  run.metric_source =
      feed_ != ArmPoseInput::kRecorded || run.metric_source == "arm_stream" ? "none" : "arm";
  return run;
}

Status ButtonPipeline::ChooseMetricSource(const PipelineSource& source) {
  const std::string& path = source.info.path;
  const ArmPoseInput feed =
      ChooseArmPoseInput(source.info, config_.mono_run, config_.serve, source.arm_poses != nullptr);
  if (feed != feed_) {
    feed_ = feed;
    SIGHTLINE_RETURN_IF_ERROR(mono_.Configure(config_.slam, MonoRun()));
  }
  end_effector_from_camera_ = Eigen::Isometry3d::Identity();
  if (feed_ == ArmPoseInput::kRecorded || config_.mono_run.hand_eye == "none") return Status::Ok();
  std::string hand_eye = config_.mono_run.hand_eye;
  if (hand_eye.empty()) hand_eye = FindBeside(path, "hand_eye.yaml");
  if (hand_eye.empty() && feed_ == ArmPoseInput::kLiveSource) {
    return NotFound(path + ": the arm's poses come from the live source (" +
                    source.info.arm_pose_channel +
                    ") but the camera's mount on the end effector is not given: set "
                    "mono.run.hand_eye to a hand_eye.yaml (\"none\" = the camera is the end "
                    "effector)");
  }
  if (hand_eye.empty()) {
    return NotFound(path +
                    ": no hand_eye.yaml beside the images for the arm's pose stream "
                    "(mono.run.hand_eye; \"none\" = the camera is the end effector)");
  }
  StatusOr<HandEye> read = ReadHandEyeFile(hand_eye);
  if (!read.ok()) return read.status();
  end_effector_from_camera_ = read->end_effector_from_camera;
  return Status::Ok();
}

Status ButtonPipeline::Open(const PipelineSource& source) {
  SIGHTLINE_RETURN_IF_ERROR(ChooseMetricSource(source));
  scale_mode_ =
      ChooseButtonScaleMode(source.info, config_.mono_run, feed_, source.arm_poses != nullptr);
  if (!scale_mode_.metric) mono_.SetMetricSource("none");
  SIGHTLINE_RETURN_IF_ERROR(mono_.Open(source));
  StatusOr<std::optional<ButtonTruth>> truth = LoadTruth(source.info.path, config_.mono_run);
  if (!truth.ok()) return truth.status();
  truth_ = std::move(*truth);
  true_button_ = nullptr;
  source_ = source;
  ButtonUncertaintyOptions& u = config_.picker.uncertainty;
  StatusOr<std::string> stated =
      StateHandEyeSigmas(HandEyePathFor(source.info.path, config_.mono_run), &u.hand_eye_sigma_m,
                         &u.hand_eye_sigma_deg);
  if (!stated.ok()) return stated.status();
  run_notes_ = {*stated};
  SIGHTLINE_RETURN_IF_ERROR(StartOutput());
  StartRun();
  return Status::Ok();
}

Status ButtonPipeline::StartOutput() {
  if (!config_.serve) {
    StopOutput("serving turned off");
    return Status::Ok();
  }
  if (!output_) {
    StatusOr<std::shared_ptr<ButtonTargetOutput>> started =
        ButtonTargetOutput::Start(config_.server, config_.arm_pose);
    if (!started.ok()) return started.status();
    output_ = std::move(*started);
    if (source_ && !source_->info.live) NoteReplay();
    std::shared_ptr<ButtonTargetOutput> output = output_;
    commands_->SetImmediate(
        this, [output](const std::string& reason) { output->PublishStop(reason); },
        [output] { output->Resume(); });
    // After SetImmediate: a STOP pressed from now on reaches this server at once.
    if (commands_->stopped()) output_->PublishStop("operator");
  }
  return output_->WaitForClients(config_.run.wait_clients, config_.run.wait_clients_s);
}

void ButtonPipeline::NoteReplay() {
  const std::string note = "replay: the targets served come from the recorded frames of " +
                           source_->info.path + ", not from a live camera";
  std::fprintf(stderr, "sightline: %s\n", note.c_str());
  if (std::find(run_notes_.begin(), run_notes_.end(), note) == run_notes_.end())
    run_notes_.push_back(note);
}

void ButtonPipeline::StopOutput(const std::string& reason) {
  if (!output_) return;
  commands_->ClearImmediate(this);
  output_->Close(reason);
  output_.reset();
}

void ButtonPipeline::StartRun() {
  picker_ = std::make_unique<ButtonPicker>(config_.picker);
  if (commands_->stopped()) picker_->Stop();  // A new run does not lift the operator's STOP.
  metric_ = std::make_unique<MetricSlamView>(mono_.metric_poses(), config_.slam.scale, config_.view,
                                             config_.mono_run.gt_tolerance_s);
  map_units_ = MapUnitsView();
  overlay_.reset();
  if (headless_ && config_.overlay.png) {
    overlay_ = std::make_unique<ButtonOverlayWriter>(config_.overlay);
  }
  log_ = ButtonRunLog();
  arm_stream_ = ArmStreamCounts();
  true_button_ = nullptr;
  frames_ = 0;
  seen_.clear();
  last_.reset();
  fresh_run_ = true;
  if (config_.tap) {
    ButtonTapRequest tap;
    tap.x = config_.tap->x;
    tap.y = config_.tap->y;
    tap.frame = config_.tap->frame;
    tap.ahead = true;
    tap.confirm = true;  // button.run.tap is the operator's tap and Yes.
    tap.required = headless_;
    commands_->Tap(tap);
  }
}

void ButtonPipeline::Reset() {
  mono_.Reset();
  if (picker_) picker_->Cancel();
  metric_ = std::make_unique<MetricSlamView>(mono_.metric_poses(), config_.slam.scale, config_.view,
                                             config_.mono_run.gt_tolerance_s);
  map_units_ = MapUnitsView();
  if (overlay_) overlay_ = std::make_unique<ButtonOverlayWriter>(config_.overlay);
  log_ = ButtonRunLog();
  arm_stream_ = ArmStreamCounts();
  frames_ = 0;
  seen_.clear();
  last_.reset();
  fresh_run_ = true;
}

StatusOr<std::shared_ptr<const PipelineResult>> ButtonPipeline::Process(const Frame& frame) {
  if (!metric_) return FailedPrecondition("button: a frame before the source was opened");
  // Serving is on but the server was closed (Abort: the source ended): it starts again.
  if (config_.serve && !output_) SIGHTLINE_RETURN_IF_ERROR(StartOutput());
  const double start = HostTimeS();  // For timing statistics only.
  StatusOr<std::shared_ptr<const MonoSlamFrameResult>> mono = mono_.ProcessMono(frame);
  if (!mono.ok()) return mono.status();
  auto out = std::make_shared<ButtonFrameResult>();
  static_cast<MonoSlamFrameResult&>(*out) = **mono;
  // The SLAM itself has none.
  if (feed_ != ArmPoseInput::kRecorded)
    out->metric_source = feed_ == ArmPoseInput::kStream ? "arm_stream" : "arm";
  if (!out->slam) return std::shared_ptr<const PipelineResult>(out);  // Status says why.
  const double slam_ms = (HostTimeS() - start) * 1000.0;
  if (host_delay_s_ > 0) std::this_thread::sleep_for(std::chrono::duration<double>(host_delay_s_));
  const MonoSlamResult& r = *out->slam;
  if (feed_ != ArmPoseInput::kRecorded) FeedArmPose(r.stamp.sensor_time_s, out.get());
  // Tracking only without a metric source, and under auto for an arm that has not yet given a
  // pose (streamed or on the live source): nothing can be sent before its poses give the scale.
  const bool metric =
      scale_mode_.metric && (feed_ == ArmPoseInput::kRecorded || arm_stream_.with_pose > 0 ||
                             config_.mono_run.metric_source != "auto");
  const SlamView view =
      metric ? metric_->Update(r, mono_.camera()) : map_units_.Update(r, mono_.camera());
  out->tracking_only = !metric;
  out->scale_converged = view.scale_converged;
  out->scale_ml = metric_->lambda_ml();
  const int64_t index = frames_++;
  SIGHTLINE_RETURN_IF_ERROR(ApplyCommands(r, index, out.get()));
  const bool tap_frame = out->tap_answered && out->tap_status.ok();
  if (!tap_frame) RunPicker(r, view, index, out.get());
  AddStats((*mono)->stats, slam_ms, !tap_frame && log_.tap_index >= 0, out.get());
  AddLinkState(out.get());
  Record(*out, view.tracking, index, slam_ms, (HostTimeS() - start) * 1000.0);
  if (log_.tap_index >= 0 && overlay_) SIGHTLINE_RETURN_IF_ERROR(AddOverlay(*out));
  Remember(r, index);
  last_ = out;
  fresh_run_ = false;
  return std::shared_ptr<const PipelineResult>(out);
}

StatusOr<std::shared_ptr<const PipelineResult>> ButtonPipeline::Reprocess(const Frame& frame) {
  if (fresh_run_ || !last_ || last_->stamp.sequence_id != StampOf(frame).sequence_id) {
    return Process(frame);  // A new run (new options) starts on the shown frame.
  }
  auto again = std::make_shared<ButtonFrameResult>(*last_);
  again->tap_answered = false;
  again->tap_status = Status::Ok();
  again->tap_refused = TapRefusal::kNone;
  again->tap_stamp_s = 0;
  again->target_published = false;
  AddLinkState(again.get());
  return std::shared_ptr<const PipelineResult>(again);
}

void ButtonPipeline::FeedArmPose(double stamp_s, ButtonFrameResult* out) {
  bool waited = false;
  std::optional<Eigen::Isometry3d> base_from_end_effector;
  if (feed_ == ArmPoseInput::kLiveSource) {
    base_from_end_effector = LiveArmPose(stamp_s);
  } else if (output_) {
    base_from_end_effector = output_->poses().At(stamp_s, &waited);
  }
  arm_stream_.waited += waited ? 1 : 0;
  if (!base_from_end_effector) {
    ++arm_stream_.without_pose;  // No base frame and no scale pair for this frame.
    if (feed_ == ArmPoseInput::kLiveSource) NoteMissingLivePose(stamp_s, out);
    return;
  }
  if (arm_stream_.last_missing) {
    std::fprintf(stderr, "sightline: button: the arm's pose is back at %.6f s (%s)\n", stamp_s,
                 source_->info.arm_pose_channel.c_str());
  }
  arm_stream_.last_missing = false;
  ++arm_stream_.with_pose;
  metric_->AddMeasuredPose(stamp_s, *base_from_end_effector * end_effector_from_camera_);
}

std::optional<Eigen::Isometry3d> ButtonPipeline::LiveArmPose(double stamp_s) const {
  const Trajectory* poses =
      source_ && source_->live_arm_poses ? source_->live_arm_poses() : nullptr;
  if (poses == nullptr || poses->empty()) return std::nullopt;
  // The source adds a pose for a frame at that frame's own stamp, or none: a neighbour's pose
  // is never taken for it (tf's own gap limit, the source's tf_gap, already applied).
  const std::optional<size_t> i = poses->Nearest(stamp_s, kStampResolutionS);
  if (!i) return std::nullopt;
  return poses->poses()[*i].world_from_sensor;
}

void ButtonPipeline::NoteMissingLivePose(double stamp_s, ButtonFrameResult* out) {
  char stamp[64];
  std::snprintf(stamp, sizeof(stamp), "%.6f", stamp_s);
  out->arm_pose_missing = "no arm pose at " + std::string(stamp) +
                          " s: " + source_->info.arm_pose_channel +
                          " has no transform at that stamp; the frame has no base frame and no "
                          "scale pair";
  if (arm_stream_.first_missing.empty()) arm_stream_.first_missing = out->arm_pose_missing;
  // Said when the poses stop coming, not for every frame after (the counts are in the figures).
  if (!arm_stream_.last_missing)
    std::fprintf(stderr, "sightline: button: %s\n", out->arm_pose_missing.c_str());
  arm_stream_.last_missing = true;
}

void ButtonPipeline::AddLinkState(ButtonFrameResult* out) const {
  out->held = commands_->held();
  out->stopped = commands_->stopped();
  out->serving = output_ != nullptr;
  out->arm_clients = output_ ? output_->Stats().authorised : 0;
}

void ButtonPipeline::Remember(const MonoSlamResult& r, int64_t index) {
  if (headless_) return;  // Headless taps are for a frame ahead.
  seen_.push_back({FrameId(r.stamp, index), r.stamp.sensor_time_s, r.image});
  while (seen_.size() > 64 || (seen_.size() > 1 && r.stamp.sensor_time_s - seen_.front().stamp_s >
                                                       config_.max_tap_age_s)) {
    seen_.pop_front();
  }
}

Status ButtonPipeline::ApplyCommands(const MonoSlamResult& r, int64_t index,
                                     ButtonFrameResult* out) {
  const ButtonCommands::Pending pending = commands_->Take(index);
  const bool stopped = commands_->stopped();  // The latch decides, whatever came in between.
  if (pending.stop || stopped) picker_->Stop();
  if (pending.restart && !stopped) picker_->Start();
  if (pending.cancel) picker_->Cancel();
  if (pending.tap) {
    SIGHTLINE_RETURN_IF_ERROR(HandleTap(*pending.tap, r, index, out));
    if (!pending.tap->ahead) {
      commands_->PostAnswer(
          {pending.tap->frame, out->tap_status, out->tap_refused, out->candidate_outline});
    }
  }
  if (pending.confirm) picker_->Confirm();
  if (out->tap_answered && out->tap_status.ok()) out->picker.state = picker_->state();
  return Status::Ok();
}

Status ButtonPipeline::HandleTap(const ButtonTapRequest& tap, const MonoSlamResult& r,
                                 int64_t index, ButtonFrameResult* out) {
  int64_t frame_id = FrameId(r.stamp, index);
  cv::Mat still = r.image;
  out->tap_answered = true;
  out->tap_stamp_s = tap.stamp_s;
  if (!tap.ahead) {  // The operator's: found on the frame the operator saw, or refused.
    const SeenFrame* seen = nullptr;
    out->tap_refused = FindTapped(tap, r.stamp.sensor_time_s, &seen);
    if (out->tap_refused != TapRefusal::kNone) {
      out->tap_status =
          FailedPrecondition("tap on frame " + std::to_string(tap.frame) + " refused");
      return Status::Ok();
    }
    frame_id = seen->id;
    still = seen->image;
  }
  out->tap_status = picker_->Tap(still, {tap.x, tap.y}, frame_id);
  if (!tap.ahead && out->tap_status.code() == StatusCode::kFailedPrecondition) {
    out->tap_refused = TapRefusal::kStopped;
  }
  if (!out->tap_status.ok()) {
    if (!tap.required) return Status::Ok();  // The operator is asked again.
    return out->tap_status.WithContext("tap at " + config_.run.tap + " (frame " +
                                       std::to_string(index) + ")");
  }
  const ButtonModel& candidate = *picker_->candidate();
  out->candidate_outline = candidate.contour;
  if (tap.confirm) picker_->Confirm();
  log_.tapped_centre = candidate.center;
  log_.tap_index = index;
  double distance_px = 0;
  true_button_ = truth_ ? TappedTrueButton(log_, *truth_, &distance_px) : nullptr;
  log_.tap_stamp_s = r.stamp.sensor_time_s;
  log_.first_target_index = -1;
  log_.processing_ms_to_first = 0;
  // The tap frame's row: the candidate, tracked by the tap itself.
  PickerFrame& p = out->picker;
  p.frame_id = frame_id;
  p.stamp_s = r.stamp.sensor_time_s;
  p.track.found = true;
  p.track.center = candidate.center;
  p.track.radius_px = candidate.RadiusPx();
  p.track.confidence = 1;
  return Status::Ok();
}

TapRefusal ButtonPipeline::FindTapped(const ButtonTapRequest& tap, double now_s,
                                      const SeenFrame** seen) const {
  if (commands_->stopped()) return TapRefusal::kStopped;
  for (const SeenFrame& f : seen_) {
    if (f.id != tap.frame || std::abs(f.stamp_s - tap.stamp_s) > 1e-6) continue;
    if (now_s - f.stamp_s > config_.max_tap_age_s) return TapRefusal::kTooOld;
    *seen = &f;
    return TapRefusal::kNone;
  }
  return tap.frame >= 0 && !seen_.empty() && tap.stamp_s < seen_.front().stamp_s
             ? TapRefusal::kTooOld
             : TapRefusal::kNoPicture;
}

// The time a target of this frame goes out, on the sensor clock. A recording runs in data time:
// the frame's own time, however long the host takes. A live device's frames age in real time
// while they wait and are processed: that delay is guarded by the host clock at send time.
double ButtonPipeline::SendTimeS(const FrameStamp& stamp) const {
  if (!source_ || !source_->info.live || stamp.host_time_s <= 0) return stamp.sensor_time_s;
  const double live_delay_s = HostTimeS() - stamp.host_time_s;  // Live device guard.
  return stamp.sensor_time_s + std::max(0.0, live_delay_s);
}

void ButtonPipeline::RunPicker(const MonoSlamResult& r, SlamView view, int64_t index,
                               ButtonFrameResult* out) {
  // Tracking only: the map frame in map units stands for the base frame; nothing goes out. A
  // frame the live source gave no arm pose has none: a neighbour's within the association
  // tolerance does not stand in.
  std::optional<Eigen::Isometry3d> base(r.map_from_camera);
  if (!out->tracking_only) {
    base = out->arm_pose_missing.empty() ? metric_->BaseFromCamera(r.stamp.sensor_time_s)
                                         : std::nullopt;
  }
  if (!base) view.tracking = false;  // No arm pose: no base frame for this image.
  view.arm_pose = !out->tracking_only && base.has_value();
  out->picker = picker_->Process(FrameId(r.stamp, index), r.stamp.sensor_time_s, r.image, view,
                                 base.value_or(Eigen::Isometry3d::Identity()), SendTimeS(r.stamp));
  if (out->tracking_only) {
    if (out->picker.verdict.reason == GateReason::kScaleNotConverged) ++log_.suppressed_targets;
    out->picker.target.reset();  // Never without metres, whatever the gate said.
    return;
  }
  if (!out->picker.target) return;
  if (commands_->held()) {  // The picture is paused: nothing goes to the arm.
    out->picker.target.reset();
    return;
  }
  Publish(out);
  SentTarget sent;
  sent.index = index;
  sent.target = *out->picker.target;
  sent.track = out->picker.track;
  sent.map_from_camera = r.map_from_camera;
  sent.map = r.map;
  sent.base_from_camera = *base;
  if (out->picker.location) sent.unfused_in_base = *base * out->picker.location->button_in_camera;
  sent.arm_in_base = out->picker.arm_in_base;
  log_.sent.push_back(std::move(sent));
}

void ButtonPipeline::Publish(ButtonFrameResult* out) {
  out->target_published = output_ && output_->Publish(*out->picker.target);
}

void ButtonPipeline::AddStats(const std::vector<std::pair<std::string, double>>& mono,
                              double slam_ms, bool picker_ran, ButtonFrameResult* out) const {
  out->stats.clear();
  for (const auto& [key, value] : mono) {
    if (key.size() < 3 || key.compare(key.size() - 3, 3, "_ms") != 0)
      out->stats.emplace_back(key, value);
  }
  const PickerFrame& p = out->picker;
  out->stats.emplace_back("button/slam_ms", slam_ms);
  if (picker_ran) out->stats.emplace_back("button/tracking_ms", p.tracking_ms);
  out->stats.emplace_back("button/scale_converged", out->scale_converged ? 1 : 0);
  out->stats.emplace_back("button/scale_ml", out->scale_ml);
  out->stats.emplace_back("button/track_confidence", p.track.confidence);
  out->stats.emplace_back("button/fused_estimates", p.fused_estimates);
  if (p.location && !out->tracking_only) {  // Metres only with a metric scale.
    out->stats.emplace_back("button/uncertainty_m", p.uncertainty_m);
    out->stats.emplace_back("button/distance_m", p.location->button_in_camera.norm());
  }
  out->stats.emplace_back("button/target_sent", p.target ? 1 : 0);
  if (std::isfinite(p.approach_sigma_deg)) {
    out->stats.emplace_back("button/approach_sigma_deg", p.approach_sigma_deg);
  }
  const double error_deg = ApproachErrorDeg(p.approach_in_base);
  if (std::isfinite(error_deg)) out->stats.emplace_back("button/approach_err_deg", error_deg);
}

double ButtonPipeline::ApproachErrorDeg(const Eigen::Vector3d& approach_in_base) const {
  if (!true_button_ || !truth_ || !truth_->world_from_base) return std::nan("");
  return ApproachAngleDeg(approach_in_base, *true_button_, *truth_->world_from_base);
}

void ButtonPipeline::Record(const ButtonFrameResult& out, bool slam_tracking, int64_t index,
                            double slam_ms, double frame_ms) {
  if (log_.tap_index < 0) return;  // button.csv starts at the tap.
  ButtonRunRow row;
  row.picker = out.picker;
  row.slam_ms = slam_ms;
  row.slam_tracking = slam_tracking;
  row.scale_converged = out.scale_converged;
  row.lambda_ml = out.scale_ml;
  AddMapUnits(out, &row);
  log_.rows.push_back(std::move(row));
  if (log_.first_target_index >= 0) return;
  log_.processing_ms_to_first += frame_ms;  // Host time: a timing figure, decides nothing.
  if (!log_.sent.empty() && log_.sent.back().index >= log_.tap_index) {
    log_.first_target_index = index;
    log_.first_target_stamp_s = out.stamp.sensor_time_s;
  }
}

void ButtonPipeline::AddMapUnits(const ButtonFrameResult& out, ButtonRunRow* row) const {
  row->metric = !out.tracking_only;
  if (!out.slam || !out.slam->tracked) return;
  const Eigen::Isometry3d& map_from_camera = out.slam->map_from_camera;
  row->camera_in_map = map_from_camera.translation();
  if (!out.picker.location) return;
  const double lambda = !out.tracking_only ? metric_->lambda_ml() : 1.0;  // Map units per metre.
  if (!(lambda > 0)) return;
  row->button_in_map = map_from_camera * (out.picker.location->button_in_camera * lambda);
}

Status ButtonPipeline::AddOverlay(const ButtonFrameResult& out) {
  const PickerFrame& p = out.picker;
  char line[160];
  std::vector<std::string> caption;
  std::snprintf(line, sizeof(line), "frame %lld  %s", static_cast<long long>(p.frame_id),
                PickerStateKey(p.state));
  caption.emplace_back(line);
  const ButtonRunRow& row = log_.rows.back();
  if (out.tracking_only) {
    caption.emplace_back(std::string("TRACKING ONLY: ") + kNoMetricScaleNote);
    if (row.button_in_map.allFinite()) {
      std::snprintf(line, sizeof(line), "button (%.3f, %.3f, %.3f) map units (unscaled)",
                    row.button_in_map.x(), row.button_in_map.y(), row.button_in_map.z());
      caption.emplace_back(line);
    }
  } else {
    caption.emplace_back(std::string("gate: ") + GateReasonKey(p.verdict.reason));
    if (p.button_in_base.allFinite()) {
      std::snprintf(line, sizeof(line), "button (%.3f, %.3f, %.3f) m, arm base",
                    p.button_in_base.x(), p.button_in_base.y(), p.button_in_base.z());
      caption.emplace_back(line);
    }
  }
  return overlay_->Add(out.slam ? out.slam->image : cv::Mat(), p.frame_id, p.track, caption);
}

void ButtonPipeline::Abort(const std::string& reason) { StopOutput(reason); }

namespace {

// Why a run achieved nothing: no target went out. Empty when one did.
std::string NoTargetSent(const ButtonRunLog& log, int64_t frames) {
  if (!log.sent.empty()) return "";
  if (log.tap_index < 0)
    return "no target sent: no button was tapped in " + std::to_string(frames) + " frame(s)";
  return "no target sent: the button tapped at frame " + std::to_string(log.tap_index) +
         " was never located well enough to pass the safety gate in the " +
         std::to_string(frames - log.tap_index) + " frame(s) from the tap on";
}

}  // namespace

bool ButtonPipeline::TrackedOnly() const {
  if (!scale_mode_.metric) return true;
  // auto, serving without arm_poses.txt, and no arm ever streamed its pose (a plain recording),
  // or a live source whose channel never gave one.
  return feed_ != ArmPoseInput::kRecorded && arm_stream_.with_pose == 0 &&
         config_.mono_run.metric_source == "auto";
}

std::string ButtonPipeline::NoArmPoses() const {
  if (feed_ == ArmPoseInput::kRecorded || !log_.sent.empty() || arm_stream_.with_pose > 0)
    return "";
  if (feed_ == ArmPoseInput::kLiveSource) {
    return "no target sent: none of the " + std::to_string(frames_) +
           " frame(s) had an arm pose from the live source (" + source_->info.arm_pose_channel +
           "; the first: " + arm_stream_.first_missing +
           "): without the arm's poses there is neither a metric scale nor the arm's base frame";
  }
  const int64_t received = output_ ? output_->Stats().poses_received : 0;
  return "no target sent: none of the " + std::to_string(frames_) +
         " frame(s) had an arm pose (mono.run.metric_source = arm_stream, " +
         std::to_string(received) + " arm_pose line(s) received" +
         (output_ ? "" : ", not serving") +
         "): without the arm's poses there is neither a metric scale nor the arm's base frame";
}

void ButtonPipeline::AddArmStreamFigures(RunResult* result, std::vector<std::string>* notes) const {
  const bool stream = feed_ == ArmPoseInput::kStream, live = feed_ == ArmPoseInput::kLiveSource;
  result->counts.emplace_back("metric_from_arm_stream", stream ? 1 : 0);
  result->counts.emplace_back("metric_from_live_arm_poses", live ? 1 : 0);
  if (!stream && !live) return;
  if (stream && output_) {
    const ArmServerStats stats = output_->Stats();
    result->counts.emplace_back("arm_poses_received", static_cast<double>(stats.poses_received));
    result->counts.emplace_back("arm_poses_over_rate", static_cast<double>(stats.poses_over_rate));
    result->counts.emplace_back("arm_poses_refused", static_cast<double>(stats.poses_refused));
    if (!stats.last_pose_error.empty())
      notes->push_back("last arm_pose refused: " + stats.last_pose_error);
  }
  result->counts.emplace_back("frames_with_arm_pose", static_cast<double>(arm_stream_.with_pose));
  result->counts.emplace_back("frames_without_arm_pose",
                              static_cast<double>(arm_stream_.without_pose));
  if (stream) {
    result->counts.emplace_back("frames_waited_for_arm_pose",
                                static_cast<double>(arm_stream_.waited));
  }
  notes->push_back("metric scale source: " +
                   (stream ? std::string("the arm's pose stream")
                           : "the live source's arm poses, " + source_->info.arm_pose_channel) +
                   " (" + std::to_string(arm_stream_.with_pose) + " of " + std::to_string(frames_) +
                   " frame(s) with an arm pose)");
  if (live && !arm_stream_.first_missing.empty()) {
    notes->push_back(std::to_string(arm_stream_.without_pose) +
                     " frame(s) without an arm pose; the first: " + arm_stream_.first_missing);
  }
}

StatusOr<RunResult> ButtonPipeline::Finish(const std::string& out_dir) {
  if (!source_ || frames_ == 0) {
    return OutOfRange((source_ ? source_->info.path : std::string("button")) + " holds no frames");
  }
  if (headless_ && config_.tap && commands_->tap_pending()) {
    return OutOfRange("button.run.tap: frame " + std::to_string(config_.tap->frame) +
                      " is past the last frame (" + std::to_string(frames_ - 1) + ")");
  }
  if (output_ && headless_) {
    output_->Linger(config_.run.linger_s);  // Queued targets go out first.
    output_->Close("source ended");
  }
  RunResult result;
  result.dataset_format = source_->info.format;
  result.frames = frames_;
  SIGHTLINE_RETURN_IF_ERROR(WriteButtonCsv(log_.rows, (fs::path(out_dir) / "button.csv").string()));
  result.outputs.push_back("button.csv");
  std::vector<std::string> notes = run_notes_;  // Hand-eye sigmas stated, replay.
  if (truth_) truth_->camera_in_world = mono_.ground_truth();
  AddButtonFigures(log_, *metric_, mono_.camera(), config_.picker, config_.slam.scale, truth_,
                   &result, &notes);
  if (output_) {
    const ArmServerStats stats = output_->Stats();
    result.counts.emplace_back("arm_clients_at_start", output_->clients_at_start());
    result.counts.emplace_back("arm_targets_published", static_cast<double>(stats.targets));
    result.counts.emplace_back("arm_lines_sent", static_cast<double>(stats.sent_lines));
  }
  AddArmStreamFigures(&result, &notes);
  result.counts.emplace_back("scale_pairs_used", metric_->pairs_used());
  result.counts.emplace_back("lost_frames", mono_.lost_frames());
  result.counts.emplace_back("metric_scale", TrackedOnly() ? 0 : 1);
  if (overlay_) SIGHTLINE_RETURN_IF_ERROR(overlay_->Finish(out_dir, &result.outputs, &notes));
  if (!TrackedOnly()) {
    result.nothing_achieved = NoArmPoses();
    if (result.nothing_achieved.empty()) result.nothing_achieved = NoTargetSent(log_, frames_);
  } else {
    AddTrackingOnlyFigures(&result, &notes);
  }
  if (!result.nothing_achieved.empty()) notes.insert(notes.begin(), result.nothing_achieved);
  result.notes = notes;
  std::ofstream log(fs::path(out_dir) / "button_notes.txt");
  for (const std::string& note : notes) log << note << "\n";
  result.outputs.push_back("button_notes.txt");
  result.notes = std::move(notes);
  return result;
}

PipelineInfo ButtonPipelineInfo(const std::shared_ptr<ButtonCommands>& commands,
                                const std::shared_ptr<MonoSlamCommands>& mono_commands) {
  PipelineInfo info;
  info.name = "button";
  info.title = "Button picker (monocular SLAM)";
  info.summary = "the operator's button picker: tap (--tap X,Y[@FRAME]), track, locate, gate, send";
  info.accepts = {SourceKind::kMono, SourceKind::kStereo};
  info.declare_options = [](OptionSet* set) {
    SIGHTLINE_RETURN_IF_ERROR(set->Declare(MonoSlamOptions::Describe()));
    SIGHTLINE_RETURN_IF_ERROR(set->Declare(MonoSlamRunOptions::Describe()));
    SIGHTLINE_RETURN_IF_ERROR(set->Declare(ButtonPickerOptions::Describe()));
    SIGHTLINE_RETURN_IF_ERROR(set->Declare(MetricViewOptions::Describe()));
    SIGHTLINE_RETURN_IF_ERROR(set->Declare(ArmServerOptions::Describe()));
    SIGHTLINE_RETURN_IF_ERROR(set->Declare(ArmPoseStreamOptions::Describe()));
    SIGHTLINE_RETURN_IF_ERROR(set->Declare(ButtonGuiOptions::Describe()));
    SIGHTLINE_RETURN_IF_ERROR(set->Declare(ButtonOverlayOptions::Describe()));
    return set->Declare(ButtonRunOptions::Describe());
  };
  info.create = [commands, mono_commands]() -> std::unique_ptr<Pipeline> {
    return std::make_unique<ButtonPipeline>(commands, mono_commands);
  };
  return info;
}

}  // namespace sightline
