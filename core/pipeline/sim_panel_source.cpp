#include "core/pipeline/sim_panel_source.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <thread>
#include <variant>

#include "core/button/arm_sim_session.h"
#include "core/io/hand_eye_file.h"
#include "core/sensors/driver_registry.h"

namespace sightline {
namespace {

constexpr char kScheme[] = "sim://";
constexpr char kPanel[] = "panel";

LiveSourceOptions SimLiveOptions() {
  LiveSourceOptions o;
  o.queue_capacity = 1;
  o.grab_timeout_ms = 60000;  // A loaded host renders slowly; the run must not end for it.
  o.stall_timeout_ms = 0;     // Nothing to reconnect.
  return o;
}

Status BadUri(const std::string& uri, const std::string& why) {
  return InvalidArgument(uri + ": " + why + " (expected sim://panel?seed=N&fps=F)");
}

}  // namespace

bool IsSimUri(const std::string& uri) { return uri.rfind(kScheme, 0) == 0; }

StatusOr<SimPanelUri> ParseSimPanelUri(const std::string& uri) {
  if (!IsSimUri(uri)) return BadUri(uri, "not a sim:// URI");
  const std::string rest = uri.substr(std::strlen(kScheme));
  const size_t question = rest.find('?');
  if (rest.substr(0, question) != kPanel) {
    return BadUri(uri, "unknown scene '" + rest.substr(0, question) + "' (only panel is live)");
  }
  SimPanelUri out;
  std::string query = question == std::string::npos ? "" : rest.substr(question + 1);
  while (!query.empty()) {
    const size_t amp = query.find('&');
    const std::string item = query.substr(0, amp);
    query = amp == std::string::npos ? "" : query.substr(amp + 1);
    const size_t eq = item.find('=');
    const std::string key = item.substr(0, eq);
    const std::string value = eq == std::string::npos ? "" : item.substr(eq + 1);
    if (key != "seed" && key != "fps") return BadUri(uri, "unknown key '" + key + "'");
    char* end = nullptr;
    const double number = std::strtod(value.c_str(), &end);
    if (value.empty() || *end != '\0' || !std::isfinite(number)) {
      return BadUri(uri, "'" + item + "' needs a number");
    }
    if (key == "seed") {
      if (number < 0 || number != std::floor(number) || number > 1e9) {
        return BadUri(uri, "seed must be a whole number >= 0");
      }
      out.seed = static_cast<int>(number);
    } else {
      if (!(number > 0 && number <= 100)) return BadUri(uri, "fps must lie in (0, 100]");
      out.fps = number;
    }
  }
  return out;
}

SimPanelSource::SimPanelSource(std::string uri, SimPanelUri parsed)
    : LiveSource(SimLiveOptions()), uri_(std::move(uri)), parsed_(parsed) {}

SimPanelSource::~SimPanelSource() { Close(); }

std::string SimPanelSource::DeviceLabel() const { return "simulated camera '" + uri_ + "'"; }

Status SimPanelSource::Connect(SourceInfo* info) {
  sim::SimulationOptions options = sim::SimulationOptions::ForScene("panel");
  options.seed = parsed_.seed;
  options.frames = 1;
  StatusOr<sim::Simulator> simulator = sim::Simulator::Create(options);
  if (!simulator.ok()) return simulator.status().WithContext(uri_);
  StatusOr<ArmSimWorld> world = BuildArmSimWorld(parsed_.seed);
  if (!world.ok()) return world.status().WithContext(uri_);
  const PinholeCamera camera = simulator->mono_camera();
  simulator_.emplace(std::move(*simulator));
  world_.emplace(std::move(*world));
  *info = SourceInfo();
  info->format = "simulated panel camera";
  info->path = uri_;
  info->kind = SourceKind::kMono;
  info->width = camera.width;
  info->height = camera.height;
  info->rate_hz = parsed_.fps;
  info->live = true;
  info->camera = camera;
  info->notes.push_back("the panel scene of seed " + std::to_string(parsed_.seed) +
                        " rendered live from the arm's pose (PoseBoard '" + kChannel +
                        "', e.g. sightline-cli arm-sim); the plan's start pose before any");
  PoseBoard::Global().Clear(kChannel);  // A pose of an earlier arm is not this one's.
  due_ = Clock::now();
  rendered_ = 0;
  last_count_ = -1;
  last_stamp_s_ = 0;
  return Status::Ok();
}

StatusOr<std::optional<CapturedFrame>> SimPanelSource::ReadFrame(
    std::chrono::milliseconds timeout) {
  if (!simulator_ || !world_) return Unavailable(DeviceLabel() + " is not open");
  const Clock::time_point now = Clock::now();
  if (due_ - now > timeout) {
    std::this_thread::sleep_for(timeout);
    return std::optional<CapturedFrame>();
  }
  if (due_ > now) std::this_thread::sleep_until(due_);
  const auto period =
      std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(1.0 / parsed_.fps));
  due_ = std::max(due_ + period, Clock::now());  // A slow render is not made up in a burst.
  Eigen::Isometry3d base_from_ee = world_->PlanPose(0);
  double stamp = WallClockS();
  if (std::optional<BoardPose> latest = PoseBoard::Global().Latest(kChannel)) {
    base_from_ee = latest->pose;
    if (latest->count != last_count_) stamp = latest->stamp_s;  // Else the arm holds still.
    last_count_ = latest->count;
  }
  if (stamp <= last_stamp_s_) stamp = last_stamp_s_ + 1e-6;
  last_stamp_s_ = stamp;
  sim::SimulatedMono mono;
  SIGHTLINE_RETURN_IF_ERROR(simulator_->RenderMonoAt(
      world_->world_from_base * base_from_ee * world_->end_effector_from_camera,
      rendered_ / parsed_.fps, rendered_, &mono));
  ++rendered_;
  MonoFrame frame;
  frame.stamp.sensor_time_s = stamp;
  frame.image = mono.image;
  CapturedFrame captured;
  captured.frame = std::move(frame);
  captured.device_frame_id = rendered_ - 1;
  return std::optional<CapturedFrame>(std::move(captured));
}

void SimPanelSource::Disconnect(bool) {
  simulator_.reset();
  world_.reset();
}

StatusOr<std::unique_ptr<Source>> OpenRunSource(const std::string& uri, const OptionSet& options) {
  if (!IsSimUri(uri)) return OpenSource(uri, options);
  StatusOr<SimPanelUri> parsed = ParseSimPanelUri(uri);
  if (!parsed.ok()) return parsed.status();
  auto source = std::make_unique<SimPanelSource>(uri, *parsed);
  SIGHTLINE_RETURN_IF_ERROR(source->Open());
  return std::unique_ptr<Source>(std::move(source));
}

bool IsLiveUri(const std::string& uri) { return IsSensorUri(uri) || IsSimUri(uri); }

StatusOr<std::string> SimTapPixel(const std::string& uri, int button) {
  StatusOr<SimPanelUri> parsed = ParseSimPanelUri(uri);
  if (!parsed.ok()) return parsed.status();
  StatusOr<ArmSimWorld> world = BuildArmSimWorld(parsed->seed);
  if (!world.ok()) return world.status();
  const ArmSimButton* b = world->FindButton(button);
  if (b == nullptr) {
    return InvalidArgument("button.run.tap = button:" + std::to_string(button) + ": " + uri +
                           " has buttons 0.." + std::to_string(world->buttons.size() - 1));
  }
  const PinholeCamera camera = sim::SimulationOptions::ForScene("panel").mono.Camera();
  const Eigen::Isometry3d base_from_camera = world->PlanPose(0) * world->end_effector_from_camera;
  const Eigen::Vector3d in_camera = base_from_camera.inverse() * b->center;
  const Eigen::Vector2d pixel = camera.Project(in_camera);
  if (!(in_camera.z() > 0) || pixel.x() < 0 || pixel.y() < 0 || pixel.x() > camera.width - 1 ||
      pixel.y() > camera.height - 1) {
    return InvalidArgument("button.run.tap = button:" + std::to_string(button) +
                           ": the button is not in view at the start pose of " + uri);
  }
  char text[64];
  std::snprintf(text, sizeof(text), "%.1f,%.1f@0", pixel.x(), pixel.y());
  return std::string(text);
}

namespace {

StatusOr<std::string> StringOption(const OptionSet& options, const std::string& key) {
  StatusOr<OptionValue> value = options.Get(key);
  if (!value.ok()) return value.status();
  const std::string* text = std::get_if<std::string>(&*value);
  if (text == nullptr) return InvalidArgument(key + " is not a text option");
  return *text;
}

Status WriteSimHandEye(const std::string& uri, const std::string& path) {
  StatusOr<SimPanelUri> parsed = ParseSimPanelUri(uri);
  if (!parsed.ok()) return parsed.status();
  StatusOr<ArmSimWorld> world = BuildArmSimWorld(parsed->seed);
  if (!world.ok()) return world.status();
  HandEye hand_eye;
  hand_eye.end_effector_from_camera = world->end_effector_from_camera;
  hand_eye.world_from_base = world->world_from_base;
  FileComments comments;
  comments.header.push_back("The true hand-eye of the simulated arm camera of " + uri + ".");
  return WriteHandEyeFile(hand_eye, path, comments);
}

}  // namespace

Status PrepareSimRun(const std::string& uri, const std::string& out_dir, OptionSet* options) {
  if (!IsSimUri(uri)) return Status::Ok();
  if (options->Has("button.run.tap")) {
    StatusOr<std::string> tap = StringOption(*options, "button.run.tap");
    if (!tap.ok()) return tap.status();
    if (tap->rfind("button:", 0) == 0) {
      char* end = nullptr;
      const long id = std::strtol(tap->c_str() + 7, &end, 10);
      if (tap->size() == 7 || *end != '\0') {
        return InvalidArgument("button.run.tap = '" + *tap + "': expected button:K (an id)");
      }
      StatusOr<std::string> pixel = SimTapPixel(uri, static_cast<int>(id));
      if (!pixel.ok()) return pixel.status();
      SIGHTLINE_RETURN_IF_ERROR(options->Set("button.run.tap", *pixel, "sim button " + *tap));
    }
  }
  if (options->Has("mono.run.hand_eye")) {
    StatusOr<std::string> hand_eye = StringOption(*options, "mono.run.hand_eye");
    if (!hand_eye.ok()) return hand_eye.status();
    if (hand_eye->empty()) {
      std::error_code ec;
      std::filesystem::create_directories(out_dir, ec);
      const std::string path = (std::filesystem::path(out_dir) / "sim_hand_eye.yaml").string();
      SIGHTLINE_RETURN_IF_ERROR(WriteSimHandEye(uri, path));
      SIGHTLINE_RETURN_IF_ERROR(options->Set("mono.run.hand_eye", path, "sim:// hand-eye"));
    }
  }
  return Status::Ok();
}

}  // namespace sightline
