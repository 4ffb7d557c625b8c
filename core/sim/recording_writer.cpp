#include "core/sim/recording_writer.h"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <opencv2/imgcodecs.hpp>

#include "core/common/text_file.h"
#include "core/io/camera_yaml.h"

namespace sightline::sim {
namespace {

constexpr double kDepthScale = 5000;  // TUM: 16-bit value / 5000 = metres.

std::string FrameName(int frame) {
  char name[32];
  std::snprintf(name, sizeof(name), "%06d.png", frame);
  return name;
}

std::string Time(double t) {
  char text[32];
  std::snprintf(text, sizeof(text), "%.6f", t);
  return text;
}

Status MakeDirs(const std::string& path) {
  std::error_code ec;
  std::filesystem::create_directories(path, ec);
  if (ec) return Unavailable("cannot create folder " + path + ": " + ec.message());
  return Status::Ok();
}

std::string ProjectionLine(const char* label, const PinholeCamera& c, double tx) {
  char line[256];
  std::snprintf(line, sizeof(line),
                "%s: %.12e %.12e %.12e %.12e %.12e %.12e %.12e %.12e %.12e %.12e %.12e %.12e\n",
                label, c.fx, 0.0, c.cx, c.fx * tx, 0.0, c.fy, c.cy, 0.0, 0.0, 0.0, 1.0, 0.0);
  return line;
}

}  // namespace

std::string TumLine(double time_s, const Eigen::Isometry3d& pose) {
  const Eigen::Quaterniond q(pose.linear());
  const Eigen::Vector3d t = pose.translation();
  char line[256];
  std::snprintf(line, sizeof(line), "%.6f %.9f %.9f %.9f %.9f %.9f %.9f %.9f\n", time_s, t.x(),
                t.y(), t.z(), q.x(), q.y(), q.z(), q.w());
  return line;
}

std::string KittiLine(const Eigen::Isometry3d& pose) {
  const Eigen::Matrix4d& m = pose.matrix();
  std::string line;
  char number[40];
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 4; ++c) {
      std::snprintf(number, sizeof(number), "%s%.9e", r == 0 && c == 0 ? "" : " ", m(r, c));
      line += number;
    }
  }
  return line + "\n";
}

StatusOr<std::unique_ptr<RecordingWriter>> RecordingWriter::Create(const RecordingSetup& setup) {
  std::unique_ptr<RecordingWriter> w(new RecordingWriter());
  w->setup_ = setup;
  const std::string& dir = setup.dir;
  SIGHTLINE_RETURN_IF_ERROR(MakeDirs(dir));
  const std::string header = "# Sightline simulator (see core/sim/README.md)\n";
  if (setup.rgbd_camera) {
    SIGHTLINE_RETURN_IF_ERROR(MakeDirs(JoinPath(dir, "rgbd/rgb")));
    SIGHTLINE_RETURN_IF_ERROR(MakeDirs(JoinPath(dir, "rgbd/depth")));
    CameraFile camera{*setup.rgbd_camera, kDepthScale, setup.rgbd_max_depth_m, setup.rate_hz};
    SIGHTLINE_RETURN_IF_ERROR(WriteCameraYaml(camera, JoinPath(dir, "rgbd/camera.yaml")));
    w->files_.push_back("rgbd/camera.yaml");
    SIGHTLINE_RETURN_IF_ERROR(
        w->OpenIndex("rgbd/rgb.txt", &w->rgb_txt_, header + "# timestamp filename\n"));
    SIGHTLINE_RETURN_IF_ERROR(
        w->OpenIndex("rgbd/depth.txt", &w->depth_txt_, header + "# timestamp filename\n"));
    SIGHTLINE_RETURN_IF_ERROR(w->OpenIndex("rgbd/associations.txt", &w->associations_txt_,
                                           header + "# t_rgb rgb_file t_depth depth_file\n"));
    SIGHTLINE_RETURN_IF_ERROR(w->OpenIndex("rgbd/groundtruth.txt", &w->rgbd_gt_,
                                           header + "# colour camera (optical frame) in the map "
                                                    "frame\n# timestamp tx ty tz qx qy qz qw\n"));
  }
  if (setup.stereo_rig) {
    SIGHTLINE_RETURN_IF_ERROR(MakeDirs(JoinPath(dir, "stereo/image_0")));
    SIGHTLINE_RETURN_IF_ERROR(MakeDirs(JoinPath(dir, "stereo/image_1")));
    const StereoRig& rig = *setup.stereo_rig;
    std::ofstream calib(JoinPath(dir, "stereo/calib.txt"));
    // KITTI: P1's fourth column is -fx * baseline (the right camera at +baseline along x).
    calib << ProjectionLine("P0", rig.left, 0.0)
          << ProjectionLine("P1", rig.right, rig.right_from_left.translation().x());
    if (!calib) return Unavailable("cannot write " + JoinPath(dir, "stereo/calib.txt"));
    w->files_.push_back("stereo/calib.txt");
    SIGHTLINE_RETURN_IF_ERROR(w->OpenIndex("stereo/times.txt", &w->stereo_times_, ""));
    SIGHTLINE_RETURN_IF_ERROR(w->OpenIndex("stereo/poses.txt", &w->stereo_poses_, ""));
    SIGHTLINE_RETURN_IF_ERROR(w->OpenIndex(
        "stereo/groundtruth.txt", &w->stereo_gt_,
        header +
            "# left camera (optical frame) in the map frame\n# timestamp tx ty tz qx qy qz qw\n"));
  }
  if (setup.mono_camera) {
    SIGHTLINE_RETURN_IF_ERROR(MakeDirs(JoinPath(dir, "mono")));
    CameraFile camera{*setup.mono_camera, std::nullopt, std::nullopt, setup.rate_hz};
    SIGHTLINE_RETURN_IF_ERROR(WriteCameraYaml(camera, JoinPath(dir, "mono/camera.yaml")));
    w->files_.push_back("mono/camera.yaml");
    SIGHTLINE_RETURN_IF_ERROR(
        w->OpenIndex("mono/times.txt", &w->mono_times_, header + "# timestamp filename\n"));
    SIGHTLINE_RETURN_IF_ERROR(w->OpenIndex(
        "mono/groundtruth.txt", &w->mono_gt_,
        header + "# camera (optical frame) in the map frame\n# timestamp tx ty tz qx qy qz qw\n"));
  }
  return w;
}

Status RecordingWriter::OpenIndex(const std::string& relative, std::ofstream* out,
                                  const std::string& header) {
  const std::string path = JoinPath(setup_.dir, relative);
  out->open(path, std::ios::binary | std::ios::trunc);
  if (!*out) return Unavailable("cannot write " + path);
  *out << header;
  files_.push_back(relative);
  return Flush(out, relative);
}

Status RecordingWriter::Flush(std::ofstream* out, const std::string& relative) {
  out->flush();
  if (!*out)
    return Unavailable("write to " + JoinPath(setup_.dir, relative) + " failed (disk full?)");
  return Status::Ok();
}

Status RecordingWriter::WritePng(const std::string& relative, const cv::Mat& image) {
  const std::string path = JoinPath(setup_.dir, relative);
  bool written = false;
  try {
    written = cv::imwrite(path, image, {cv::IMWRITE_PNG_COMPRESSION, setup_.png_compression});
  } catch (const cv::Exception& e) {
    return Unavailable("cannot write " + path + ": " + e.what());
  }
  if (!written) return Unavailable("cannot write " + path);
  ++images_;
  return Status::Ok();
}

Status RecordingWriter::WriteRgbd(int frame, double time_s, const cv::Mat& color,
                                  const cv::Mat& depth_m,
                                  const Eigen::Isometry3d& world_from_camera) {
  if (!setup_.rgbd_camera) return FailedPrecondition("recording has no rgbd sensor");
  const std::string name = FrameName(frame), t = Time(time_s);
  cv::Mat raw(depth_m.size(), CV_16UC1);
  for (int v = 0; v < depth_m.rows; ++v) {
    const float* z = depth_m.ptr<float>(v);
    uint16_t* out = raw.ptr<uint16_t>(v);
    for (int u = 0; u < depth_m.cols; ++u) {
      const double value = std::isfinite(z[u]) && z[u] > 0 ? std::round(z[u] * kDepthScale) : 0;
      out[u] = static_cast<uint16_t>(value > 65535 ? 0 : value);
    }
  }
  SIGHTLINE_RETURN_IF_ERROR(WritePng("rgbd/rgb/" + name, color));
  SIGHTLINE_RETURN_IF_ERROR(WritePng("rgbd/depth/" + name, raw));
  rgb_txt_ << t << " rgb/" << name << "\n";
  depth_txt_ << t << " depth/" << name << "\n";
  associations_txt_ << t << " rgb/" << name << " " << t << " depth/" << name << "\n";
  rgbd_gt_ << TumLine(time_s, world_from_camera);
  SIGHTLINE_RETURN_IF_ERROR(Flush(&rgb_txt_, "rgbd/rgb.txt"));
  SIGHTLINE_RETURN_IF_ERROR(Flush(&depth_txt_, "rgbd/depth.txt"));
  SIGHTLINE_RETURN_IF_ERROR(Flush(&associations_txt_, "rgbd/associations.txt"));
  return Flush(&rgbd_gt_, "rgbd/groundtruth.txt");
}

Status RecordingWriter::WriteStereo(int frame, double time_s, const cv::Mat& left,
                                    const cv::Mat& right,
                                    const Eigen::Isometry3d& world_from_left) {
  if (!setup_.stereo_rig) return FailedPrecondition("recording has no stereo sensor");
  const std::string name = FrameName(frame);
  SIGHTLINE_RETURN_IF_ERROR(WritePng("stereo/image_0/" + name, left));
  SIGHTLINE_RETURN_IF_ERROR(WritePng("stereo/image_1/" + name, right));
  if (!first_left_from_world_) first_left_from_world_ = world_from_left.inverse();
  stereo_times_ << Time(time_s) << "\n";
  stereo_poses_ << KittiLine(*first_left_from_world_ * world_from_left);
  stereo_gt_ << TumLine(time_s, world_from_left);
  SIGHTLINE_RETURN_IF_ERROR(Flush(&stereo_times_, "stereo/times.txt"));
  SIGHTLINE_RETURN_IF_ERROR(Flush(&stereo_poses_, "stereo/poses.txt"));
  return Flush(&stereo_gt_, "stereo/groundtruth.txt");
}

Status RecordingWriter::WriteMono(int frame, double time_s, const cv::Mat& image,
                                  const Eigen::Isometry3d& world_from_camera) {
  if (!setup_.mono_camera) return FailedPrecondition("recording has no mono sensor");
  const std::string name = FrameName(frame);
  SIGHTLINE_RETURN_IF_ERROR(WritePng("mono/" + name, image));
  mono_times_ << Time(time_s) << " " << name << "\n";
  mono_gt_ << TumLine(time_s, world_from_camera);
  SIGHTLINE_RETURN_IF_ERROR(Flush(&mono_times_, "mono/times.txt"));
  return Flush(&mono_gt_, "mono/groundtruth.txt");
}

Status RecordingWriter::Close() {
  for (std::ofstream* f : {&rgb_txt_, &depth_txt_, &associations_txt_, &rgbd_gt_, &stereo_times_,
                           &stereo_poses_, &stereo_gt_, &mono_times_, &mono_gt_}) {
    if (f->is_open()) {
      f->close();
      if (f->fail()) return Unavailable("closing an index file in " + setup_.dir + " failed");
    }
  }
  return Status::Ok();
}

std::vector<std::string> RecordingWriter::Files() const { return files_; }

}  // namespace sightline::sim
