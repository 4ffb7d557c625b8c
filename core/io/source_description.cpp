#include "core/io/source_description.h"

#include <cstdio>
#include <sstream>

#include "core/common/json_writer.h"

namespace sightline {
namespace {

std::string Printf(const char* format, double value) {
  char buffer[64];
  std::snprintf(buffer, sizeof(buffer), format, value);
  return buffer;
}

std::string CameraText(const PinholeCamera& c) {
  std::string text = "fx=" + Printf("%.6g", c.fx) + " fy=" + Printf("%.6g", c.fy) +
                     " cx=" + Printf("%.6g", c.cx) + " cy=" + Printf("%.6g", c.cy);
  if (c.HasDistortion()) {
    text += ", distortion k1 k2 p1 p2 k3 =";
    for (double d : c.distortion) {
      text += ' ';  // Appending separately avoids a GCC 12 -Wrestrict false positive.
      text += Printf("%.6g", d);
    }
  } else {
    text += ", no distortion";
  }
  return text;
}

void CameraJson(const PinholeCamera& c, JsonWriter* w) {
  w->BeginObject();
  w->Key("width").Int(c.width);
  w->Key("height").Int(c.height);
  w->Key("fx").Double(c.fx);
  w->Key("fy").Double(c.fy);
  w->Key("cx").Double(c.cx);
  w->Key("cy").Double(c.cy);
  w->Key("distortion").BeginArray();
  for (double d : c.distortion) w->Double(d);
  w->EndArray();
  w->EndObject();
}

const char* FrameNoun(SourceKind kind, bool plural) {
  switch (kind) {
    case SourceKind::kRgbd:
      return plural ? "RGB-D frames" : "RGB-D frame";
    case SourceKind::kStereo:
      return plural ? "stereo pairs" : "stereo pair";
    case SourceKind::kMono:
      return plural ? "images" : "image";
    case SourceKind::kCloud:
      return plural ? "point clouds" : "point cloud";
  }
  return plural ? "frames" : "frame";
}

}  // namespace

std::string DescribeFrameCount(const SourceInfo& info) {
  if (info.live || info.frame_count < 0) return "live";
  return std::to_string(info.frame_count) + " " + FrameNoun(info.kind, info.frame_count != 1);
}

std::string DescribeSourceText(const Source& source) {
  const SourceInfo& info = source.info();
  std::ostringstream out;
  out << "format: " << info.format << "\n";
  out << "path: " << info.path << "\n";
  out << "kind: " << SourceKindName(info.kind) << "\n";
  out << "frames: " << DescribeFrameCount(info) << "\n";
  out << "resolution: " << info.width << "x" << info.height << "\n";
  if (!info.live) out << "duration: " << Printf("%.3f", info.duration_s) << " s\n";
  out << "rate: " << (info.rate_hz > 0 ? Printf("%.4g", info.rate_hz) + " Hz" : "unknown") << "\n";
  if (info.stereo) {
    out << "left camera: " << CameraText(info.stereo->left) << "\n";
    out << "right camera: " << CameraText(info.stereo->right) << "\n";
    out << "stereo baseline: " << Printf("%.4f", info.stereo->BaselineM()) << " m ("
        << (info.stereo->rectified ? "rectified" : "not rectified") << ")\n";
  } else if (info.camera) {
    out << "camera: " << CameraText(*info.camera) << "\n";
  } else {
    out << "camera: unknown\n";
  }
  if (info.rgbd) {
    out << "depth scale: " << Printf("%g", info.rgbd->depth_scale) << " units per metre\n";
  }
  if (const Trajectory* gt = source.ground_truth(); gt != nullptr && !gt->empty()) {
    out << "ground truth: yes (" << gt->size() << " poses, path length "
        << Printf("%.2f", gt->LengthM()) << " m, " << Printf("%.2f", gt->DurationS()) << " s)\n";
  } else {
    out << "ground truth: no\n";
  }
  if (!info.notes.empty()) {
    out << "notes:\n";
    for (const std::string& note : info.notes) out << "  - " << note << "\n";
  }
  return out.str();
}

std::string DescribeSourceJson(const Source& source) {
  const SourceInfo& info = source.info();
  JsonWriter w;
  w.BeginObject();
  w.Key("format").String(info.format);
  w.Key("path").String(info.path);
  w.Key("kind").String(SourceKindName(info.kind));
  w.Key("frames").Int(info.frame_count);
  w.Key("frames_text").String(DescribeFrameCount(info));
  w.Key("width").Int(info.width);
  w.Key("height").Int(info.height);
  w.Key("duration_s").Double(info.duration_s);
  if (info.rate_hz > 0) {
    w.Key("rate_hz").Double(info.rate_hz);
  } else {
    w.Key("rate_hz").Null();
  }
  w.Key("live").Bool(info.live);
  w.Key("seekable").Bool(info.seekable);
  w.Key("camera");
  if (info.camera) {
    CameraJson(*info.camera, &w);
  } else {
    w.Null();
  }
  w.Key("stereo");
  if (info.stereo) {
    w.BeginObject();
    w.Key("baseline_m").Double(info.stereo->BaselineM());
    w.Key("rectified").Bool(info.stereo->rectified);
    w.Key("left");
    CameraJson(info.stereo->left, &w);
    w.Key("right");
    CameraJson(info.stereo->right, &w);
    w.EndObject();
  } else {
    w.Null();
  }
  w.Key("depth_scale");
  if (info.rgbd) {
    w.Double(info.rgbd->depth_scale);
  } else {
    w.Null();
  }
  w.Key("ground_truth").BeginObject();
  const Trajectory* gt = source.ground_truth();
  const bool has_gt = gt != nullptr && !gt->empty();
  w.Key("present").Bool(has_gt);
  w.Key("poses").Int(has_gt ? static_cast<long long>(gt->size()) : 0);
  w.Key("path_length_m").Double(has_gt ? gt->LengthM() : 0.0);
  w.Key("duration_s").Double(has_gt ? gt->DurationS() : 0.0);
  w.EndObject();
  w.Key("notes").BeginArray();
  for (const std::string& note : info.notes) w.String(note);
  w.EndArray();
  w.EndObject();
  return w.str() + "\n";
}

}  // namespace sightline
