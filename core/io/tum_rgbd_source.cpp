#include "core/io/tum_rgbd_source.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>

#include "core/common/text_file.h"
#include "core/io/camera_yaml.h"
#include "core/io/file_listing.h"
#include "core/io/image_loading.h"
#include "core/io/timed_file_list.h"

namespace sightline {
namespace {

// Reads associations.txt: "t_rgb rgb_file t_depth depth_file" per line.
StatusOr<std::vector<TumAssociation>> ReadAssociations(const std::string& path) {
  auto lines = ReadDataLines(path);
  if (!lines.ok()) return lines.status();
  std::vector<TumAssociation> pairs;
  for (const DataLine& line : *lines) {
    const std::vector<std::string> f = SplitFields(line.text);
    const std::string where = path + " line " + std::to_string(line.number);
    if (f.size() < 4) {
      return ParseError(where + ": expected 't_rgb rgb_file t_depth depth_file', found " +
                        std::to_string(f.size()) + " field(s) (truncated line?)");
    }
    auto t_rgb = ParseNumbers(DataLine{line.number, f[0]}, 1, path);
    if (!t_rgb.ok()) return t_rgb.status();
    auto t_depth = ParseNumbers(DataLine{line.number, f[2]}, 1, path);
    if (!t_depth.ok()) return t_depth.status();
    if (!pairs.empty()) {
      SIGHTLINE_RETURN_IF_ERROR(
          CheckTimeIncreases(pairs.back().rgb.time_s, (*t_rgb)[0], path, line.number));
    }
    SIGHTLINE_RETURN_IF_ERROR(CheckListedPath(f[1], path, line.number));
    SIGHTLINE_RETURN_IF_ERROR(CheckListedPath(f[3], path, line.number));
    pairs.push_back({{(*t_rgb)[0], f[1], line.number}, {(*t_depth)[0], f[3], line.number}});
  }
  return pairs;
}

std::string DepthNote(double depth_scale) {
  char buffer[96];
  std::snprintf(buffer, sizeof(buffer), "depth: 16-bit PNG / %g = metres, 0 = no reading (NaN)",
                depth_scale);
  return buffer;
}

}  // namespace

std::vector<TumAssociation> AssociateByTime(const std::vector<TimedFile>& rgb,
                                            const std::vector<TimedFile>& depth, double max_dt_s) {
  struct Candidate {
    double dt;
    size_t rgb, depth;
  };
  std::vector<size_t> depth_order(depth.size());
  for (size_t i = 0; i < depth.size(); ++i) depth_order[i] = i;
  std::sort(depth_order.begin(), depth_order.end(),
            [&](size_t a, size_t b) { return depth[a].time_s < depth[b].time_s; });
  std::vector<Candidate> candidates;
  for (size_t r = 0; r < rgb.size(); ++r) {
    const double t = rgb[r].time_s;
    auto it = std::lower_bound(depth_order.begin(), depth_order.end(), t - max_dt_s,
                               [&](size_t d, double v) { return depth[d].time_s < v; });
    for (; it != depth_order.end() && depth[*it].time_s <= t + max_dt_s; ++it) {
      candidates.push_back({std::abs(depth[*it].time_s - t), r, *it});
    }
  }
  std::stable_sort(candidates.begin(), candidates.end(),
                   [](const Candidate& a, const Candidate& b) { return a.dt < b.dt; });
  std::vector<bool> rgb_used(rgb.size(), false), depth_used(depth.size(), false);
  std::vector<TumAssociation> pairs;
  for (const Candidate& c : candidates) {
    if (rgb_used[c.rgb] || depth_used[c.depth]) continue;
    rgb_used[c.rgb] = depth_used[c.depth] = true;
    pairs.push_back({rgb[c.rgb], depth[c.depth]});
  }
  std::sort(pairs.begin(), pairs.end(), [](const TumAssociation& a, const TumAssociation& b) {
    return a.rgb.time_s < b.rgb.time_s;
  });
  return pairs;
}

std::optional<int> DetectFreiburgCamera(const std::string& text) {
  std::string lower = text;
  for (char& c : lower) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  for (const std::string key : {"freiburg", "fr"}) {
    for (size_t pos = lower.find(key); pos != std::string::npos; pos = lower.find(key, pos + 1)) {
      // "fr" must start a word ("tum_fr1", not "xfr1"); "freiburg" may sit anywhere.
      if (key == "fr" && pos > 0 && std::isalpha(static_cast<unsigned char>(lower[pos - 1]))) {
        continue;
      }
      const size_t digit = pos + key.size();
      if (digit >= lower.size() || lower[digit] < '1' || lower[digit] > '3') continue;
      if (digit + 1 < lower.size() && std::isdigit(static_cast<unsigned char>(lower[digit + 1]))) {
        continue;
      }
      return lower[digit] - '0';
    }
  }
  return std::nullopt;
}

PinholeCamera TumCamera(int freiburg) {
  PinholeCamera c;
  c.width = 640;
  c.height = 480;
  switch (freiburg) {
    case 1:
      c.fx = 517.3, c.fy = 516.5, c.cx = 318.6, c.cy = 255.3;
      c.distortion = {0.2624, -0.9531, -0.0054, 0.0026, 1.1633};
      break;
    case 2:
      c.fx = 520.9, c.fy = 521.0, c.cx = 325.1, c.cy = 249.7;
      c.distortion = {0.2312, -0.7849, -0.0033, -0.0001, 0.9172};
      break;
    case 3:
      c.fx = 535.4, c.fy = 539.2, c.cx = 320.1, c.cy = 247.6;
      break;
    default:
      c.fx = 525.0, c.fy = 525.0, c.cx = 319.5, c.cy = 239.5;
  }
  return c;
}

Status TumRgbdSource::Open() {
  if (!DirectoryExists(folder_)) return NotFound(folder_ + ": no such folder");
  SourceInfo info;
  info.format = "TUM RGB-D";
  info.path = folder_;
  info.kind = SourceKind::kRgbd;

  // 1. Colour/depth pairs.
  std::vector<TumAssociation> pairs;
  std::string assoc_path;
  for (const char* name : {"associations.txt", "associate.txt"}) {
    if (PathExists(JoinPath(folder_, name))) {
      assoc_path = JoinPath(folder_, name);
      break;
    }
  }
  if (!assoc_path.empty()) {
    auto read = ReadAssociations(assoc_path);
    if (!read.ok()) return read.status();
    pairs = std::move(*read);
    info.notes.push_back("colour/depth pairs from " + BaseName(assoc_path));
  } else {
    auto rgb = ReadTimedFileList(JoinPath(folder_, "rgb.txt"));
    if (!rgb.ok()) return rgb.status();
    auto depth = ReadTimedFileList(JoinPath(folder_, "depth.txt"));
    if (!depth.ok()) return depth.status();
    pairs = AssociateByTime(*rgb, *depth, 0.02);
    std::string note = "colour/depth paired by nearest timestamp (at most 0.02 s apart)";
    if (pairs.size() < rgb->size()) {
      note += "; " + std::to_string(rgb->size() - pairs.size()) + " of " +
              std::to_string(rgb->size()) + " colour images have no depth partner and are skipped";
    }
    info.notes.push_back(note);
  }
  // The lists' readers checked that times increase and files stay inside the folder.
  if (pairs.empty()) return ParseError(folder_ + ": no colour/depth pairs listed");
  for (TumAssociation& p : pairs) {
    p.rgb.file = JoinPath(folder_, p.rgb.file);
    p.depth.file = JoinPath(folder_, p.depth.file);
    SIGHTLINE_RETURN_IF_ERROR(CheckFileExists(p.rgb.file));
    SIGHTLINE_RETURN_IF_ERROR(CheckFileExists(p.depth.file));
  }

  // 2. Camera: camera.yaml, else the sequence name, else the ROS default.
  RgbdCalibration calibration;
  calibration.depth_scale = 5000;
  bool camera_from_file = false;
  std::optional<double> nominal_rate;
  if (const std::string yaml = JoinPath(folder_, kCameraYamlName); PathExists(yaml)) {
    auto file = ReadCameraYaml(yaml);
    if (!file.ok()) return file.status();
    calibration.color = file->camera;
    if (file->depth_scale) calibration.depth_scale = *file->depth_scale;
    if (file->max_depth_m) calibration.max_depth_m = *file->max_depth_m;
    nominal_rate = file->rate_hz;
    camera_from_file = true;
    info.notes.push_back("intrinsics and depth scale from camera.yaml");
  } else {
    std::optional<int> freiburg;
    std::string origin;
    for (const char* list : {"rgb.txt", "depth.txt", "groundtruth.txt"}) {
      for (const std::string& comment : ReadCommentLines(JoinPath(folder_, list))) {
        if (comment.find("file:") == std::string::npos) continue;
        freiburg = DetectFreiburgCamera(comment);
        if (freiburg) origin = std::string("the header of ") + list;
        break;
      }
      if (freiburg) break;
    }
    if (!freiburg) {
      freiburg = DetectFreiburgCamera(BaseName(folder_));
      if (freiburg) origin = "the folder name";
    }
    calibration.color = TumCamera(freiburg.value_or(0));
    if (freiburg) {
      info.notes.push_back("intrinsics of TUM freiburg" + std::to_string(*freiburg) +
                           " (sequence found in " + origin + ")");
    } else {
      info.notes.push_back(
          "sequence not recognised: ROS default intrinsics 525/525/319.5/239.5; put a "
          "camera.yaml beside rgb.txt for exact ones");
    }
  }
  info.notes.push_back(DepthNote(calibration.depth_scale));

  // 3. Size from the first pair, which also proves the images decode.
  auto color = LoadColorImage(pairs.front().rgb.file);
  if (!color.ok()) return color.status();
  auto depth = LoadDepthImage(pairs.front().depth.file, calibration.depth_scale);
  if (!depth.ok()) return depth.status();
  if (depth->size() != color->size()) {
    return ParseError(pairs.front().depth.file + ": depth image is " + std::to_string(depth->cols) +
                      "x" + std::to_string(depth->rows) + " but the colour image is " +
                      std::to_string(color->cols) + "x" + std::to_string(color->rows));
  }
  info.width = color->cols;
  info.height = color->rows;
  PinholeCamera& camera = calibration.color;
  if (camera.width != info.width || camera.height != info.height) {
    if (camera_from_file) {
      return ParseError(JoinPath(folder_, kCameraYamlName) + ": camera is " +
                        std::to_string(camera.width) + "x" + std::to_string(camera.height) +
                        " but the images are " + std::to_string(info.width) + "x" +
                        std::to_string(info.height));
    }
    camera = camera.Scaled(info.width, info.height);
    info.notes.push_back("intrinsics scaled from 640x480 to the image size");
  }
  info.camera = camera;
  info.rgbd = calibration;
  if (nominal_rate) info.rate_hz = *nominal_rate;

  // 4. Ground truth: pose of the colour camera in the mocap world.
  std::optional<Trajectory> ground_truth;
  if (const std::string gt_path = JoinPath(folder_, "groundtruth.txt"); PathExists(gt_path)) {
    auto gt = ReadTumTrajectory(gt_path);
    if (!gt.ok()) return gt.status();
    size_t covered = 0;
    for (const TumAssociation& p : pairs) covered += gt->Nearest(p.rgb.time_s, 0.02) ? 1 : 0;
    if (covered < pairs.size()) {
      info.notes.push_back("ground truth within 0.02 s for " + std::to_string(covered) + " of " +
                           std::to_string(pairs.size()) + " frames");
    }
    ground_truth = std::move(*gt);
  }

  std::vector<double> times;
  times.reserve(pairs.size());
  for (const TumAssociation& p : pairs) times.push_back(p.rgb.time_s);
  depth_scale_ = calibration.depth_scale;
  pairs_ = std::move(pairs);
  return Commit(std::move(info), std::move(times), std::move(ground_truth));
}

StatusOr<Frame> TumRgbdSource::Load(int64_t index) {
  const TumAssociation& pair = pairs_[static_cast<size_t>(index)];
  RgbdFrame frame;
  auto color = LoadColorImage(pair.rgb.file);
  if (!color.ok()) return color.status();
  auto depth = LoadDepthImage(pair.depth.file, depth_scale_);
  if (!depth.ok()) return depth.status();
  if (depth->size() != color->size()) {
    return ParseError(pair.depth.file + ": depth image is " + std::to_string(depth->cols) + "x" +
                      std::to_string(depth->rows) + " but the colour image is " +
                      std::to_string(color->cols) + "x" + std::to_string(color->rows));
  }
  frame.color = std::move(*color);
  frame.depth_m = std::move(*depth);
  frame.stamp = MakeStamp(index);
  return Frame(std::move(frame));
}

std::string TumRgbdSource::FrameFile(int64_t index) const {
  return pairs_[static_cast<size_t>(index)].rgb.file;
}

}  // namespace sightline
