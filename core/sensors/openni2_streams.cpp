#include "core/sensors/openni2_streams.h"

#include <opencv2/imgproc.hpp>

namespace sightline {

const char* StreamName(int stream) { return stream == kDepth ? "depth" : "colour"; }

std::string VideoModeText(const openni::VideoMode& m) {
  std::string format;
  switch (m.getPixelFormat()) {
    case openni::PIXEL_FORMAT_DEPTH_1_MM:
      format = "DEPTH_1_MM";
      break;
    case openni::PIXEL_FORMAT_DEPTH_100_UM:
      format = "DEPTH_100_UM";
      break;
    case openni::PIXEL_FORMAT_RGB888:
      format = "RGB888";
      break;
    case openni::PIXEL_FORMAT_YUV422:
      format = "YUV422";
      break;
    case openni::PIXEL_FORMAT_YUYV:
      format = "YUYV";
      break;
    case openni::PIXEL_FORMAT_GRAY8:
      format = "GRAY8";
      break;
    case openni::PIXEL_FORMAT_GRAY16:
      format = "GRAY16";
      break;
    case openni::PIXEL_FORMAT_JPEG:
      format = "JPEG";
      break;
    default:
      format = "format " + std::to_string(static_cast<int>(m.getPixelFormat()));
  }
  return std::to_string(m.getResolutionX()) + "x" + std::to_string(m.getResolutionY()) + "@" +
         std::to_string(m.getFps()) + " " + format;
}

double DepthUnitsPerMetre(openni::PixelFormat format) {
  if (format == openni::PIXEL_FORMAT_DEPTH_1_MM) return 1000;
  if (format == openni::PIXEL_FORMAT_DEPTH_100_UM) return 10000;
  return 0;
}

bool StreamFormatSupported(int stream, openni::PixelFormat format) {
  if (stream == kDepth) return DepthUnitsPerMetre(format) > 0;
  return format == openni::PIXEL_FORMAT_RGB888 || format == openni::PIXEL_FORMAT_YUYV ||
         format == openni::PIXEL_FORMAT_YUV422 || format == openni::PIXEL_FORMAT_GRAY8;
}

Status SelectVideoMode(openni::VideoStream* stream, int which, int width, int height, int fps,
                       const std::string& who) {
  const openni::VideoMode current = stream->getVideoMode();
  const int want_w = width > 0 ? width : current.getResolutionX();
  const int want_h = height > 0 ? height : current.getResolutionY();
  const int want_fps = fps > 0 ? fps : current.getFps();
  if (current.getResolutionX() == want_w && current.getResolutionY() == want_h &&
      current.getFps() == want_fps && StreamFormatSupported(which, current.getPixelFormat())) {
    return Status::Ok();
  }
  const openni::Array<openni::VideoMode>& modes = stream->getSensorInfo().getSupportedVideoModes();
  std::string offered;
  int best = -1;
  for (int i = 0; i < modes.getSize(); ++i) {
    offered += (offered.empty() ? "" : ", ") + VideoModeText(modes[i]);
    if (modes[i].getResolutionX() != want_w || modes[i].getResolutionY() != want_h ||
        modes[i].getFps() != want_fps || !StreamFormatSupported(which, modes[i].getPixelFormat())) {
      continue;
    }
    const bool preferred = modes[i].getPixelFormat() == openni::PIXEL_FORMAT_RGB888 ||
                           modes[i].getPixelFormat() == openni::PIXEL_FORMAT_DEPTH_1_MM;
    if (best < 0 || preferred) best = i;
  }
  if (best < 0) {
    return InvalidArgument(who + ": no " + StreamName(which) + " mode " + std::to_string(want_w) +
                           "x" + std::to_string(want_h) + "@" + std::to_string(want_fps) +
                           " (modes: " + offered + ")");
  }
  if (stream->setVideoMode(modes[best]) != openni::STATUS_OK) {
    return InvalidArgument(who + ": the device refused " + StreamName(which) + " mode " +
                           VideoModeText(modes[best]) + ": " + openni::OpenNI::getExtendedError());
  }
  return Status::Ok();
}

cv::Mat ColorFrameToBgr(const openni::VideoFrameRef& frame) {
  void* data = const_cast<void*>(frame.getData());  // Wrapped read-only; converted into bgr.
  const int w = frame.getWidth(), h = frame.getHeight();
  const size_t stride = static_cast<size_t>(frame.getStrideInBytes());
  cv::Mat bgr;
  switch (frame.getVideoMode().getPixelFormat()) {
    case openni::PIXEL_FORMAT_RGB888:
      cv::cvtColor(cv::Mat(h, w, CV_8UC3, data, stride), bgr, cv::COLOR_RGB2BGR);
      break;
    case openni::PIXEL_FORMAT_GRAY8:
      cv::cvtColor(cv::Mat(h, w, CV_8UC1, data, stride), bgr, cv::COLOR_GRAY2BGR);
      break;
    case openni::PIXEL_FORMAT_YUYV:
      cv::cvtColor(cv::Mat(h, w, CV_8UC2, data, stride), bgr, cv::COLOR_YUV2BGR_YUYV);
      break;
    case openni::PIXEL_FORMAT_YUV422:
      cv::cvtColor(cv::Mat(h, w, CV_8UC2, data, stride), bgr, cv::COLOR_YUV2BGR_UYVY);
      break;
    default:
      break;
  }
  return bgr;
}

void OpenNi2DeviceWatcher::onDeviceDisconnected(const openni::DeviceInfo* info) {
  if (info != nullptr && uri_ == info->getUri()) Set("the driver reported it unplugged");
}

void OpenNi2DeviceWatcher::onDeviceStateChanged(const openni::DeviceInfo* info,
                                                openni::DeviceState state) {
  if (info != nullptr && uri_ == info->getUri() && state == openni::DEVICE_STATE_ERROR) {
    Set("the driver reported an error state");
  }
}

std::string OpenNi2DeviceWatcher::Gone() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return reason_;
}

void OpenNi2DeviceWatcher::Set(const std::string& reason) {
  std::lock_guard<std::mutex> lock(mutex_);
  if (reason_.empty()) reason_ = reason;
}

}  // namespace sightline
