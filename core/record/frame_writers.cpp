#include "core/record/frame_writers.h"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <future>
#include <opencv2/imgcodecs.hpp>
#include <sstream>

#include "core/common/text_file.h"
#include "core/io/camera_yaml.h"
#include "core/record/durable_file.h"

namespace sightline {
namespace {

constexpr double kTumDepthScale = 5000;  // 16-bit value / 5000 = metres.
const char kHeader[] = "# Sightline recording\n";

std::string Number(const char* format, double value) {
  char text[64];
  std::snprintf(text, sizeof(text), format, value);
  return text;
}

std::string FrameName(int64_t index) {
  char name[32];
  std::snprintf(name, sizeof(name), "%06lld.png", static_cast<long long>(index));
  return name;
}

Status MakeDirs(const std::string& path) {
  std::error_code ec;
  std::filesystem::create_directories(path, ec);
  if (ec) return Unavailable("cannot create folder " + path + ": " + ec.message());
  return Status::Ok();
}

// Encodes one image as PNG.
StatusOr<std::vector<uint8_t>> EncodePng(const cv::Mat& image, const std::string& path,
                                         const FrameWriterSettings& s) {
  if (image.empty()) return InvalidArgument("empty image for " + path);
  std::vector<uint8_t> png;
  try {
    if (!cv::imencode(".png", image, png, {cv::IMWRITE_PNG_COMPRESSION, s.png_compression})) {
      return InvalidArgument("cannot encode " + path + " as PNG");
    }
  } catch (const cv::Exception& e) {
    return InvalidArgument("cannot encode " + path + " as PNG: " + e.what());
  }
  return png;
}

// Encodes (PNG compression is the writer's main cost) and writes one image atomically.
StatusOr<int64_t> EncodeAndWrite(const std::string& path, const cv::Mat& image,
                                 const FrameWriterSettings& s) {
  StatusOr<std::vector<uint8_t>> png = EncodePng(image, path, s);
  if (!png.ok()) return png.status();
  SIGHTLINE_RETURN_IF_ERROR(WriteFileAtomically(path, *png, s.sync));
  return static_cast<int64_t>(png->size());
}

// The two images of one frame, each encoded, written and fsynced on its own thread; adds their
// sizes to *bytes. Fails with the first error (in the order a, b).
Status WritePngPair(const std::string& path_a, const cv::Mat& a, const std::string& path_b,
                    const cv::Mat& b, const FrameWriterSettings& s, int64_t* bytes) {
  auto written_b = std::async(std::launch::async, [&] { return EncodeAndWrite(path_b, b, s); });
  StatusOr<int64_t> size_a = EncodeAndWrite(path_a, a, s);
  StatusOr<int64_t> size_b = written_b.get();
  if (size_a.ok()) *bytes += *size_a;
  if (size_b.ok()) *bytes += *size_b;
  if (!size_a.ok()) return size_a.status();
  return size_b.ok() ? Status::Ok() : size_b.status();
}

Status WritePng(const std::string& path, const cv::Mat& image, const FrameWriterSettings& s,
                int64_t* bytes) {
  StatusOr<std::vector<uint8_t>> png = EncodePng(image, path, s);
  if (!png.ok()) return png.status();
  SIGHTLINE_RETURN_IF_ERROR(WriteFileAtomically(path, *png, s.sync));
  *bytes += static_cast<int64_t>(png->size());
  return Status::Ok();
}

Status AppendCounted(AppendOnlyFile* file, const std::string& line, int64_t* bytes,
                     bool durable = true) {
  SIGHTLINE_RETURN_IF_ERROR(file->AppendLine(line, durable));
  *bytes += static_cast<int64_t>(line.size() + 1);
  return Status::Ok();
}

// TUM RGB-D: colour and depth PNGs, then rgb.txt, depth.txt and associations.txt (the reader
// pairs by associations.txt, so an interrupted frame is never half listed).
class TumRgbdWriter : public FrameWriter {
 public:
  TumRgbdWriter(std::string folder, FrameWriterSettings s) : folder_(std::move(folder)), s_(s) {}

  Status Init(const SourceInfo& info) {
    SIGHTLINE_RETURN_IF_ERROR(MakeDirs(JoinPath(folder_, "rgb")));
    SIGHTLINE_RETURN_IF_ERROR(MakeDirs(JoinPath(folder_, "depth")));
    std::optional<PinholeCamera> camera = info.camera;
    double max_depth_m = 10;
    if (info.rgbd) {
      camera = info.rgbd->color;
      max_depth_m = info.rgbd->max_depth_m;
    }
    if (camera) {
      CameraFile file{*camera, kTumDepthScale, max_depth_m, std::nullopt};
      if (info.rate_hz > 0) file.rate_hz = info.rate_hz;
      SIGHTLINE_RETURN_IF_ERROR(WriteCameraYaml(file, JoinPath(folder_, kCameraYamlName)));
    } else {
      notes_.push_back("the source has no calibration: no camera.yaml written");
    }
    const std::string list = std::string(kHeader) + "# timestamp filename\n";
    SIGHTLINE_RETURN_IF_ERROR(rgb_.Open(JoinPath(folder_, "rgb.txt"), list, s_.sync));
    SIGHTLINE_RETURN_IF_ERROR(depth_.Open(JoinPath(folder_, "depth.txt"), list, s_.sync));
    return pairs_.Open(JoinPath(folder_, "associations.txt"),
                       std::string(kHeader) + "# t_rgb rgb_file t_depth depth_file\n", s_.sync);
  }

  Status Write(const Frame& frame, int64_t index) override {
    const auto* rgbd = std::get_if<RgbdFrame>(&frame);
    if (rgbd == nullptr) return InvalidArgument("TUM RGB-D recording got a non-RGB-D frame");
    if (rgbd->color.empty() || rgbd->depth_m.empty()) {
      return InvalidArgument("frame " + std::to_string(rgbd->stamp.sequence_id) +
                             " lacks colour or depth; TUM RGB-D stores both");
    }
    const std::string name = FrameName(index);
    const std::string t = Number("%.6f", rgbd->stamp.sensor_time_s);
    SIGHTLINE_RETURN_IF_ERROR(WritePngPair(JoinPath(folder_, "rgb/" + name), rgbd->color,
                                           JoinPath(folder_, "depth/" + name),
                                           DepthToTum(rgbd->depth_m), s_, &bytes_));
    // The reader takes the pairs from associations.txt: only that line needs to be durable
    // before the next frame (one fsync per frame instead of three).
    SIGHTLINE_RETURN_IF_ERROR(AppendCounted(&rgb_, t + " rgb/" + name, &bytes_, false));
    SIGHTLINE_RETURN_IF_ERROR(AppendCounted(&depth_, t + " depth/" + name, &bytes_, false));
    return AppendCounted(&pairs_, t + " rgb/" + name + " " + t + " depth/" + name, &bytes_);
  }

  const std::string& folder() const override { return folder_; }
  const char* format() const override { return "TUM RGB-D"; }

 private:
  static cv::Mat DepthToTum(const cv::Mat& depth_m) {
    cv::Mat raw(depth_m.size(), CV_16UC1);
    for (int v = 0; v < depth_m.rows; ++v) {
      const float* z = depth_m.ptr<float>(v);
      uint16_t* out = raw.ptr<uint16_t>(v);
      for (int u = 0; u < depth_m.cols; ++u) {
        const double value =
            std::isfinite(z[u]) && z[u] > 0 ? std::round(z[u] * kTumDepthScale) : 0;
        out[u] = static_cast<uint16_t>(value > 65535 ? 0 : value);
      }
    }
    return raw;
  }

  std::string folder_;
  FrameWriterSettings s_;
  AppendOnlyFile rgb_, depth_, pairs_;
};

// An image folder: NNNNNN.png and times.txt with "time filename" lines (which define the frames).
class ImageFolderWriter : public FrameWriter {
 public:
  ImageFolderWriter(std::string folder, FrameWriterSettings s)
      : folder_(std::move(folder)), s_(s) {}

  Status Init(const SourceInfo& info) {
    SIGHTLINE_RETURN_IF_ERROR(MakeDirs(folder_));
    if (info.camera) {
      CameraFile file{*info.camera, std::nullopt, std::nullopt, std::nullopt};
      if (info.rate_hz > 0) file.rate_hz = info.rate_hz;
      SIGHTLINE_RETURN_IF_ERROR(WriteCameraYaml(file, JoinPath(folder_, kCameraYamlName)));
    } else {
      notes_.push_back("the source has no calibration: no camera.yaml written");
    }
    return times_.Open(JoinPath(folder_, "times.txt"),
                       std::string(kHeader) + "# timestamp filename\n", s_.sync);
  }

  Status Write(const Frame& frame, int64_t index) override {
    const auto* mono = std::get_if<MonoFrame>(&frame);
    if (mono == nullptr) return InvalidArgument("image-folder recording got a non-mono frame");
    const std::string name = FrameName(index);
    SIGHTLINE_RETURN_IF_ERROR(WritePng(JoinPath(folder_, name), mono->image, s_, &bytes_));
    return AppendCounted(&times_, Number("%.6f", mono->stamp.sensor_time_s) + " " + name, &bytes_);
  }

  const std::string& folder() const override { return folder_; }
  const char* format() const override { return "image folder"; }

 private:
  std::string folder_;
  FrameWriterSettings s_;
  AppendOnlyFile times_;
};

// EuRoC MAV: mav0/cam0 and mav0/cam1, each data/<ns>.png, data.csv and sensor.yaml. The reader
// pairs equal timestamps, so a pair listed in one data.csv only is skipped, not an error.
class EurocStereoWriter : public FrameWriter {
 public:
  EurocStereoWriter(std::string folder, FrameWriterSettings s)
      : folder_(std::move(folder)), s_(s) {}

  Status Init(const SourceInfo& info) {
    StereoRig rig;
    if (info.stereo) {
      rig = *info.stereo;
    } else {
      for (PinholeCamera* c : {&rig.left, &rig.right}) {
        c->width = info.width;
        c->height = info.height;
        c->fx = c->fy = info.width;
        c->cx = (info.width - 1) / 2.0;
        c->cy = (info.height - 1) / 2.0;
      }
      rig.right_from_left.translation() = Eigen::Vector3d(-0.1, 0, 0);
      notes_.push_back(
          "the source has no stereo calibration: sensor.yaml holds a nominal one "
          "(focal length = width, baseline 0.1 m)");
    }
    if (rig.rectified) {
      notes_.push_back(
          "the source's images were rectified; EuRoC stores the rig as "
          "unrectified (zero distortion), so readers rectify again (a no-op)");
    }
    const Eigen::Isometry3d body_from_right = rig.right_from_left.inverse();
    const double rate = info.rate_hz;
    SIGHTLINE_RETURN_IF_ERROR(
        InitCamera("cam0", rig.left, Eigen::Isometry3d::Identity(), rate, &left_));
    return InitCamera("cam1", rig.right, body_from_right, rate, &right_);
  }

  Status Write(const Frame& frame, int64_t) override {
    const auto* stereo = std::get_if<StereoFrame>(&frame);
    if (stereo == nullptr) return InvalidArgument("EuRoC recording got a non-stereo frame");
    const long long ns = std::llround(stereo->stamp.sensor_time_s * 1e9);
    const std::string name = std::to_string(ns) + ".png";
    SIGHTLINE_RETURN_IF_ERROR(WritePngPair(Data("cam0", name), stereo->left, Data("cam1", name),
                                           stereo->right, s_, &bytes_));
    const std::string line = std::to_string(ns) + "," + name;
    // The reader pairs equal times; a cam1 line lost without its cam0 line only unpairs it.
    SIGHTLINE_RETURN_IF_ERROR(AppendCounted(&right_, line, &bytes_, false));
    return AppendCounted(&left_, line, &bytes_);
  }

  const std::string& folder() const override { return folder_; }
  const char* format() const override { return "EuRoC MAV"; }

 private:
  std::string Data(const char* cam, const std::string& name) const {
    return JoinPath(folder_, std::string("mav0/") + cam + "/data/" + name);
  }

  Status InitCamera(const char* cam, const PinholeCamera& c, const Eigen::Isometry3d& body_from_cam,
                    double rate_hz, AppendOnlyFile* csv) {
    const std::string dir = JoinPath(folder_, std::string("mav0/") + cam);
    SIGHTLINE_RETURN_IF_ERROR(MakeDirs(JoinPath(dir, "data")));
    std::ostringstream yaml;
    yaml.precision(17);
    yaml << "%YAML:1.0\nsensor_type: camera\ncomment: Sightline recording\nT_BS:\n"
         << "  cols: 4\n  rows: 4\n  data: [";
    const Eigen::Matrix4d& m = body_from_cam.matrix();
    for (int i = 0; i < 16; ++i) yaml << (i ? ", " : "") << m(i / 4, i % 4);
    yaml << "]\n";
    if (rate_hz > 0) yaml << "rate_hz: " << rate_hz << "\n";
    yaml << "resolution: [" << c.width << ", " << c.height << "]\ncamera_model: pinhole\n"
         << "intrinsics: [" << c.fx << ", " << c.fy << ", " << c.cx << ", " << c.cy << "]\n"
         << "distortion_model: radial-tangential\ndistortion_coefficients: [";
    for (int i = 0; i < 5; ++i) yaml << (i ? ", " : "") << c.distortion[i];
    yaml << "]\n";
    const std::string text = yaml.str();
    SIGHTLINE_RETURN_IF_ERROR(WriteFileAtomically(
        JoinPath(dir, "sensor.yaml"), std::vector<uint8_t>(text.begin(), text.end()), s_.sync));
    return csv->Open(JoinPath(dir, "data.csv"), "#timestamp [ns],filename\n", s_.sync);
  }

  std::string folder_;
  FrameWriterSettings s_;
  AppendOnlyFile left_, right_;
};

template <typename W>
StatusOr<std::unique_ptr<FrameWriter>> Make(const std::string& folder, const SourceInfo& info,
                                            const FrameWriterSettings& settings) {
  auto writer = std::make_unique<W>(folder, settings);
  SIGHTLINE_RETURN_IF_ERROR(writer->Init(info));
  return std::unique_ptr<FrameWriter>(std::move(writer));
}

}  // namespace

const char* SensorFolderName(SourceKind kind) {
  switch (kind) {
    case SourceKind::kRgbd:
      return "rgbd";
    case SourceKind::kStereo:
      return "stereo";
    case SourceKind::kMono:
      return "mono";
    case SourceKind::kCloud:
      return "cloud";
  }
  return "sensor";
}

StatusOr<std::unique_ptr<FrameWriter>> CreateFrameWriter(const std::string& dir,
                                                         const SourceInfo& info,
                                                         const FrameWriterSettings& settings) {
  const std::string folder = JoinPath(dir, SensorFolderName(info.kind));
  switch (info.kind) {
    case SourceKind::kRgbd:
      return Make<TumRgbdWriter>(folder, info, settings);
    case SourceKind::kStereo:
      return Make<EurocStereoWriter>(folder, info, settings);
    case SourceKind::kMono:
      return Make<ImageFolderWriter>(folder, info, settings);
    case SourceKind::kCloud:
      break;
  }
  return InvalidArgument("point-cloud sources cannot be recorded yet (RGB-D, stereo and mono can)");
}

}  // namespace sightline
