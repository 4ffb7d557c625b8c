#include "core/pipeline/button_pipeline.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <thread>

#include "core/button/arm_server.h"
#include "core/io/hand_eye_file.h"
#include "core/pipeline/metric_slam_view.h"
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

namespace {

double Median(std::vector<double> v) {
  if (v.empty()) return std::nan("");
  std::sort(v.begin(), v.end());
  return v.size() % 2 ? v[v.size() / 2] : 0.5 * (v[v.size() / 2 - 1] + v[v.size() / 2]);
}

// Per-axis median of the last `window` positions (all when 0), as the picker fuses them.
Eigen::Vector3d FuseMedian(const std::vector<Eigen::Vector3d>& values, int window) {
  const size_t n = window > 0 ? std::min(values.size(), size_t(window)) : values.size();
  Eigen::Vector3d out;
  for (int k = 0; k < 3; ++k) {
    std::vector<double> axis;
    for (size_t i = values.size() - n; i < values.size(); ++i) axis.push_back(values[i][k]);
    out[k] = Median(axis);
  }
  return out;
}

// What the accuracy needs of the last frame that sent a target.
struct LastTarget {
  int64_t index = -1;
  ArmTarget target;
  ButtonTrack track;
  Eigen::Isometry3d map_from_camera = Eigen::Isometry3d::Identity();
  std::shared_ptr<const MapSnapshot> map;
  Eigen::Isometry3d base_from_camera = Eigen::Isometry3d::Identity();
  Eigen::Vector3d unfused_in_base = Eigen::Vector3d::Constant(std::nan(""));
};

struct Waiter {
  static Status ForClients(ArmServer& server, const ButtonRunOptions& run,
                           const RunContext& context) {
    const auto start = std::chrono::steady_clock::now();
    while (server.Stats().authorised < run.wait_clients) {
      if (context.Cancelled()) {
        server.SendStopAndClose("cancelled");
        return Cancelled("run cancelled while waiting for arm clients");
      }
      const double waited =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      if (waited > run.wait_clients_s) {
        return Unavailable("button.run.wait_clients: " + std::to_string(server.Stats().authorised) +
                           " of " + std::to_string(run.wait_clients) +
                           " arm clients connected within " + std::to_string(run.wait_clients_s) +
                           " s");
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    return Status::Ok();
  }
};

StatusOr<RunResult> RunButtonPipeline(const RunContext& context) {
  const MonoSlamOptions slam_options = context.options.Extract(MonoSlamOptions::Describe());
  MonoSlamRunOptions mono_run = context.options.Extract(MonoSlamRunOptions::Describe());
  const ButtonPickerOptions picker_options =
      context.options.Extract(ButtonPickerOptions::Describe());
  const ButtonRunOptions run = context.options.Extract(ButtonRunOptions::Describe());
  const MetricViewOptions view_options = context.options.Extract(MetricViewOptions::Describe());
  const ArmServerOptions server_options = context.options.Extract(ArmServerOptions::Describe());
  std::string error;
  if (!run.IsValid(&error) || !view_options.IsValid(&error) || !picker_options.IsValid(&error)) {
    return InvalidArgument(error);
  }
  StatusOr<ButtonTap> tap = ParseButtonTap(run.tap);
  if (!tap.ok()) return tap.status();
  const std::string& path = context.dataset_path;
  if (mono_run.metric_source == "auto") mono_run.metric_source = "arm";
  if (mono_run.metric_source != "arm") {
    return InvalidArgument(
        "mono.run.metric_source must be arm (or auto) for the button pipeline: "
        "the targets are in the arm's base frame");
  }
  StatusOr<OpenedMono> opened = OpenMono(path);
  if (!opened.ok()) return opened.status();
  std::string metric_source;
  StatusOr<Trajectory> base_from_camera =
      LoadMetricCameraPoses(path, mono_run, opened->ground_truth, &metric_source);
  if (!base_from_camera.ok()) return base_from_camera.status();
  MetricSlamView metric(*base_from_camera, slam_options.scale, view_options,
                        mono_run.gt_tolerance_s);

  // Ground truth: the simulator's buttons and the arm base in its map frame.
  std::optional<std::vector<TrueButton>> truth;
  std::optional<Eigen::Isometry3d> world_from_base;
  std::vector<std::string> notes;
  if (const std::string file = FindBeside(path, "buttons.csv"); !file.empty()) {
    StatusOr<std::vector<TrueButton>> read = ReadTrueButtons(file);
    if (!read.ok()) return read.status();
    truth = std::move(*read);
    std::string hand_eye = mono_run.hand_eye;
    if (hand_eye.empty()) hand_eye = FindBeside(path, "hand_eye.yaml");
    if (!hand_eye.empty() && hand_eye != "none") {
      StatusOr<HandEye> he = ReadHandEyeFile(hand_eye);
      if (!he.ok()) return he.status();
      world_from_base = he->world_from_base;
    }
  }

  std::unique_ptr<ArmServer> server;
  if (run.serve) {
    StatusOr<std::unique_ptr<ArmServer>> started = ArmServer::Start(server_options);
    if (!started.ok()) return started.status();
    server = std::move(*started);
    SIGHTLINE_RETURN_IF_ERROR(Waiter::ForClients(*server, run, context));
  }
  const int clients_at_start = server ? server->Stats().authorised : 0;

  MonoSlam slam(slam_options);
  SIGHTLINE_RETURN_IF_ERROR(slam.Configure(opened->camera).WithContext(path));
  ButtonPicker picker(picker_options);
  Source& source = *opened->source;
  int64_t total = source.info().frame_count;
  if (mono_run.max_frames > 0 && (total < 0 || total > mono_run.max_frames))
    total = mono_run.max_frames;
  std::vector<ButtonRunRow> rows;
  LastTarget last;
  std::vector<LastTarget> sent;  // Every frame that sent a target, for the single-ratio figure.
  int64_t targets = 0, first_target_index = -1, frames = 0;
  double tap_stamp_s = 0, first_target_stamp_s = 0, processing_ms_to_first = 0;
  std::optional<cv::Point2d> tapped_centre;
  for (int64_t index = 0; total < 0 || index < total; ++index) {
    if (context.Cancelled()) {
      if (server) server->SendStopAndClose("cancelled");  // Signals land here (run --serve).
      return Cancelled("run cancelled after " + std::to_string(index) + " frames");
    }
    StatusOr<std::optional<MonoFrame>> next = NextMonoFrame(source, path);
    if (!next.ok()) return next.status().WithContext("frame " + std::to_string(index));
    if (!*next) break;
    const MonoFrame& mono = **next;
    ++frames;
    const auto start = std::chrono::steady_clock::now();
    StatusOr<std::shared_ptr<const MonoSlamResult>> result = slam.Process(mono);
    if (!result.ok()) return result.status();
    const double slam_ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    context.timing->Add("slam", slam_ms);
    const MonoSlamResult& r = **result;
    const SlamView view = metric.Update(r, opened->camera);
    ButtonRunRow row;
    row.slam_ms = slam_ms;
    row.slam_tracking = view.tracking;
    row.scale_converged = view.scale_converged;
    row.lambda_ml = metric.lambda_ml();
    const int64_t frame_id = mono.stamp.sequence_id >= 0 ? mono.stamp.sequence_id : index;
    if (index == tap->frame) {
      const Status tapped = picker.Tap(mono.image, {tap->x, tap->y}, frame_id);
      if (!tapped.ok()) {
        return tapped.WithContext("tap at " + run.tap + " (frame " + std::to_string(index) + ")");
      }
      tapped_centre = picker.candidate()->center;
      picker.Confirm();  // Headless: the tap is the operator's Yes.
      tap_stamp_s = mono.stamp.sensor_time_s;
      row.picker.frame_id = frame_id;
      row.picker.stamp_s = mono.stamp.sensor_time_s;
      row.picker.state = picker.state();
      row.picker.track.found = true;
      row.picker.track.center = *tapped_centre;
      row.picker.track.radius_px = picker.candidate()->RadiusPx();
      row.picker.track.confidence = 1;
      rows.push_back(row);
    } else if (index > tap->frame) {
      const std::optional<Eigen::Isometry3d> base = metric.BaseFromCamera(mono.stamp.sensor_time_s);
      SlamView gated = view;
      if (!base) gated.tracking = false;  // No arm pose: no base frame for this image.
      const double elapsed_s =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      row.picker = picker.Process(frame_id, mono.stamp.sensor_time_s, mono.image, gated,
                                  base.value_or(Eigen::Isometry3d::Identity()),
                                  mono.stamp.sensor_time_s + elapsed_s);
      context.timing->Add("tracking", row.picker.tracking_ms);
      if (row.picker.target) {
        ++targets;
        if (server) server->PublishTarget(*row.picker.target);
        last = {index, *row.picker.target, row.picker.track, r.map_from_camera, r.map, *base};
        if (row.picker.location)
          last.unfused_in_base = *base * row.picker.location->button_in_camera;
        sent.push_back(last);
      }
      rows.push_back(row);
    }
    const double frame_ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    context.timing->Add("total", frame_ms);
    if (index >= tap->frame && first_target_index < 0) {
      processing_ms_to_first += frame_ms;
      if (last.index >= 0) {
        first_target_index = index;
        first_target_stamp_s = mono.stamp.sensor_time_s;
      }
    }
    if (context.progress) context.progress(index + 1, total);
  }
  slam.Stop();
  if (frames == 0) return OutOfRange(path + " holds no frames");
  if (tap->frame >= frames) {
    return OutOfRange("button.run.tap: frame " + std::to_string(tap->frame) +
                      " is past the last frame (" + std::to_string(frames - 1) + ")");
  }
  if (server) {
    // Queued targets go out, then every client is told the stream is over.
    const auto linger_end =
        std::chrono::steady_clock::now() + std::chrono::duration<double>(run.linger_s);
    while (std::chrono::steady_clock::now() < linger_end && !context.Cancelled())
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
    server->SendStopAndClose(context.Cancelled() ? "cancelled" : "source ended");
  }

  RunResult result;
  result.dataset_format = source.info().format;
  result.frames = frames;
  SIGHTLINE_RETURN_IF_ERROR(
      WriteButtonCsv(rows, (fs::path(context.out_dir) / "button.csv").string()));
  result.outputs.push_back("button.csv");
  result.accuracy.emplace_back("targets_sent", static_cast<double>(targets));
  if (metric.lambda_ml() > 0) result.accuracy.emplace_back("scale_ml", metric.lambda_ml());
  if (metric.lambda_single() > 0)
    result.accuracy.emplace_back("scale_single", metric.lambda_single());
  if (first_target_index >= 0) {
    result.counts.emplace_back("tap_to_first_target_frames",
                               static_cast<double>(first_target_index - tap->frame));
    result.counts.emplace_back("tap_to_first_target_ms",
                               1e3 * (first_target_stamp_s - tap_stamp_s));
    result.counts.emplace_back("tap_to_first_target_processing_ms", processing_ms_to_first);
  } else {
    notes.push_back("no target was sent");
  }
  if (server) {
    const ArmServerStats stats = server->Stats();
    result.counts.emplace_back("arm_clients_at_start", clients_at_start);
    result.counts.emplace_back("arm_targets_published", static_cast<double>(stats.targets));
    result.counts.emplace_back("arm_lines_sent", static_cast<double>(stats.sent_lines));
  }

  // Accuracy against the simulator's true buttons.
  if (truth && tapped_centre) {
    const TrueButton* button = nullptr;
    double best = 1e18;
    for (const TrueButton& b : *truth) {
      if (static_cast<size_t>(tap->frame) >= b.pixel.size() || !b.visible[tap->frame]) continue;
      const double d =
          (b.pixel[tap->frame] - Eigen::Vector2d(tapped_centre->x, tapped_centre->y)).norm();
      if (d < best) best = d, button = &b;
    }
    if (button == nullptr) {
      notes.push_back("no true button is visible in the tap frame");
    } else {
      result.counts.emplace_back("true_button", button->id);
      result.accuracy.emplace_back("tap_selection_error_px", best);
      std::vector<double> errors;
      for (const ButtonRunRow& row : rows) {
        const size_t f = static_cast<size_t>(row.picker.frame_id);
        if (!row.picker.track.found || f >= button->pixel.size() || !button->visible[f]) continue;
        errors.push_back((Eigen::Vector2d(row.picker.track.center.x, row.picker.track.center.y) -
                          button->pixel[f])
                             .norm());
      }
      if (!errors.empty()) {
        result.accuracy.emplace_back("track_error_px_median", Median(errors));
        result.accuracy.emplace_back("track_error_px_max",
                                     *std::max_element(errors.begin(), errors.end()));
        result.counts.emplace_back("track_error_frames", static_cast<double>(errors.size()));
      }
      if (!world_from_base) {
        notes.push_back("hand_eye.yaml has no world_from_base: no 3D error");
      } else if (last.index >= 0) {
        const Eigen::Vector3d truth_in_base = world_from_base->inverse() * button->center_in_world;
        result.accuracy.emplace_back("final_error_mm",
                                     1e3 * (last.target.position_m - truth_in_base).norm());
        result.accuracy.emplace_back("final_error_mm_unfused",
                                     1e3 * (last.unfused_in_base - truth_in_base).norm());
        // The same frames located with the single-ratio scale and fused the same way.
        if (metric.lambda_single() > 0) {
          std::vector<Eigen::Vector3d> single_positions;
          for (const LastTarget& t : sent) {
            if (!t.map) continue;
            const SlamView single = MetricSlamView::MakeView(
                opened->camera, true, t.map_from_camera, *t.map, metric.lambda_single());
            LocatorInput in;
            in.camera = single.camera;
            in.camera_from_world = single.camera_from_world;
            in.points_in_world = single.map_points_in_world.get();
            in.button_px = {t.track.center.x, t.track.center.y};
            in.button_radius_px = t.track.radius_px;
            StatusOr<ButtonLocation> at = ButtonLocator(picker_options.locate).Locate(in);
            if (at.ok() && at->plane_sound)
              single_positions.push_back(t.base_from_camera * at->button_in_camera);
          }
          if (single_positions.empty()) {
            notes.push_back("single-ratio relocation found no sound plane");
          } else {
            Eigen::Vector3d p = FuseMedian(single_positions, picker_options.fuse.window);
            result.accuracy.emplace_back("final_error_mm_single_ratio",
                                         1e3 * (p - truth_in_base).norm());
          }
        }
      }
    }
  }
  result.counts.emplace_back("scale_pairs_used", metric.pairs_used());
  result.counts.emplace_back("lost_frames", slam.lost_frames());
  std::ofstream log(fs::path(context.out_dir) / "button_notes.txt");
  for (const std::string& note : notes) log << note << "\n";
  result.outputs.push_back("button_notes.txt");
  return result;
}

}  // namespace

PipelineInfo ButtonPipeline() {
  PipelineInfo info;
  info.name = "button";
  info.summary =
      "the operator's button picker headless: tap (--tap X,Y[@FRAME]), track, locate, gate, send";
  info.declare_options = [](OptionSet* set) {
    SIGHTLINE_RETURN_IF_ERROR(set->Declare(MonoSlamOptions::Describe()));
    SIGHTLINE_RETURN_IF_ERROR(set->Declare(MonoSlamRunOptions::Describe()));
    SIGHTLINE_RETURN_IF_ERROR(set->Declare(ButtonPickerOptions::Describe()));
    SIGHTLINE_RETURN_IF_ERROR(set->Declare(MetricViewOptions::Describe()));
    SIGHTLINE_RETURN_IF_ERROR(set->Declare(ArmServerOptions::Describe()));
    return set->Declare(ButtonRunOptions::Describe());
  };
  info.run = RunButtonPipeline;
  return info;
}

}  // namespace sightline
