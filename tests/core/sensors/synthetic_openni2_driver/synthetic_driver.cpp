// A small OpenNI2 driver for tests: one RGB-D device, "sightline-synthetic://0", streaming the
// known depth and colour pattern of synthetic_pattern.h at 30 Hz. It can stop after N frames,
// either stalling or reporting itself unplugged and coming back later (environment variables in
// synthetic_pattern.h). Loaded by libOpenNI2 from an OpenNI2/Drivers/ folder beside a private
// copy of the library in the build tree; never installed.
#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdlib>
#include <cstring>
#include <mutex>
#include <new>
#include <string>
#include <thread>
#include <vector>

// XnLib's allocation macros, used by ONI_EXPORT_DRIVER but not shipped in libopenni2-dev.
#define XN_NEW(type, ...) new type(__VA_ARGS__)
#define XN_DELETE(p) delete (p)
#include <Driver/OniDriverAPI.h>

#include "tests/core/sensors/synthetic_openni2_driver/synthetic_pattern.h"

namespace {

namespace pattern = sightline::synthetic_openni2;
using Clock = std::chrono::steady_clock;

int EnvInt(const char* name, int fallback) {
  const char* value = std::getenv(name);
  return value != nullptr && *value != '\0' ? std::atoi(value) : fallback;
}

// Copies a property value into OpenNI's buffer when the size fits.
template <typename T>
OniStatus Put(const T& value, void* data, int* size) {
  if (*size < static_cast<int>(sizeof(T))) return ONI_STATUS_BAD_PARAMETER;
  std::memcpy(data, &value, sizeof(T));
  *size = sizeof(T);
  return ONI_STATUS_OK;
}

class SyntheticDriver;

class SyntheticStream : public oni::driver::StreamBase {
 public:
  explicit SyntheticStream(OniSensorType type) : type_(type) {
    mode_.pixelFormat =
        type == ONI_SENSOR_DEPTH ? ONI_PIXEL_FORMAT_DEPTH_1_MM : ONI_PIXEL_FORMAT_RGB888;
    mode_.resolutionX = pattern::kWidth;
    mode_.resolutionY = pattern::kHeight;
    mode_.fps = pattern::kFps;
  }

  OniStatus start() override {
    started_ = true;
    return ONI_STATUS_OK;
  }
  void stop() override { started_ = false; }
  bool started() const { return started_; }

  OniBool isPropertySupported(int id) override {
    switch (id) {
      case ONI_STREAM_PROPERTY_VIDEO_MODE:
      case ONI_STREAM_PROPERTY_HORIZONTAL_FOV:
      case ONI_STREAM_PROPERTY_VERTICAL_FOV:
      case ONI_STREAM_PROPERTY_MIRRORING:
      case ONI_STREAM_PROPERTY_CROPPING:
      case ONI_STREAM_PROPERTY_STRIDE:
        return TRUE;
      case ONI_STREAM_PROPERTY_MAX_VALUE:
      case ONI_STREAM_PROPERTY_MIN_VALUE:
        return type_ == ONI_SENSOR_DEPTH;
      default:
        return FALSE;
    }
  }

  OniStatus getProperty(int id, void* data, int* size) override {
    switch (id) {
      case ONI_STREAM_PROPERTY_VIDEO_MODE:
        return Put(mode_, data, size);
      case ONI_STREAM_PROPERTY_HORIZONTAL_FOV:
        return Put(pattern::kHorizontalFovRad, data, size);
      case ONI_STREAM_PROPERTY_VERTICAL_FOV:
        return Put(pattern::kVerticalFovRad, data, size);
      case ONI_STREAM_PROPERTY_MIRRORING:
        return Put(OniBool(mirror_ ? TRUE : FALSE), data, size);
      case ONI_STREAM_PROPERTY_CROPPING: {
        OniCropping cropping{};
        cropping.enabled = FALSE;
        return Put(cropping, data, size);
      }
      case ONI_STREAM_PROPERTY_STRIDE:
        return Put(Stride(), data, size);
      case ONI_STREAM_PROPERTY_MAX_VALUE:
        if (type_ != ONI_SENSOR_DEPTH) return ONI_STATUS_NOT_SUPPORTED;
        return Put(int(10000), data, size);
      case ONI_STREAM_PROPERTY_MIN_VALUE:
        if (type_ != ONI_SENSOR_DEPTH) return ONI_STATUS_NOT_SUPPORTED;
        return Put(int(0), data, size);
      default:
        return ONI_STATUS_NOT_SUPPORTED;
    }
  }

  OniStatus setProperty(int id, const void* data, int size) override {
    if (id == ONI_STREAM_PROPERTY_MIRRORING && size == sizeof(OniBool)) {
      mirror_ = *static_cast<const OniBool*>(data) != FALSE;
      return ONI_STATUS_OK;
    }
    if (id == ONI_STREAM_PROPERTY_VIDEO_MODE && size == sizeof(OniVideoMode)) {
      const OniVideoMode* mode = static_cast<const OniVideoMode*>(data);
      const bool same = mode->pixelFormat == mode_.pixelFormat &&
                        mode->resolutionX == mode_.resolutionX &&
                        mode->resolutionY == mode_.resolutionY && mode->fps == mode_.fps;
      return same ? ONI_STATUS_OK : ONI_STATUS_NOT_SUPPORTED;
    }
    if (id == ONI_STREAM_PROPERTY_CROPPING && size == sizeof(OniCropping)) {
      return static_cast<const OniCropping*>(data)->enabled ? ONI_STATUS_NOT_SUPPORTED
                                                            : ONI_STATUS_OK;
    }
    return ONI_STATUS_NOT_SUPPORTED;
  }

  // Sends frame `index` if started. Called by the device's thread.
  void Emit(int index, uint64_t timestamp_us) {
    if (!started_) return;
    OniFrame* frame = getServices().acquireFrame();
    if (frame == nullptr) return;
    frame->sensorType = type_;
    frame->timestamp = timestamp_us;
    frame->frameIndex = index;
    frame->width = mode_.resolutionX;
    frame->height = mode_.resolutionY;
    frame->videoMode = mode_;
    frame->croppingEnabled = FALSE;
    frame->cropOriginX = 0;
    frame->cropOriginY = 0;
    frame->stride = Stride();
    frame->dataSize = Stride() * mode_.resolutionY;
    uint8_t* bytes = static_cast<uint8_t*>(frame->data);
    for (int y = 0; y < mode_.resolutionY; ++y) {
      for (int x = 0; x < mode_.resolutionX; ++x) {
        const int source_x = mirror_ ? mode_.resolutionX - 1 - x : x;
        if (type_ == ONI_SENSOR_DEPTH) {
          const uint16_t mm = pattern::DepthMm(source_x, y, index);
          std::memcpy(bytes + y * Stride() + 2 * x, &mm, 2);
        } else {
          pattern::Rgb(source_x, y, index, bytes + y * Stride() + 3 * x);
        }
      }
    }
    raiseNewFrame(frame);
    getServices().releaseFrame(frame);
  }

 private:
  int Stride() const { return mode_.resolutionX * (type_ == ONI_SENSOR_DEPTH ? 2 : 3); }

  const OniSensorType type_;
  OniVideoMode mode_{};
  std::atomic<bool> started_{false};
  std::atomic<bool> mirror_{false};
};

class SyntheticDevice : public oni::driver::DeviceBase {
 public:
  explicit SyntheticDevice(SyntheticDriver* driver);
  ~SyntheticDevice() override;

  OniStatus getSensorInfoList(OniSensorInfo** infos, int* count) override {
    *infos = sensors_;
    *count = 2;
    return ONI_STATUS_OK;
  }

  oni::driver::StreamBase* createStream(OniSensorType type) override {
    if (type != ONI_SENSOR_DEPTH && type != ONI_SENSOR_COLOR) return nullptr;
    std::lock_guard<std::mutex> lock(mutex_);
    streams_.push_back(new SyntheticStream(type));
    return streams_.back();
  }

  void destroyStream(oni::driver::StreamBase* stream) override {
    std::lock_guard<std::mutex> lock(mutex_);
    streams_.erase(std::remove(streams_.begin(), streams_.end(), stream), streams_.end());
    delete stream;
  }

  OniBool isPropertySupported(int id) override {
    return id == ONI_DEVICE_PROPERTY_IMAGE_REGISTRATION || id == ONI_DEVICE_PROPERTY_SERIAL_NUMBER;
  }
  OniStatus getProperty(int id, void* data, int* size) override {
    if (id == ONI_DEVICE_PROPERTY_IMAGE_REGISTRATION) return Put(registration_, data, size);
    if (id == ONI_DEVICE_PROPERTY_SERIAL_NUMBER) {
      const char serial[] = "SYN0001";
      if (*size < static_cast<int>(sizeof(serial))) return ONI_STATUS_BAD_PARAMETER;
      std::memcpy(data, serial, sizeof(serial));
      *size = sizeof(serial);
      return ONI_STATUS_OK;
    }
    return ONI_STATUS_NOT_SUPPORTED;
  }
  OniStatus setProperty(int id, const void* data, int size) override {
    if (id == ONI_DEVICE_PROPERTY_IMAGE_REGISTRATION && size == sizeof(OniImageRegistrationMode)) {
      registration_ = *static_cast<const OniImageRegistrationMode*>(data);
      return ONI_STATUS_OK;
    }
    return ONI_STATUS_NOT_SUPPORTED;
  }
  OniBool isImageRegistrationModeSupported(OniImageRegistrationMode) override { return TRUE; }

 private:
  void Run();

  SyntheticDriver* const driver_;
  OniVideoMode modes_[2];
  OniSensorInfo sensors_[2];
  std::mutex mutex_;  // streams_ between OpenNI's calls and the frame thread.
  std::vector<SyntheticStream*> streams_;
  OniImageRegistrationMode registration_ = ONI_IMAGE_REGISTRATION_OFF;
  const int stop_after_;
  const bool unplug_;
  std::mutex stop_mutex_;
  std::condition_variable stop_cv_;
  bool stop_ = false;
  std::thread thread_;
};

class SyntheticDriver : public oni::driver::DriverBase {
 public:
  explicit SyntheticDriver(OniDriverServices* services) : DriverBase(services) {
    std::memset(&info_, 0, sizeof(info_));
    std::strncpy(info_.uri, pattern::kUri, ONI_MAX_STR - 1);
    std::strncpy(info_.vendor, pattern::kVendor, ONI_MAX_STR - 1);
    std::strncpy(info_.name, pattern::kName, ONI_MAX_STR - 1);
    info_.usbVendorId = 0x5347;
    info_.usbProductId = 0x0001;
  }

  OniStatus initialize(oni::driver::DeviceConnectedCallback connected,
                       oni::driver::DeviceDisconnectedCallback disconnected,
                       oni::driver::DeviceStateChangedCallback state_changed,
                       void* cookie) override {
    DriverBase::initialize(connected, disconnected, state_changed, cookie);
    deviceConnected(&info_);
    return ONI_STATUS_OK;
  }

  oni::driver::DeviceBase* deviceOpen(const char* uri, const char* /*mode*/) override {
    if (uri == nullptr || std::strcmp(uri, pattern::kUri) != 0 || Absent()) return nullptr;
    return new SyntheticDevice(this);
  }
  void deviceClose(oni::driver::DeviceBase* device) override { delete device; }

  OniStatus tryDevice(const char* uri) override {
    return uri != nullptr && std::strcmp(uri, pattern::kUri) == 0 && !Absent() ? ONI_STATUS_OK
                                                                               : ONI_STATUS_ERROR;
  }

  void shutdown() override {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      stop_ = true;
    }
    cv_.notify_all();
    if (replug_thread_.joinable()) replug_thread_.join();
  }

  void* enableFrameSync(oni::driver::StreamBase**, int) override { return new int(1); }
  void disableFrameSync(void* group) override { delete static_cast<int*>(group); }

  // The device reports itself unplugged, then, like a real driver's hot-plug thread, announces
  // it connected again after the absence.
  void Unplug() {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      unplugged_ = true;
      replug_at_ = Clock::now() + std::chrono::milliseconds(EnvInt(pattern::kAbsentMsEnv, 1000));
      if (!replug_thread_.joinable()) replug_thread_ = std::thread(&SyntheticDriver::Replug, this);
    }
    deviceDisconnected(&info_);
    cv_.notify_all();
  }

 private:
  bool Absent() {
    std::lock_guard<std::mutex> lock(mutex_);
    return unplugged_;
  }

  void Replug() {
    std::unique_lock<std::mutex> lock(mutex_);
    while (!stop_) {
      if (unplugged_ && Clock::now() >= replug_at_) {
        unplugged_ = false;
        lock.unlock();
        deviceConnected(&info_);
        lock.lock();
        continue;
      }
      if (unplugged_) {
        cv_.wait_until(lock, replug_at_);
      } else {
        cv_.wait(lock);
      }
    }
  }

  OniDeviceInfo info_;
  std::mutex mutex_;
  std::condition_variable cv_;
  bool unplugged_ = false;
  bool stop_ = false;
  Clock::time_point replug_at_;
  std::thread replug_thread_;
};

SyntheticDevice::SyntheticDevice(SyntheticDriver* driver)
    : driver_(driver), stop_after_(EnvInt(pattern::kStopAfterEnv, 0)), unplug_([] {
        const char* mode = std::getenv(pattern::kStopModeEnv);
        return mode != nullptr && std::string(mode) == "unplug";
      }()) {
  const OniSensorType types[2] = {ONI_SENSOR_DEPTH, ONI_SENSOR_COLOR};
  for (int i = 0; i < 2; ++i) {
    modes_[i].pixelFormat = i == 0 ? ONI_PIXEL_FORMAT_DEPTH_1_MM : ONI_PIXEL_FORMAT_RGB888;
    modes_[i].resolutionX = pattern::kWidth;
    modes_[i].resolutionY = pattern::kHeight;
    modes_[i].fps = pattern::kFps;
    sensors_[i].sensorType = types[i];
    sensors_[i].numSupportedVideoModes = 1;
    sensors_[i].pSupportedVideoModes = &modes_[i];
  }
  thread_ = std::thread(&SyntheticDevice::Run, this);
}

SyntheticDevice::~SyntheticDevice() {
  {
    std::lock_guard<std::mutex> lock(stop_mutex_);
    stop_ = true;
  }
  stop_cv_.notify_all();
  thread_.join();
  for (SyntheticStream* stream : streams_) delete stream;
}

void SyntheticDevice::Run() {
  const auto period = std::chrono::microseconds(1000000 / pattern::kFps);
  Clock::time_point next = Clock::now();
  int index = 0;
  bool stopped = false;
  while (true) {
    next += period;
    {
      std::unique_lock<std::mutex> lock(stop_mutex_);
      if (stop_cv_.wait_until(lock, next, [&] { return stop_; })) return;
    }
    if (stopped) continue;
    bool any_started = false;
    {
      std::lock_guard<std::mutex> lock(mutex_);
      any_started = std::any_of(streams_.begin(), streams_.end(),
                                [](const SyntheticStream* s) { return s->started(); });
      if (any_started) {
        ++index;
        const uint64_t timestamp_us = 1000000ull + static_cast<uint64_t>(index) * 33333ull;
        for (SyntheticStream* stream : streams_) stream->Emit(index, timestamp_us);
      }
    }
    if (stop_after_ > 0 && index >= stop_after_) {
      stopped = true;
      if (unplug_) driver_->Unplug();
    }
  }
}

}  // namespace

ONI_EXPORT_DRIVER(SyntheticDriver)
