// textured_fake_stereo_camera: a left and a right GigE Vision camera (Aravis' ArvGvFakeCamera,
// the simulator behind arv-fake-gv-camera-0.8) served from one process, streaming Mono8 stereo
// pairs of Sightline's simulated corridor (core/sim) instead of Aravis' diagonal ramp, so that
// live stereo odometry over aravis://LEFT,RIGHT has texture to track and ground truth to meet.
//
//   textured_fake_stereo_camera --left-address 127.0.0.1 --right-address 127.0.0.2 \
//       --left-serial VOL --right-serial VOR --motion robot --log /tmp/served
//
// Frames: both fake cameras run at the same frame period, and Aravis starts each frame on a
// multiple of that period, so a left and a right frame of one instant carry timestamps a few
// milliseconds apart at most (what the stereo source pairs by, sensors.aravis.stereo.*). Each
// buffer shows the scene at (tick - first tick) x period, the tick being the frame-grid instant
// its timestamp (taken late, when the camera's thread wakes) belongs to, so both images of a
// pair show the same instant. A moving rig stops at the
// motion's last frame; a static rig repeats its frames (same pose, fresh image noise). When no
// camera has streamed for a second (a client closed the cameras) the motion restarts at frame 0
// with the next frame served.
//
// --log DIR writes, line by line as frames are served:
//   DIR/served.csv              side,timestamp_ns,frame (side: left or right)
//   DIR/served_groundtruth.txt  TUM "t tx ty tz qx qy qz qw": the true pose of the left camera
//                               (map frame) at the timestamp of every left frame served.
//
// --calibration FILE writes the served rig as an OpenCV stereo YAML
// (aravis://L,R?calibration_file=).
//
// Runs until SIGINT or SIGTERM. The images are rendered before the cameras start; the cameras
// are discoverable once "serving" is printed.
#include <arv.h>
#include <signal.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <map>
#include <mutex>
#include <opencv2/core.hpp>
#include <string>
#include <vector>

#include "core/sim/recording_writer.h"
#include "core/sim/sensor_options.h"
#include "core/sim/simulator.h"

namespace sightline {
namespace {

// The command line; defaults give the simulator's corridor stereo rig at Aravis' 25 Hz.
struct Settings {
  std::string left_address = "127.0.0.1";
  std::string right_address = "127.0.0.2";
  std::string left_serial = "TEXL";
  std::string right_serial = "TEXR";
  std::string motion = "robot";  // sim.motion.kind: robot (drives the corridor) or static.
  int frames = 125;              // Scene frames rendered (5 s at 25 Hz).
  double rate_hz = 25;           // Scene frames per second, also the cameras' frame rate.
  int width = 752, height = 480;
  double focal_px = 458;
  double baseline_m = 0.11;
  double speed_mps = 0.5;
  int seed = 3;
  std::string log_dir;      // "" = no logs.
  std::string calibration;  // "" = none; else the rig as an OpenCV stereo YAML.
};

const char kUsage[] =
    "usage: textured_fake_stereo_camera [--left-address IP] [--right-address IP]\n"
    "  [--left-serial S] [--right-serial S] [--motion robot|static] [--frames N] [--rate HZ]\n"
    "  [--width PX] [--height PX] [--focal PX] [--baseline M] [--speed MPS] [--seed N]\n"
    "  [--log DIR] [--calibration FILE]\n";

bool ParseArguments(int argc, char** argv, Settings* s, std::string* error) {
  const std::map<std::string, std::string*> texts = {{"left-address", &s->left_address},
                                                     {"right-address", &s->right_address},
                                                     {"left-serial", &s->left_serial},
                                                     {"right-serial", &s->right_serial},
                                                     {"motion", &s->motion},
                                                     {"log", &s->log_dir},
                                                     {"calibration", &s->calibration}};
  const std::map<std::string, int*> integers = {
      {"frames", &s->frames}, {"width", &s->width}, {"height", &s->height}, {"seed", &s->seed}};
  const std::map<std::string, double*> numbers = {{"rate", &s->rate_hz},
                                                  {"focal", &s->focal_px},
                                                  {"baseline", &s->baseline_m},
                                                  {"speed", &s->speed_mps}};
  for (int i = 1; i < argc; i += 2) {
    const std::string option = argv[i];
    if (option.rfind("--", 0) != 0 || i + 1 >= argc) {
      *error = "expected --option value, got '" + option + "'";
      return false;
    }
    const std::string key = option.substr(2), value = argv[i + 1];
    try {
      if (texts.count(key) != 0) {
        *texts.at(key) = value;
      } else if (integers.count(key) != 0) {
        *integers.at(key) = std::stoi(value);
      } else if (numbers.count(key) != 0) {
        *numbers.at(key) = std::stod(value);
      } else {
        *error = "unknown option " + option;
        return false;
      }
    } catch (const std::exception&) {
      *error = option + " expects a number, not '" + value + "'";
      return false;
    }
  }
  if (s->motion != "robot" && s->motion != "static") {
    *error = "--motion must be robot or static, not '" + s->motion + "'";
    return false;
  }
  if (s->frames < 1 || !(s->rate_hz > 0 && s->rate_hz <= 100)) {
    *error = "--frames must be >= 1 and --rate in (0, 100] Hz";
    return false;
  }
  if (s->left_serial == s->right_serial || s->left_address == s->right_address) {
    *error = "the two cameras need different serials and addresses";
    return false;
  }
  return true;
}

// One rendered instant of the scene.
struct SceneFrame {
  cv::Mat images[2];  // Left, right: CV_8UC1.
  Eigen::Isometry3d world_from_left = Eigen::Isometry3d::Identity();
};

// Everything the two cameras' fill callbacks share; they run on the cameras' own threads.
class StereoServer {
 public:
  // `repeat`: after the last frame start again at frame 0, else keep showing the last frame.
  StereoServer(std::vector<SceneFrame> frames, double rate_hz, bool repeat,
               const std::string& log_dir)
      : frames_(std::move(frames)), rate_hz_(rate_hz), repeat_(repeat) {
    if (!log_dir.empty()) {
      served_ = std::fopen((log_dir + "/served.csv").c_str(), "w");
      ground_truth_ = std::fopen((log_dir + "/served_groundtruth.txt").c_str(), "w");
      if (served_ != nullptr) {
        std::fputs("side,timestamp_ns,frame\n", served_);
        std::fflush(served_);
      }
      if (ground_truth_ != nullptr) {
        std::fputs("# timestamp tx ty tz qx qy qz qw (left camera, map frame)\n", ground_truth_);
        std::fflush(ground_truth_);
      }
    }
  }
  bool logs_open() const { return served_ != nullptr && ground_truth_ != nullptr; }

  // Writes the scene frame of the buffer's timestamp into the buffer (side 0 = left) of a camera
  // whose frame period is `period_us`.
  void Fill(int side, uint32_t period_us, ArvBuffer* buffer, ArvPixelFormat format) {
    if (buffer == nullptr) return;
    const uint64_t stamp_ns = arv_buffer_get_timestamp(buffer);
    const int64_t period_ns = static_cast<int64_t>(std::max<uint32_t>(period_us, 1)) * 1000;
    // Aravis starts frames on multiples of the period (of the clock the timestamps use) and
    // stamps each when its thread wakes: late, by as much as the machine's load delays it
    // (rounding to the nearest tick named two ticks for one instant once both cameras woke
    // about half a period late, on a loaded 2-core machine). The tick is the last one at or
    // before the stamp, allowing an eighth of a period early: one tick for a left and a right
    // frame of the same instant unless a camera wakes more than 7/8 of a period late.
    const int64_t tick = (static_cast<int64_t>(stamp_ns) + period_ns / 8) / period_ns;
    int frame = 0;
    {
      std::lock_guard<std::mutex> lock(mutex_);
      if (last_ns_ == 0 || stamp_ns > last_ns_ + kRestartGapNs) first_tick_ = tick;
      last_ns_ = std::max(last_ns_, stamp_ns);
      const double scene_time_s = static_cast<double>(tick - first_tick_) * period_ns * 1e-9;
      const int64_t index = std::max<int64_t>(0, std::llround(scene_time_s * rate_hz_));
      const int64_t count = static_cast<int64_t>(frames_.size());
      frame = static_cast<int>(repeat_ ? index % count : std::min(index, count - 1));
      Log(side, stamp_ns, frame);
    }
    // arv_fake_camera_fill_buffer() calls this only when the buffer holds the region its
    // registers select (else the buffer is marked SIZE_MISMATCH), and the GigE camera sends
    // that many bytes, so width x height bytes are written here. (The buffer's data size reads
    // 0 at this point: it is what was received so far, not what was allocated.)
    auto* data = static_cast<uint8_t*>(const_cast<void*>(arv_buffer_get_data(buffer, nullptr)));
    gint x = 0, y = 0, w = 0, h = 0;
    arv_buffer_get_image_region(buffer, &x, &y, &w, &h);
    if (data == nullptr || w <= 0 || h <= 0) return;
    cv::Mat out(h, w, CV_8UC1, data);
    if (format != ARV_PIXEL_FORMAT_MONO_8) {
      out.setTo(0);  // Only Mono8 is rendered; other formats read black.
      return;
    }
    // The region of the rendered image the registers select (a real sensor crops the same way).
    const cv::Mat& image = frames_[frame].images[side];
    const cv::Rect inside = cv::Rect(x, y, w, h) & cv::Rect(0, 0, image.cols, image.rows);
    if (inside.size() != cv::Size(w, h)) out.setTo(0);
    if (inside.area() > 0) {
      image(inside).copyTo(out(cv::Rect(inside.x - x, inside.y - y, inside.width, inside.height)));
    }
  }

  ~StereoServer() {
    if (served_ != nullptr) std::fclose(served_);
    if (ground_truth_ != nullptr) std::fclose(ground_truth_);
  }

 private:
  static constexpr uint64_t kRestartGapNs = 1000000000ull;  // 1 s without any frame.

  // Called with mutex_ held; flushed per line, as the process usually ends by a signal.
  void Log(int side, uint64_t stamp_ns, int frame) {
    if (served_ != nullptr) {
      std::fprintf(served_, "%s,%llu,%d\n", side == 0 ? "left" : "right",
                   static_cast<unsigned long long>(stamp_ns), frame);
      std::fflush(served_);
    }
    if (side == 0 && ground_truth_ != nullptr) {
      const std::string line = sim::TumLine(static_cast<double>(stamp_ns) * 1e-9,
                                            frames_[frame].world_from_left);  // Ends in \n.
      std::fputs(line.c_str(), ground_truth_);
      std::fflush(ground_truth_);
    }
  }

  const std::vector<SceneFrame> frames_;
  const double rate_hz_;
  const bool repeat_;
  std::mutex mutex_;
  int64_t first_tick_ = 0;
  uint64_t last_ns_ = 0;
  std::FILE* served_ = nullptr;
  std::FILE* ground_truth_ = nullptr;
};

// The callback's data: which camera, and the shared server.
struct CameraSide {
  StereoServer* server = nullptr;
  int side = 0;
  ArvFakeCamera* camera = nullptr;
};

void FillPattern(ArvBuffer* buffer, void* data, guint32 /*exposure_time_us*/, guint32 /*gain*/,
                 ArvPixelFormat pixel_format) {
  const auto* side = static_cast<const CameraSide*>(data);
  guint32 period_us = 0;
  arv_fake_camera_read_register(side->camera, ARV_FAKE_CAMERA_REGISTER_ACQUISITION_FRAME_PERIOD_US,
                                &period_us);
  side->server->Fill(side->side, period_us, buffer, pixel_format);
}

StatusOr<std::vector<SceneFrame>> RenderFrames(const Settings& s) {
  sim::SimulationOptions options = sim::SimulationOptions::ForScene("corridor");
  options.seed = s.seed;
  options.frames = s.frames;
  options.rate_hz = s.rate_hz;
  options.sensors = "stereo";
  options.corridor.people = 0;  // A rigid world: the served motion is the only motion.
  options.stereo.width = s.width;
  options.stereo.height = s.height;
  options.stereo.focal_px = s.focal_px;
  options.stereo.baseline_m = s.baseline_m;
  options.motion.kind = s.motion;
  options.motion.speed_mps = s.speed_mps;
  StatusOr<sim::Simulator> simulator = sim::Simulator::Create(options);
  if (!simulator.ok()) return simulator.status();
  std::vector<SceneFrame> frames(static_cast<size_t>(s.frames));
  sim::SimulatedStereo stereo;
  for (int i = 0; i < s.frames; ++i) {
    SIGHTLINE_RETURN_IF_ERROR(simulator->RenderStereo(i, &stereo));
    frames[i].images[0] = stereo.left.clone();
    frames[i].images[1] = stereo.right.clone();
    frames[i].world_from_left = stereo.world_from_left;
  }
  return frames;
}

// Writes the served rig as the OpenCV stereo YAML `sightline-cli calibrate stereo` writes (the
// part the stereo sources read: image size, M1 D1 M2 D2 R T), for live runs by hand.
bool WriteCalibration(const StereoRig& rig, const std::string& path) {
  cv::FileStorage fs(path, cv::FileStorage::WRITE);
  if (!fs.isOpened()) return false;
  auto k = [](const PinholeCamera& c) -> cv::Mat {
    return (cv::Mat_<double>(3, 3) << c.fx, 0, c.cx, 0, c.fy, c.cy, 0, 0, 1);
  };
  const Eigen::Vector3d t = rig.right_from_left.translation();
  fs << "image_width" << rig.left.width << "image_height" << rig.left.height;
  fs << "M1" << k(rig.left) << "D1" << cv::Mat::zeros(1, 5, CV_64F);
  fs << "M2" << k(rig.right) << "D2" << cv::Mat::zeros(1, 5, CV_64F);
  fs << "R" << cv::Mat::eye(3, 3, CV_64F) << "T" << (cv::Mat_<double>(3, 1) << t.x(), t.y(), t.z());
  return true;
}

// Sizes the camera's image registers to the rendered frames and its frame period to the rate.
void ConfigureRegisters(ArvFakeCamera* camera, const Settings& s) {
  arv_fake_camera_write_register(camera, ARV_FAKE_CAMERA_REGISTER_WIDTH, s.width);
  arv_fake_camera_write_register(camera, ARV_FAKE_CAMERA_REGISTER_HEIGHT, s.height);
  arv_fake_camera_write_register(camera, ARV_FAKE_CAMERA_REGISTER_X_OFFSET, 0);
  arv_fake_camera_write_register(camera, ARV_FAKE_CAMERA_REGISTER_Y_OFFSET, 0);
  arv_fake_camera_write_register(camera, ARV_FAKE_CAMERA_REGISTER_PIXEL_FORMAT,
                                 ARV_PIXEL_FORMAT_MONO_8);
  arv_fake_camera_write_register(camera, ARV_FAKE_CAMERA_REGISTER_ACQUISITION_FRAME_PERIOD_US,
                                 static_cast<guint32>(std::lround(1e6 / s.rate_hz)));
}

volatile sig_atomic_t g_stop = 0;

void OnSignal(int) { g_stop = 1; }

int Main(int argc, char** argv) {
  Settings settings;
  std::string error;
  if (!ParseArguments(argc, argv, &settings, &error)) {
    std::cerr << "textured_fake_stereo_camera: " << error << "\n" << kUsage;
    return 2;
  }
  if (!settings.log_dir.empty()) {
    std::error_code ec;
    std::filesystem::create_directories(settings.log_dir, ec);
  }
  if (!settings.calibration.empty()) {
    sim::StereoSensorOptions rig;
    rig.width = settings.width;
    rig.height = settings.height;
    rig.focal_px = settings.focal_px;
    rig.baseline_m = settings.baseline_m;
    if (!WriteCalibration(rig.Rig(), settings.calibration)) {
      std::cerr << "textured_fake_stereo_camera: cannot write " << settings.calibration << "\n";
      return 1;
    }
  }
  const auto start = std::chrono::steady_clock::now();
  StatusOr<std::vector<SceneFrame>> frames = RenderFrames(settings);
  if (!frames.ok()) {
    std::cerr << "textured_fake_stereo_camera: " << frames.status().ToString() << "\n";
    return 1;
  }
  const double render_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  StereoServer server(std::move(*frames), settings.rate_hz, settings.motion == "static",
                      settings.log_dir);
  if (!settings.log_dir.empty() && !server.logs_open()) {
    std::cerr << "textured_fake_stereo_camera: cannot write the logs in " << settings.log_dir
              << "\n";
    return 1;
  }

  CameraSide sides[2];
  const std::string addresses[2] = {settings.left_address, settings.right_address};
  const std::string serials[2] = {settings.left_serial, settings.right_serial};
  ArvGvFakeCamera* cameras[2] = {nullptr, nullptr};
  for (int i = 0; i < 2; ++i) {
    cameras[i] = arv_gv_fake_camera_new(addresses[i].c_str(), serials[i].c_str());
    if (cameras[i] == nullptr || !arv_gv_fake_camera_is_running(cameras[i])) {
      std::cerr << "textured_fake_stereo_camera: cannot serve camera " << serials[i] << " on "
                << addresses[i] << "\n";
      return 1;
    }
    ArvFakeCamera* fake = arv_gv_fake_camera_get_fake_camera(cameras[i]);
    ConfigureRegisters(fake, settings);
    sides[i] = {&server, i, fake};
    arv_fake_camera_set_fill_pattern(fake, FillPattern, &sides[i]);
  }
  std::printf(
      "serving %s (%s) and %s (%s): %d %s frames of %dx%d Mono8 at %g Hz "
      "(rendered in %.1f s)\n",
      serials[0].c_str(), addresses[0].c_str(), serials[1].c_str(), addresses[1].c_str(),
      settings.frames, settings.motion.c_str(), settings.width, settings.height, settings.rate_hz,
      render_s);
  std::fflush(stdout);

  signal(SIGINT, OnSignal);
  signal(SIGTERM, OnSignal);
  while (!g_stop) pause();
  for (ArvGvFakeCamera* camera : cameras) g_object_unref(camera);
  return 0;
}

}  // namespace
}  // namespace sightline

int main(int argc, char** argv) { return sightline::Main(argc, argv); }
