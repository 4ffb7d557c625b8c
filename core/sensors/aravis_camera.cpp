#include "core/sensors/aravis_camera.h"

#include <arv.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <sstream>

#include "core/common/timing.h"
#include "core/sensors/camera_pixels.h"

namespace sightline {
namespace {

// Takes the message out of a GError and frees it.
std::string TakeError(GError** error) {
  std::string message = (*error != nullptr && (*error)->message != nullptr)
                            ? (*error)->message
                            : "unknown Aravis error";
  g_clear_error(error);
  return message;
}

std::string Num(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

void OnControlLost(ArvDevice* /*device*/, gpointer flag) {
  static_cast<std::atomic<bool>*>(flag)->store(true);  // Called on Aravis' heartbeat thread.
}

// An Aravis string, "" for none.
std::string Text(const char* value) { return std::string(value != nullptr ? value : ""); }

// A setting the camera refused: `what` failed, with Aravis' reason (taken from *error).
Status Failed(const std::string& who, const std::string& what, GError** error) {
  return InvalidArgument(who + ": " + what + ": " + TakeError(error));
}

// Reads the device id, vendor, model and serial into *settings.
void ReadIdentity(ArvCamera* cam, AravisCameraSettings* settings) {
  GError* error = nullptr;
  settings->device_id = Text(arv_camera_get_device_id(cam, &error));
  g_clear_error(&error);
  settings->vendor = Text(arv_camera_get_vendor_name(cam, &error));
  g_clear_error(&error);
  settings->model = Text(arv_camera_get_model_name(cam, &error));
  g_clear_error(&error);
  settings->serial = Text(arv_camera_get_device_serial_number(cam, &error));
  g_clear_error(&error);
}

// Pixel format: only formats the camera lists, and only ones Sightline converts.
Status SelectPixelFormat(ArvCamera* cam, const std::string& who, const AravisOptions& o,
                         AravisCameraSettings* settings) {
  GError* error = nullptr;
  if (!o.pixel_format.empty()) {
    guint n = 0;
    const char** formats = arv_camera_dup_available_pixel_formats_as_strings(cam, &n, &error);
    if (error != nullptr) return Failed(who, "cannot list pixel formats", &error);
    std::string offered;
    bool found = false;
    for (guint i = 0; i < n; ++i) {
      if (formats[i] == nullptr) continue;
      offered += (offered.empty() ? "" : ", ") + std::string(formats[i]);
      found = found || o.pixel_format == formats[i];
    }
    g_free(formats);
    if (!found) {
      return InvalidArgument(who + " does not offer pixel format '" + o.pixel_format +
                             "' (it offers " + offered + ")");
    }
    arv_camera_set_pixel_format_from_string(cam, o.pixel_format.c_str(), &error);
    if (error != nullptr)
      return Failed(who, "cannot select pixel format " + o.pixel_format, &error);
  }
  const ArvPixelFormat format = arv_camera_get_pixel_format(cam, &error);
  if (error != nullptr) return Failed(who, "cannot read the pixel format", &error);
  settings->pixel_format = Text(arv_camera_get_pixel_format_as_string(cam, &error));
  g_clear_error(&error);
  if (PixelFormatName(format).rfind("0x", 0) == 0) {
    return InvalidArgument(who + " streams pixel format " + settings->pixel_format +
                           ", which Sightline cannot convert; choose one with "
                           "sensors.aravis.pixel_format (Mono8, Mono16, BayerRG8, RGB8, ...)");
  }
  return Status::Ok();
}

// Region of interest: the requested size from the origin, within the camera's bounds.
Status SetRegion(ArvCamera* cam, const std::string& who, const AravisOptions& o,
                 AravisCameraSettings* settings) {
  GError* error = nullptr;
  gint x = 0, y = 0, w = 0, h = 0;
  arv_camera_get_region(cam, &x, &y, &w, &h, &error);
  if (error != nullptr) return Failed(who, "cannot read the image region", &error);
  if (o.width > 0 || o.height > 0) {
    gint wmin = 0, wmax = 0, hmin = 0, hmax = 0;
    arv_camera_get_width_bounds(cam, &wmin, &wmax, &error);
    g_clear_error(&error);
    arv_camera_get_height_bounds(cam, &hmin, &hmax, &error);
    g_clear_error(&error);
    const int want_w = o.width > 0 ? o.width : w;
    const int want_h = o.height > 0 ? o.height : h;
    if (wmax > 0 && (want_w < wmin || want_w > wmax)) {
      return InvalidArgument(who + ": width " + std::to_string(want_w) +
                             " px outside the camera's range [" + std::to_string(wmin) + ", " +
                             std::to_string(wmax) + "]");
    }
    if (hmax > 0 && (want_h < hmin || want_h > hmax)) {
      return InvalidArgument(who + ": height " + std::to_string(want_h) +
                             " px outside the camera's range [" + std::to_string(hmin) + ", " +
                             std::to_string(hmax) + "]");
    }
    arv_camera_set_region(cam, 0, 0, want_w, want_h, &error);
    if (error != nullptr)
      return Failed(
          who, "cannot set the region to " + std::to_string(want_w) + "x" + std::to_string(want_h),
          &error);
    arv_camera_get_region(cam, &x, &y, &w, &h, &error);
    g_clear_error(&error);
  }
  settings->width = w;
  settings->height = h;
  return Status::Ok();
}

// A setting with bounds and the Aravis calls that reach it.
struct BoundedControl {
  const char* name;
  const char* unit;
  gboolean (*available)(ArvCamera*, GError**);
  void (*bounds)(ArvCamera*, double*, double*, GError**);
  void (*set)(ArvCamera*, double, GError**);
  double (*get)(ArvCamera*, GError**);
};

// Sets a bounded control: refuses out-of-range values instead of letting the camera clamp them;
// *applied gets the value read back.
Status SetBounded(ArvCamera* cam, const std::string& who, const BoundedControl& control,
                  double value, double* applied) {
  GError* error = nullptr;
  const char* name = control.name;
  const char* unit = control.unit;
  if (!control.available(cam, &error)) {
    g_clear_error(&error);
    return InvalidArgument(who + " has no " + name + " control");
  }
  double lo = 0, hi = 0;
  control.bounds(cam, &lo, &hi, &error);
  if (error != nullptr)
    return Failed(who, std::string("cannot read the ") + name + " range", &error);
  if (value < lo || value > hi) {
    return InvalidArgument(who + ": " + name + " " + Num(value) + " " + unit +
                           " outside the camera's range [" + Num(lo) + ", " + Num(hi) + "] " +
                           unit);
  }
  control.set(cam, value, &error);
  if (error != nullptr) return Failed(who, std::string("cannot set the ") + name, &error);
  *applied = control.get(cam, &error);
  if (error != nullptr) return Failed(who, std::string("cannot read back the ") + name, &error);
  return Status::Ok();
}

// Frame rate, exposure time and gain: the requested values, or the camera's.
Status SetExposureControls(ArvCamera* cam, const std::string& who, const AravisOptions& o,
                           AravisCameraSettings* settings) {
  GError* error = nullptr;
  // Frame rate first: Aravis turns frame-start triggering off when it sets a rate.
  if (o.frame_rate_hz > 0 && o.trigger == "free") {
    SIGHTLINE_RETURN_IF_ERROR(SetBounded(
        cam, who,
        {"frame rate", "Hz", arv_camera_is_frame_rate_available, arv_camera_get_frame_rate_bounds,
         arv_camera_set_frame_rate, arv_camera_get_frame_rate},
        o.frame_rate_hz, &settings->frame_rate_hz));
  } else if (o.frame_rate_hz > 0) {
    // Host triggering: the rate must still be one the camera can follow.
    double lo = 0, hi = 0;
    arv_camera_get_frame_rate_bounds(cam, &lo, &hi, &error);
    g_clear_error(&error);
    if (hi > 0 && o.frame_rate_hz > hi) {
      return InvalidArgument(who + ": trigger rate " + Num(o.frame_rate_hz) +
                             " Hz above the camera's maximum frame rate " + Num(hi) + " Hz");
    }
    settings->frame_rate_hz = o.frame_rate_hz;
  } else {
    settings->frame_rate_hz = arv_camera_get_frame_rate(cam, &error);
    g_clear_error(&error);
  }
  if (o.exposure_us > 0) {
    SIGHTLINE_RETURN_IF_ERROR(
        SetBounded(cam, who,
                   {"exposure time", "us", arv_camera_is_exposure_time_available,
                    arv_camera_get_exposure_time_bounds, arv_camera_set_exposure_time,
                    arv_camera_get_exposure_time},
                   o.exposure_us, &settings->exposure_us));
  } else {
    settings->exposure_us = arv_camera_get_exposure_time(cam, &error);
    g_clear_error(&error);
  }
  if (o.gain_db >= 0) {
    SIGHTLINE_RETURN_IF_ERROR(
        SetBounded(cam, who,
                   {"gain", "dB", arv_camera_is_gain_available, arv_camera_get_gain_bounds,
                    arv_camera_set_gain, arv_camera_get_gain},
                   o.gain_db, &settings->gain_db));
  } else {
    settings->gain_db = arv_camera_get_gain(cam, &error);
    g_clear_error(&error);
  }
  return Status::Ok();
}

// Triggering: software, a hardware line, or free running.
Status SetTrigger(ArvCamera* cam, const std::string& who, const AravisOptions& o,
                  AravisCameraSettings* settings) {
  GError* error = nullptr;
  if (o.trigger == "software") {
    const gboolean supported = arv_camera_is_software_trigger_supported(cam, &error);
    g_clear_error(&error);
    if (!supported) return InvalidArgument(who + " does not support software triggering");
    arv_camera_set_trigger(cam, "Software", &error);
    if (error != nullptr) return Failed(who, "cannot enable software triggering", &error);
    settings->trigger = "software";
  } else if (o.trigger == "hardware") {
    arv_camera_set_trigger(cam, o.trigger_line.c_str(), &error);
    if (error != nullptr)
      return Failed(who, "cannot enable hardware triggering on " + o.trigger_line, &error);
    const std::string source = Text(arv_camera_get_trigger_source(cam, &error));
    g_clear_error(&error);
    if (source != o.trigger_line) {
      return InvalidArgument(who + " kept trigger source '" + source + "' instead of '" +
                             o.trigger_line + "'");
    }
    settings->trigger = "hardware:" + source;
  } else {
    arv_camera_clear_triggers(cam, &error);
    g_clear_error(&error);  // Cameras without trigger features run free anyway.
    settings->trigger = "free";
  }
  return Status::Ok();
}

// GigE packet size: the requested one, or negotiated.
Status SetPacketSize(ArvCamera* cam, const std::string& who, const AravisOptions& o,
                     AravisCameraSettings* settings) {
  GError* error = nullptr;
  if (o.packet_size > 0) {
    arv_camera_gv_set_packet_size(cam, o.packet_size, &error);
    if (error != nullptr)
      return Failed(who, "cannot set packet size " + std::to_string(o.packet_size), &error);
  } else {
    arv_camera_gv_auto_packet_size(cam, &error);
    g_clear_error(&error);  // Keeps the camera's packet size when negotiation fails.
  }
  settings->packet_size = arv_camera_gv_get_packet_size(cam, &error);
  g_clear_error(&error);
  return Status::Ok();
}

// The stream's socket buffer (GigE) and buffer pool, and continuous acquisition.
Status PrepareStream(ArvCamera* cam, ArvStream* stream, const std::string& who,
                     const AravisOptions& o) {
  GError* error = nullptr;
  if (ARV_IS_GV_STREAM(stream)) {
    if (o.socket_buffer_bytes == 0) {
      g_object_set(stream, "socket-buffer", ARV_GV_STREAM_SOCKET_BUFFER_AUTO, "socket-buffer-size",
                   0, nullptr);
    } else {
      g_object_set(stream, "socket-buffer", ARV_GV_STREAM_SOCKET_BUFFER_FIXED, "socket-buffer-size",
                   o.socket_buffer_bytes, nullptr);
    }
  }
  const guint payload = arv_camera_get_payload(cam, &error);
  if (error != nullptr || payload == 0) return Failed(who, "cannot read the payload size", &error);
  for (int i = 0; i < o.buffer_count; ++i) {
    arv_stream_push_buffer(stream, arv_buffer_new(payload, nullptr));
  }
  arv_camera_set_acquisition_mode(cam, ARV_ACQUISITION_MODE_CONTINUOUS, &error);
  if (error != nullptr) return Failed(who, "cannot select continuous acquisition", &error);
  return Status::Ok();
}

}  // namespace

std::mutex& AravisSystemMutex() {
  static std::mutex mutex;
  return mutex;
}

struct AravisCamera::Impl {
  ArvCamera* camera = nullptr;
  ArvStream* stream = nullptr;
  ArvDevice* device = nullptr;  // Owned by camera.
  gulong lost_handler = 0;
  bool acquiring = false;
  bool debayer = true;
  std::atomic<bool> control_lost{false};
  int64_t last_raw_id = -1;
  int64_t unwrapped_id = -1;
};

AravisCamera::AravisCamera() = default;
AravisCamera::~AravisCamera() { Close(false); }

Status AravisCamera::Open(const std::string& device_id, const AravisOptions& o) {
  Close(false);
  impl_ = std::make_unique<Impl>();
  impl_->debayer = o.debayer;
  settings_ = AravisCameraSettings();
  label_id_ = device_id.empty() ? "(first camera)" : device_id;
  const std::string who = "Aravis camera '" + label_id_ + "'";
  GError* error = nullptr;
  {
    std::lock_guard<std::mutex> lock(AravisSystemMutex());
    if (o.fake_interface) arv_enable_interface("Fake");
    impl_->camera = arv_camera_new(device_id.empty() ? nullptr : device_id.c_str(), &error);
  }
  if (impl_->camera == nullptr) {
    std::string message = who + " is not available: " + TakeError(&error);
    if (!o.fake_interface && device_id.rfind("Fake", 0) == 0) {
      message += " (the simulated camera needs sensors.aravis.fake_interface=true)";
    }
    return Unavailable(message);
  }
  ArvCamera* cam = impl_->camera;
  ReadIdentity(cam, &settings_);
  const bool gv = arv_camera_is_gv_device(cam);
  settings_.protocol = gv ? "GigEVision" : arv_camera_is_uv_device(cam) ? "USB3Vision" : "other";
  if (device_id.empty() && !settings_.device_id.empty()) label_id_ = settings_.device_id;

  SIGHTLINE_RETURN_IF_ERROR(SelectPixelFormat(cam, who, o, &settings_));
  SIGHTLINE_RETURN_IF_ERROR(SetRegion(cam, who, o, &settings_));
  SIGHTLINE_RETURN_IF_ERROR(SetExposureControls(cam, who, o, &settings_));
  SIGHTLINE_RETURN_IF_ERROR(SetTrigger(cam, who, o, &settings_));

  // GigE transport: packet size, then a stream with a socket buffer large enough for a frame.
  if (gv) SIGHTLINE_RETURN_IF_ERROR(SetPacketSize(cam, who, o, &settings_));
  impl_->stream = arv_camera_create_stream(cam, nullptr, nullptr, &error);
  if (impl_->stream == nullptr) {
    return Unavailable(who + ": cannot create a stream: " + TakeError(&error));
  }
  SIGHTLINE_RETURN_IF_ERROR(PrepareStream(cam, impl_->stream, who, o));

  impl_->device = arv_camera_get_device(cam);
  impl_->lost_handler = g_signal_connect(impl_->device, "control-lost", G_CALLBACK(OnControlLost),
                                         &impl_->control_lost);
  arv_camera_start_acquisition(cam, &error);
  if (error != nullptr)
    return Unavailable(who + ": cannot start acquisition: " + TakeError(&error));
  impl_->acquiring = true;
  return Status::Ok();
}

StatusOr<AravisPop> AravisCamera::Pop(std::chrono::microseconds timeout) {
  const std::string who = "Aravis camera '" + label_id_ + "'";
  if (!impl_ || impl_->stream == nullptr) return FailedPrecondition(who + " is not open");
  if (impl_->control_lost.load()) {
    return Unavailable(who + " lost control (it stopped answering heartbeats)");
  }
  AravisPop out;
  const guint64 wait_us = static_cast<guint64>(std::max<int64_t>(0, timeout.count()));
  ArvBuffer* buffer = arv_stream_timeout_pop_buffer(impl_->stream, wait_us);
  if (buffer == nullptr) return out;
  const ArvBufferStatus status = arv_buffer_get_status(buffer);
  if (status == ARV_BUFFER_STATUS_TIMEOUT) {
    out.buffer_timeouts = 1;
  } else if (status != ARV_BUFFER_STATUS_SUCCESS) {
    out.incomplete = 1;
  } else {
    size_t size = 0;
    const void* data = arv_buffer_get_image_data(buffer, &size);
    const int width = arv_buffer_get_image_width(buffer);
    const int height = arv_buffer_get_image_height(buffer);
    const uint32_t format = arv_buffer_get_image_pixel_format(buffer);
    gint pad_x = 0, pad_y = 0;
    arv_buffer_get_image_padding(buffer, &pad_x, &pad_y);
    const size_t bytes_per_pixel = ARV_PIXEL_FORMAT_BIT_PER_PIXEL(format) / 8;
    const size_t stride = static_cast<size_t>(width) * bytes_per_pixel + std::max(0, pad_x);
    StatusOr<cv::Mat> image =
        ConvertCameraImage(format, width, height, data, size, impl_->debayer, stride);
    if (!image.ok()) {
      out.incomplete = 1;
    } else {
      AravisImage frame;
      frame.image = std::move(*image);
      // GigE Vision 1 frame ids are 16-bit, wrap to 1 and skip 0: unwrap to a monotonic count.
      const int64_t raw = static_cast<int64_t>(arv_buffer_get_frame_id(buffer));
      if (impl_->last_raw_id < 0) {
        impl_->unwrapped_id = raw;
      } else {
        int64_t delta = raw - impl_->last_raw_id;
        if (raw <= 0xFFFF && impl_->last_raw_id <= 0xFFFF && delta < 0) {
          delta += 0xFFFF;  // 65535 -> 1 is one step.
        }
        if (delta <= 0) delta = 1;  // A restarted counter: keep ours monotonic.
        out.device_frames_lost = static_cast<uint64_t>(delta - 1);
        impl_->unwrapped_id += delta;
      }
      impl_->last_raw_id = raw;
      frame.frame_id = impl_->unwrapped_id;
      guint64 stamp_ns = arv_buffer_get_timestamp(buffer);
      const guint64 system_ns = arv_buffer_get_system_timestamp(buffer);
      if (stamp_ns == 0) stamp_ns = system_ns;
      frame.device_time_s = static_cast<double>(stamp_ns) * 1e-9;
      const double host_now = HostTimeS();
      if (system_ns > 0) {
        const double age_s =
            (static_cast<double>(g_get_real_time()) * 1e3 - static_cast<double>(system_ns)) * 1e-9;
        frame.arrival_host_time_s = host_now - std::clamp(age_s, 0.0, 10.0);
      } else {
        frame.arrival_host_time_s = host_now;
      }
      out.image = std::move(frame);
    }
  }
  arv_stream_push_buffer(impl_->stream, buffer);
  return out;
}

Status AravisCamera::SoftwareTrigger() {
  if (!impl_ || impl_->camera == nullptr) return FailedPrecondition("camera not open");
  GError* error = nullptr;
  arv_camera_software_trigger(impl_->camera, &error);
  if (error != nullptr) {
    return Unavailable("Aravis camera '" + label_id_ +
                       "': software trigger failed: " + TakeError(&error));
  }
  return Status::Ok();
}

void AravisCamera::Close(bool device_lost) {
  if (!impl_) return;
  if (impl_->device != nullptr && impl_->lost_handler != 0) {
    g_signal_handler_disconnect(impl_->device, impl_->lost_handler);
  }
  const bool lost = device_lost || impl_->control_lost.load();
  if (impl_->acquiring && !lost) {
    GError* error = nullptr;
    arv_camera_stop_acquisition(impl_->camera, &error);
    g_clear_error(&error);
  }
  if (impl_->stream != nullptr) g_object_unref(impl_->stream);
  if (impl_->camera != nullptr) g_object_unref(impl_->camera);
  impl_.reset();
}

std::vector<DeviceInfo> EnumerateAravisCameras(bool include_fake) {
  std::lock_guard<std::mutex> lock(AravisSystemMutex());
  if (include_fake) arv_enable_interface("Fake");
  arv_update_device_list();
  std::vector<DeviceInfo> devices;
  const unsigned n = arv_get_n_devices();
  auto text = [](const char* value) { return std::string(value != nullptr ? value : ""); };
  for (unsigned i = 0; i < n; ++i) {
    DeviceInfo d;
    d.driver = "aravis";
    const std::string id = text(arv_get_device_id(i));
    const std::string protocol = text(arv_get_device_protocol(i));
    if (!include_fake && id.rfind("Fake", 0) == 0) continue;  // Enabled earlier in the process.
    d.uri = "aravis://" + id;
    d.name = text(arv_get_device_vendor(i));
    const std::string model = text(arv_get_device_model(i));
    if (!model.empty()) d.name += (d.name.empty() ? "" : " ") + model;
    d.serial = text(arv_get_device_serial_nbr(i));
    d.details = protocol;
    const std::string address = text(arv_get_device_address(i));
    if (!address.empty()) d.details += " " + address;
    devices.push_back(std::move(d));
  }
  return devices;
}

}  // namespace sightline
