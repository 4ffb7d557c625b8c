#include "core/sensors/openni2_source.h"

#include <OpenNI.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <mutex>
#include <opencv2/imgproc.hpp>
#include <utility>

#include "core/common/timing.h"
#include "core/sensors/depth_conversion.h"
#include "core/sensors/driver_registry.h"
#include "core/sensors/openni2_runtime.h"
#include "core/sensors/openni2_streams.h"
#include "core/sensors/timestamp_pairer.h"

namespace sightline {
namespace {

// Pairing key offset per playback loop, larger than any recording's duration [s].
constexpr double kLoopKeyOffsetS = 1e7;
// How long a file that delivered no frame waits for its player thread before closing [ms].
constexpr int kPlayerStartTimeoutMs = 2000;

// One converted stream image waiting for its partner.
struct StreamImage {
  cv::Mat image;      // Depth: CV_32FC1 metres. Colour: CV_8UC3 BGR.
  double time_s = 0;  // Device timestamp.
};

// What the started streams give: the output's frame rate and the field of view.
struct StreamGeometry {
  int fps = 0;                // Of the main stream (colour when active).
  double hfov = 0, vfov = 0;  // [rad]; not positive when unknown.
};

}  // namespace

struct OpenNi2Source::Impl {
  std::shared_ptr<OpenNi2Runtime> runtime;
  // Guards device, streams and recorder between the capture thread and StartRecording().
  mutable std::mutex mutex;
  openni::Device device;
  openni::VideoStream streams[2];
  bool active[2] = {false, false};
  bool device_open = false;
  std::string device_uri;
  std::string claimed_uri;  // Live devices: the runtime claim held while connected.
  double depth_units_per_m = 1000;
  cv::Size color_size;
  int frame_count = 0;     // Recordings: pairs in the file.
  int64_t next_index = 0;  // Recordings: index of the next pair delivered.
  int last_frame_index[2] = {-1, -1};
  int64_t loops[2] = {0, 0};
  std::unique_ptr<TimestampPairer<StreamImage>> pairer;
  uint64_t unpaired_reported = 0;
  std::unique_ptr<OpenNi2DeviceWatcher> watcher;
  std::unique_ptr<openni::Recorder> recorder;

  // Forgets the previous connection's state (with `mutex` held).
  void ResetState() {
    active[0] = active[1] = false;
    device_open = false;
    device_uri.clear();
    depth_units_per_m = 1000;
    frame_count = 0;
    next_index = 0;
    last_frame_index[0] = last_frame_index[1] = -1;
    loops[0] = loops[1] = 0;
    pairer.reset();
    unpaired_reported = 0;
    watcher.reset();
  }

  // Converts a frame of stream s (kDepth, kColor); false when a colour frame cannot be
  // converted (incomplete).
  bool Convert(int s, const openni::VideoFrameRef& frame, StreamImage* image) const;
  // The pairing key of a frame of stream s at time_s: recordings restart their timestamps when
  // they loop, so the loops are counted to keep the keys increasing.
  double PairingKey(int s, const openni::VideoFrameRef& frame, double time_s);

  // The steps of Connect() (with `mutex` held), in order.
  // Opens `target` (claiming a live device from the runtime) and notes what it is.
  Status OpenDevice(const std::string& target, bool is_file, const std::string& who,
                    std::vector<std::string>* notes);
  // Creates the wanted streams the device has; both before either starts (recordings play only
  // that way).
  Status CreateStreams(const OpenNi2Options& options, const std::string& who,
                       std::vector<std::string>* notes);
  // Video modes: the requested one, or the device's when no size/rate is given; a recording's
  // formats are checked.
  Status SelectVideoModes(const OpenNi2Options& options, bool is_file, const std::string& who,
                          std::vector<std::string>* notes);
  // Registration, synchronisation and mirroring.
  Status SetStreamOptions(const OpenNi2Options& options, bool is_file, const std::string& who,
                          std::vector<std::string>* notes);
  Status StartStreams(const std::string& who);
  // Depth units, the output size and the field of view of the started streams.
  StreamGeometry ReadGeometry(std::vector<std::string>* notes);
  // Fills *info: kind, size, rate, a recording's frame count and the intrinsics.
  void DescribeSource(const OpenNi2Options& options, bool is_file, const std::string& uri,
                      const StreamGeometry& geometry, openni::PlaybackControl* playback,
                      SourceInfo* info, std::vector<std::string>* notes);
};

OpenNi2Source::OpenNi2Source(std::string uri, OpenNi2Options options)
    : LiveSource(options.live),
      uri_(std::move(uri)),
      options_(std::move(options)),
      is_file_(IsRecordingPath(uri_)),
      impl_(std::make_unique<Impl>()) {}

OpenNi2Source::~OpenNi2Source() { Close(); }

bool OpenNi2Source::IsRecordingPath(const std::string& uri) {
  if (uri.size() < 4) return false;
  std::string ext = uri.substr(uri.size() - 4);
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return std::tolower(c); });
  return ext == ".oni";
}

Status OpenNi2Source::Available() {
  StatusOr<std::shared_ptr<OpenNi2Runtime>> runtime = OpenNi2Runtime::Acquire();
  return runtime.ok() ? Status::Ok() : runtime.status();
}

std::vector<DeviceInfo> OpenNi2Source::Enumerate() {
  std::vector<DeviceInfo> devices;
  StatusOr<std::shared_ptr<OpenNi2Runtime>> runtime = OpenNi2Runtime::Acquire();
  if (!runtime.ok()) return devices;
  openni::Array<openni::DeviceInfo> list;
  openni::OpenNI::enumerateDevices(&list);
  for (int i = 0; i < list.getSize(); ++i) {
    DeviceInfo d;
    d.driver = "openni2";
    d.uri = std::string("openni2://") + list[i].getUri();
    d.name = std::string(list[i].getVendor()) + " " + list[i].getName();
    char usb[32];
    std::snprintf(usb, sizeof(usb), "USB %04x:%04x", list[i].getUsbVendorId(),
                  list[i].getUsbProductId());
    d.details = usb;
    devices.push_back(std::move(d));
  }
  return devices;
}

std::string OpenNi2Source::DeviceLabel() const {
  if (is_file_) return "OpenNI2 recording '" + uri_ + "'";
  return "OpenNI2 device '" + (uri_.empty() ? std::string("(first device)") : uri_) + "'";
}

Status OpenNi2Source::Connect(SourceInfo* info) {
  std::string error;
  if (!options_.IsValid(&error)) return InvalidArgument(error);
  if (is_file_) SIGHTLINE_RETURN_IF_ERROR(CheckOniFile(uri_).WithContext(DeviceLabel()));
  Impl& m = *impl_;
  std::lock_guard<std::mutex> lock(m.mutex);
  m.ResetState();
  if (!m.runtime) {
    StatusOr<std::shared_ptr<OpenNi2Runtime>> runtime = OpenNi2Runtime::Acquire();
    if (!runtime.ok()) return runtime.status().WithContext(DeviceLabel());
    m.runtime = *runtime;
  }
  const std::string who = DeviceLabel();

  std::string target = uri_;
  if (!is_file_ && target.empty()) {
    openni::Array<openni::DeviceInfo> list;
    openni::OpenNI::enumerateDevices(&list);
    if (list.getSize() == 0) return Unavailable("no OpenNI2 device is attached");
    target = list[0].getUri();
  }
  std::vector<std::string> notes;
  SIGHTLINE_RETURN_IF_ERROR(m.OpenDevice(target, is_file_, who, &notes));

  openni::PlaybackControl* playback = is_file_ ? m.device.getPlaybackControl() : nullptr;
  if (playback != nullptr) {
    playback->setSpeed(options_.playback_speed > 0 ? static_cast<float>(options_.playback_speed)
                                                   : -1.0f);
    // Repeat stays on even without `loop`: at the end of a file without repeat, Debian's OniFile
    // driver (2.2.0.33) keeps its player thread spinning over its stream list, and closing the
    // file then crashes about one time in ten. The end is detected here, from the frame count.
    playback->setRepeatEnabled(true);
  }

  SIGHTLINE_RETURN_IF_ERROR(m.CreateStreams(options_, who, &notes));
  SIGHTLINE_RETURN_IF_ERROR(m.SelectVideoModes(options_, is_file_, who, &notes));
  SIGHTLINE_RETURN_IF_ERROR(m.SetStreamOptions(options_, is_file_, who, &notes));
  SIGHTLINE_RETURN_IF_ERROR(m.StartStreams(who));
  const StreamGeometry geometry = m.ReadGeometry(&notes);
  m.DescribeSource(options_, is_file_, uri_, geometry, playback, info, &notes);
  info->notes = std::move(notes);

  m.pairer = std::make_unique<TimestampPairer<StreamImage>>(options_.pair_tolerance_ms * 1e-3);
  if (!is_file_) {
    m.watcher = std::make_unique<OpenNi2DeviceWatcher>(m.device_uri);
    openni::OpenNI::addDeviceDisconnectedListener(m.watcher.get());
    openni::OpenNI::addDeviceStateChangedListener(m.watcher.get());
  }
  return Status::Ok();
}

Status OpenNi2Source::Impl::OpenDevice(const std::string& target, bool is_file,
                                       const std::string& who, std::vector<std::string>* notes) {
  if (!is_file) {
    SIGHTLINE_RETURN_IF_ERROR(runtime->ClaimDevice(target));
    claimed_uri = target;
  }
  if (device.open(target.c_str()) != openni::STATUS_OK) {
    return Unavailable(who + " could not be opened: " + openni::OpenNI::getExtendedError());
  }
  device_open = true;
  device_uri = device.getDeviceInfo().getUri();
  notes->push_back(std::string(device.getDeviceInfo().getVendor()) + " " +
                   device.getDeviceInfo().getName() + ", URI " + device_uri);
  return Status::Ok();
}

Status OpenNi2Source::Impl::CreateStreams(const OpenNi2Options& options, const std::string& who,
                                          std::vector<std::string>* notes) {
  const bool wanted[2] = {options.depth, options.color};
  const openni::SensorType types[2] = {openni::SENSOR_DEPTH, openni::SENSOR_COLOR};
  for (int s = 0; s < 2; ++s) {
    if (!wanted[s]) continue;
    if (!device.hasSensor(types[s])) {
      notes->push_back(std::string("no ") + StreamName(s) + " stream");
      continue;
    }
    if (streams[s].create(device, types[s]) != openni::STATUS_OK) {
      return Unavailable(who + ": cannot create the " + StreamName(s) +
                         " stream: " + openni::OpenNI::getExtendedError());
    }
    active[s] = true;
  }
  if (!active[kDepth] && !active[kColor]) {
    return Unavailable(who + " offers none of the requested streams");
  }
  return Status::Ok();
}

Status OpenNi2Source::Impl::SelectVideoModes(const OpenNi2Options& options, bool is_file,
                                             const std::string& who,
                                             std::vector<std::string>* notes) {
  for (int s = 0; s < 2; ++s) {
    if (!active[s]) continue;
    if (is_file) {
      const openni::VideoMode mode = streams[s].getVideoMode();
      if (!StreamFormatSupported(s, mode.getPixelFormat())) {
        return InvalidArgument(who + ": the recorded " + StreamName(s) + " format " +
                               VideoModeText(mode) + " is not supported");
      }
      continue;
    }
    SIGHTLINE_RETURN_IF_ERROR(
        SelectVideoMode(&streams[s], s, options.width, options.height, options.fps, who));
  }
  if (is_file && (options.width > 0 || options.fps > 0)) {
    notes->push_back("size and rate options do not apply to recordings");
  }
  return Status::Ok();
}

Status OpenNi2Source::Impl::SetStreamOptions(const OpenNi2Options& options, bool is_file,
                                             const std::string& who,
                                             std::vector<std::string>* notes) {
  const bool both = active[kDepth] && active[kColor];
  if (both && options.registration) {
    if (device.isImageRegistrationModeSupported(openni::IMAGE_REGISTRATION_DEPTH_TO_COLOR) &&
        device.setImageRegistrationMode(openni::IMAGE_REGISTRATION_DEPTH_TO_COLOR) ==
            openni::STATUS_OK) {
      notes->push_back("depth registered to colour by the device");
    } else {
      notes->push_back("depth not registered to colour (not supported by the " +
                       std::string(is_file ? "recording" : "device") + ")");
    }
  }
  if (both && options.sync) {
    if (device.setDepthColorSyncEnabled(true) != openni::STATUS_OK) {
      notes->push_back("depth/colour frame sync not supported; pairing by timestamp only");
    }
  }
  for (int s = 0; s < 2 && !is_file; ++s) {
    if (!active[s]) continue;
    if (streams[s].setMirroringEnabled(options.mirror) != openni::STATUS_OK && options.mirror) {
      return InvalidArgument(who + ": the " + std::string(StreamName(s)) +
                             " stream cannot be mirrored");
    }
  }
  return Status::Ok();
}

Status OpenNi2Source::Impl::StartStreams(const std::string& who) {
  for (int s = 0; s < 2; ++s) {
    if (active[s] && streams[s].start() != openni::STATUS_OK) {
      return Unavailable(who + ": cannot start the " + StreamName(s) +
                         " stream: " + openni::OpenNI::getExtendedError());
    }
  }
  return Status::Ok();
}

StreamGeometry OpenNi2Source::Impl::ReadGeometry(std::vector<std::string>* notes) {
  const bool both = active[kDepth] && active[kColor];
  openni::VideoMode depth_mode, color_mode;
  if (active[kDepth]) {
    depth_mode = streams[kDepth].getVideoMode();
    depth_units_per_m = DepthUnitsPerMetre(depth_mode.getPixelFormat());
    notes->push_back("depth " + VideoModeText(depth_mode));
  }
  if (active[kColor]) {
    color_mode = streams[kColor].getVideoMode();
    notes->push_back("colour " + VideoModeText(color_mode));
  }
  const int main = active[kColor] ? kColor : kDepth;
  const openni::VideoMode& main_mode = main == kColor ? color_mode : depth_mode;
  color_size = cv::Size(main_mode.getResolutionX(), main_mode.getResolutionY());
  if (both && (depth_mode.getResolutionX() != color_mode.getResolutionX() ||
               depth_mode.getResolutionY() != color_mode.getResolutionY())) {
    notes->push_back("depth resized to the colour size (nearest neighbour)");
  }
  StreamGeometry geometry;
  geometry.fps = main_mode.getFps();
  geometry.hfov = streams[main].getHorizontalFieldOfView();
  geometry.vfov = streams[main].getVerticalFieldOfView();
  if (!(geometry.hfov > 0 && geometry.vfov > 0) && both) {
    const int other = 1 - main;
    geometry.hfov = streams[other].getHorizontalFieldOfView();
    geometry.vfov = streams[other].getVerticalFieldOfView();
    if (geometry.hfov > 0 && geometry.vfov > 0) {
      notes->push_back(std::string("intrinsics from the ") + StreamName(other) +
                       " stream's field of view (the " + StreamName(main) + " stream has none)");
    }
  }
  return geometry;
}

void OpenNi2Source::Impl::DescribeSource(const OpenNi2Options& options, bool is_file,
                                         const std::string& uri, const StreamGeometry& geometry,
                                         openni::PlaybackControl* playback, SourceInfo* info,
                                         std::vector<std::string>* notes) {
  info->format = is_file ? "OpenNI2 recording (.oni)" : "OpenNI2 device";
  info->path = is_file ? uri : "openni2://" + device_uri;
  info->kind = SourceKind::kRgbd;
  info->width = color_size.width;
  info->height = color_size.height;
  info->rate_hz = geometry.fps;
  info->live = !is_file;
  info->seekable = is_file;
  info->frame_count = -1;
  if (playback != nullptr) {
    int count = -1;
    for (int s = 0; s < 2; ++s) {
      if (!active[s]) continue;
      const int n = playback->getNumberOfFrames(streams[s]);
      count = count < 0 ? n : std::min(count, n);
    }
    frame_count = std::max(count, 0);
    info->frame_count = frame_count;
    if (info->rate_hz > 0 && frame_count > 1) {
      info->duration_s = (frame_count - 1) / info->rate_hz;
    }
    if (options.loop) notes->push_back("loops at the end");
  }
  RgbdCalibration calibration;
  calibration.depth_scale = depth_units_per_m;
  calibration.max_depth_m = options.max_depth_m;
  if (geometry.hfov > 0 && geometry.vfov > 0) {
    calibration.color =
        PinholeFromFov(color_size.width, color_size.height, geometry.hfov, geometry.vfov);
    info->camera = calibration.color;
  } else {
    notes->push_back("no field of view reported: intrinsics unknown");
  }
  info->rgbd = calibration;
}

StatusOr<std::optional<CapturedFrame>> OpenNi2Source::ReadFrame(std::chrono::milliseconds timeout) {
  using Clock = std::chrono::steady_clock;
  Impl& m = *impl_;
  std::lock_guard<std::mutex> lock(m.mutex);
  if (!m.device_open) return FailedPrecondition(DeviceLabel() + " is not open");
  if (m.watcher) {
    const std::string gone = m.watcher->Gone();
    if (!gone.empty()) return Unavailable(DeviceLabel() + ": " + gone);
  }
  if (is_file_ && !options_.loop && m.next_index >= m.frame_count) {
    return OutOfRange("end of " + DeviceLabel() + " after " + std::to_string(m.frame_count) +
                      " frames");
  }
  openni::VideoStream* list[2];
  int index_of[2];
  int n = 0;
  for (int s = 0; s < 2; ++s) {
    if (!m.active[s]) continue;
    index_of[n] = s;
    list[n++] = &m.streams[s];
  }
  const Clock::time_point deadline = Clock::now() + timeout;
  while (true) {
    const int remaining_ms = static_cast<int>(std::max<int64_t>(
        0, std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now()).count()));
    int ready = -1;
    const openni::Status waited = openni::OpenNI::waitForAnyStream(list, n, &ready, remaining_ms);
    if (waited == openni::STATUS_TIME_OUT) return std::optional<CapturedFrame>();
    if (waited != openni::STATUS_OK || ready < 0 || ready >= n) {
      return Unavailable(DeviceLabel() +
                         ": waiting for frames failed: " + openni::OpenNI::getExtendedError());
    }
    const int s = index_of[ready];
    openni::VideoFrameRef frame;
    if (m.streams[s].readFrame(&frame) != openni::STATUS_OK || !frame.isValid()) {
      return Unavailable(DeviceLabel() + ": reading a " + StreamName(s) +
                         " frame failed: " + openni::OpenNI::getExtendedError());
    }
    StreamImage image;
    if (!m.Convert(s, frame, &image)) {
      CountIncomplete();
      continue;
    }
    const double key = m.PairingKey(s, frame, image.time_s);

    std::optional<std::pair<StreamImage, StreamImage>> pair;
    if (m.active[kDepth] && m.active[kColor]) {
      pair = m.pairer->Add(s, key, std::move(image));
      if (m.pairer->unpaired() > m.unpaired_reported) {
        CountUnpaired(m.pairer->unpaired() - m.unpaired_reported);
        m.unpaired_reported = m.pairer->unpaired();
      }
    } else {
      pair.emplace();
      (s == kDepth ? pair->first : pair->second) = std::move(image);
    }
    if (pair) {
      CapturedFrame captured;
      RgbdFrame rgbd;
      rgbd.stamp.sensor_time_s = m.active[kColor] ? pair->second.time_s : pair->first.time_s;
      rgbd.depth_m = std::move(pair->first.image);
      rgbd.color = std::move(pair->second.image);
      if (is_file_) {
        rgbd.stamp.sequence_id = m.frame_count > 0 ? m.next_index % m.frame_count : m.next_index;
        ++m.next_index;
      }
      captured.device_frame_id = frame.getFrameIndex();
      captured.frame = std::move(rgbd);
      captured.arrival_host_time_s = HostTimeS();
      return std::optional<CapturedFrame>(std::move(captured));
    }
    if (Clock::now() >= deadline) return std::optional<CapturedFrame>();
  }
}

bool OpenNi2Source::Impl::Convert(int s, const openni::VideoFrameRef& frame,
                                  StreamImage* image) const {
  image->time_s = static_cast<double>(frame.getTimestamp()) * 1e-6;
  if (s == kDepth) {
    cv::Mat raw(frame.getHeight(), frame.getWidth(), CV_16UC1, const_cast<void*>(frame.getData()),
                static_cast<size_t>(frame.getStrideInBytes()));
    image->image = RawDepthToMetres(raw, depth_units_per_m);
    if (active[kColor] && image->image.size() != color_size) {
      cv::resize(image->image, image->image, color_size, 0, 0, cv::INTER_NEAREST);
    }
    return true;
  }
  image->image = ColorFrameToBgr(frame);
  return !image->image.empty();
}

double OpenNi2Source::Impl::PairingKey(int s, const openni::VideoFrameRef& frame, double time_s) {
  if (last_frame_index[s] >= 0 && frame.getFrameIndex() < last_frame_index[s]) ++loops[s];
  last_frame_index[s] = frame.getFrameIndex();
  return time_s + static_cast<double>(loops[s]) * kLoopKeyOffsetS;
}

// OniFile's player thread marks itself running only once it is scheduled. A file closed before
// that (a quick `info` under load) leaves the thread looping, OpenNI cancels it after 3 s, and the
// cancellation crashes the process. A delivered frame proves the thread runs, so a file that has
// delivered none waits (bounded) for its first one before its streams stop.
void OpenNi2Source::WaitForPlayerThread(Impl& m) {
  if (m.last_frame_index[0] >= 0 || m.last_frame_index[1] >= 0) return;
  openni::VideoStream* list[2];
  int n = 0;
  for (int s = 0; s < 2; ++s) {
    if (m.active[s]) list[n++] = &m.streams[s];
  }
  if (n == 0) return;
  int ready = -1;
  (void)openni::OpenNI::waitForAnyStream(list, n, &ready, kPlayerStartTimeoutMs);
}

void OpenNi2Source::Disconnect(bool /*device_lost*/) {
  Impl& m = *impl_;
  {
    std::lock_guard<std::mutex> lock(m.mutex);
    if (m.recorder) {
      m.recorder->stop();
      m.recorder->destroy();
      m.recorder.reset();
    }
    if (m.watcher) {
      openni::OpenNI::removeDeviceDisconnectedListener(m.watcher.get());
      openni::OpenNI::removeDeviceStateChangedListener(m.watcher.get());
    }
    if (is_file_ && m.device_open) WaitForPlayerThread(m);
    for (int s = 0; s < 2; ++s) {
      if (m.active[s]) m.streams[s].stop();
    }
    for (int s = 0; s < 2; ++s) m.streams[s].destroy();
    if (m.device_open) m.device.close();
    if (!m.claimed_uri.empty() && m.runtime) m.runtime->ReleaseDevice(m.claimed_uri);
    m.claimed_uri.clear();
    m.ResetState();
  }
}

void OpenNi2Source::Close() {
  LiveSource::Close();  // Stops the capture thread and disconnects.
  std::shared_ptr<OpenNi2Runtime> runtime;
  {
    std::lock_guard<std::mutex> lock(impl_->mutex);
    runtime = std::move(impl_->runtime);
  }
  // Released outside the lock: the last handle shuts OpenNI2 down.
}

Status OpenNi2Source::Seek(int64_t index) {
  if (!is_file_) return FailedPrecondition(DeviceLabel() + " is a live device and cannot seek");
  if (!is_open()) return FailedPrecondition(DeviceLabel() + " is not open");
  int64_t count = 0;
  {
    std::lock_guard<std::mutex> lock(impl_->mutex);
    count = impl_->frame_count;
  }
  if (index < 0 || index > count) {
    return OutOfRange(DeviceLabel() + ": cannot seek to frame " + std::to_string(index) + " of " +
                      std::to_string(count));
  }
  Disconnect(false);
  SourceInfo scratch;
  Status reopened = Connect(&scratch);
  if (!reopened.ok()) return reopened.WithContext("seek");
  const auto timeout = std::chrono::milliseconds(live_options().grab_timeout_ms);
  for (int64_t i = 0; i < index; ++i) {
    StatusOr<std::optional<CapturedFrame>> skipped = ReadFrame(timeout);
    if (!skipped.ok()) return skipped.status().WithContext("seek");
    if (!skipped->has_value()) {
      return Unavailable(DeviceLabel() + ": no frame while skipping to frame " +
                         std::to_string(index));
    }
  }
  SetPosition(index);
  ForgetGrabbed();
  return Status::Ok();
}

Status OpenNi2Source::StartRecording(const std::string& oni_path) {
  if (is_file_) return FailedPrecondition(DeviceLabel() + " is a recording already");
  if (!is_open()) return FailedPrecondition(DeviceLabel() + " is not open");
  std::lock_guard<std::mutex> lock(impl_->mutex);
  Impl& m = *impl_;
  if (!m.device_open) return Unavailable(DeviceLabel() + " is disconnected; cannot record");
  if (m.recorder) return FailedPrecondition(DeviceLabel() + " is already recording");
  auto recorder = std::make_unique<openni::Recorder>();
  if (recorder->create(oni_path.c_str()) != openni::STATUS_OK) {
    return Unavailable("cannot create the .oni recording '" + oni_path +
                       "': " + openni::OpenNI::getExtendedError());
  }
  for (int s = 0; s < 2; ++s) {
    if (m.active[s] && recorder->attach(m.streams[s], false) != openni::STATUS_OK) {
      return Unavailable("cannot record the " + std::string(StreamName(s)) + " stream to '" +
                         oni_path + "': " + openni::OpenNI::getExtendedError());
    }
  }
  if (recorder->start() != openni::STATUS_OK) {
    return Unavailable("cannot start recording '" + oni_path +
                       "': " + openni::OpenNI::getExtendedError());
  }
  m.recorder = std::move(recorder);
  return Status::Ok();
}

void OpenNi2Source::StopRecording() {
  std::lock_guard<std::mutex> lock(impl_->mutex);
  if (!impl_->recorder) return;
  impl_->recorder->stop();
  impl_->recorder->destroy();
  impl_->recorder.reset();
}

bool OpenNi2Source::recording() const {
  std::lock_guard<std::mutex> lock(impl_->mutex);
  return impl_->recorder != nullptr;
}

}  // namespace sightline
