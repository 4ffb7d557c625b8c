#include "core/sensors/v4l2_source.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <opencv2/videoio.hpp>
#include <utility>

#include "core/common/timing.h"

namespace sightline {
namespace {

// The /dev/video* nodes in natural order.
std::vector<std::string> VideoNodes() {
  std::vector<std::string> nodes;
  std::error_code ec;
  for (const auto& entry : std::filesystem::directory_iterator("/dev", ec)) {
    const std::string name = entry.path().filename().string();
    if (name.rfind("video", 0) == 0 && name.size() > 5 &&
        std::all_of(name.begin() + 5, name.end(), [](char c) { return std::isdigit(c); })) {
      nodes.push_back(entry.path().string());
    }
  }
  std::sort(nodes.begin(), nodes.end(), [](const std::string& a, const std::string& b) {
    return a.size() != b.size() ? a.size() < b.size() : a < b;
  });
  return nodes;
}

std::string FourccText(double value) {
  const int code = static_cast<int>(value);
  std::string text;
  for (int i = 0; i < 4; ++i) {
    const char c = static_cast<char>((code >> (8 * i)) & 0xFF);
    text += std::isprint(static_cast<unsigned char>(c)) ? c : '?';
  }
  return text;
}

}  // namespace

V4l2Source::V4l2Source(const std::string& device, V4l2Options options)
    : LiveSource(options.live), path_(DevicePath(device)), options_(std::move(options)) {}

V4l2Source::~V4l2Source() { Close(); }

std::string V4l2Source::DevicePath(const std::string& device) {
  if (!device.empty() &&
      std::all_of(device.begin(), device.end(), [](char c) { return std::isdigit(c); })) {
    return "/dev/video" + device;
  }
  return device;
}

Status V4l2Source::Available() {
  if (VideoNodes().empty()) {
    return Unavailable(
        "no V4L2 video device: /dev/video* is absent (no webcam attached, or the "
        "container does not expose it)");
  }
  return Status::Ok();
}

std::vector<DeviceInfo> V4l2Source::Enumerate() {
  std::vector<DeviceInfo> devices;
  for (const std::string& node : VideoNodes()) {
    DeviceInfo d;
    d.driver = "v4l2";
    d.uri = "v4l2://" + node;
    const std::string base = std::filesystem::path(node).filename().string();
    std::ifstream name_file("/sys/class/video4linux/" + base + "/name");
    std::getline(name_file, d.name);
    if (d.name.empty()) d.name = node;
    d.details = "V4L2 " + node;
    devices.push_back(std::move(d));
  }
  return devices;
}

std::string V4l2Source::DeviceLabel() const { return "V4L2 device " + path_; }

Status V4l2Source::Connect(SourceInfo* info) {
  std::string error;
  if (!options_.IsValid(&error)) return InvalidArgument(error);
  std::error_code ec;
  if (path_.empty() || !std::filesystem::exists(path_, ec)) {
    return Unavailable(
        DeviceLabel() + " not found (no such device node" +
        (VideoNodes().empty() ? std::string("; no /dev/video* exists at all") : std::string()) +
        ")");
  }
  capture_ = std::make_unique<cv::VideoCapture>();
  if (!capture_->open(path_, cv::CAP_V4L2)) {
    return Unavailable(DeviceLabel() +
                       " could not be opened as a capture device (busy, no permission, or a "
                       "metadata node)");
  }
  if (!options_.fourcc.empty()) {
    const std::string& f = options_.fourcc;
    capture_->set(cv::CAP_PROP_FOURCC, cv::VideoWriter::fourcc(f[0], f[1], f[2], f[3]));
  }
  if (options_.width > 0) capture_->set(cv::CAP_PROP_FRAME_WIDTH, options_.width);
  if (options_.height > 0) capture_->set(cv::CAP_PROP_FRAME_HEIGHT, options_.height);
  if (options_.fps > 0) capture_->set(cv::CAP_PROP_FPS, options_.fps);
  info->format = "V4L2 camera";
  info->path = "v4l2://" + path_;
  info->kind = SourceKind::kMono;
  info->live = true;
  info->frame_count = -1;
  info->width = static_cast<int>(capture_->get(cv::CAP_PROP_FRAME_WIDTH));
  info->height = static_cast<int>(capture_->get(cv::CAP_PROP_FRAME_HEIGHT));
  info->rate_hz = capture_->get(cv::CAP_PROP_FPS);
  info->notes.push_back("camera accepted " + std::to_string(info->width) + "x" +
                        std::to_string(info->height) + " at " + std::to_string(info->rate_hz) +
                        " Hz, " + FourccText(capture_->get(cv::CAP_PROP_FOURCC)));
  info->notes.push_back("no calibration: intrinsics unknown until the camera is calibrated");
  return Status::Ok();
}

StatusOr<std::optional<CapturedFrame>> V4l2Source::ReadFrame(std::chrono::milliseconds) {
  // VideoCapture::grab() blocks for at most one frame interval of a working camera and fails
  // at once for an unplugged one.
  if (!capture_->grab()) return Unavailable(DeviceLabel() + " stopped delivering frames");
  const double arrival = HostTimeS();
  cv::Mat image;
  if (!capture_->retrieve(image) || image.empty()) {
    CountIncomplete();
    return std::optional<CapturedFrame>();
  }
  CapturedFrame captured;
  MonoFrame mono;
  const double msec = capture_->get(cv::CAP_PROP_POS_MSEC);
  mono.stamp.sensor_time_s = msec > 0 ? msec * 1e-3 : arrival;
  mono.image = image;
  captured.frame = std::move(mono);
  captured.arrival_host_time_s = arrival;
  return std::optional<CapturedFrame>(std::move(captured));
}

void V4l2Source::Disconnect(bool) {
  if (capture_) capture_->release();
  capture_.reset();
}

}  // namespace sightline
