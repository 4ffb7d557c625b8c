#include "core/io/kitti_source.h"

#include <cstdio>
#include <map>
#include <optional>

#include "core/common/text_file.h"
#include "core/io/calibration_checks.h"
#include "core/io/file_listing.h"
#include "core/io/image_loading.h"
#include "core/io/timed_file_list.h"

namespace sightline {
namespace {

using Projection = Eigen::Matrix<double, 3, 4>;

// P0 and P1 from calib.txt, labelled or not.
StatusOr<std::pair<Projection, Projection>> ReadCalibration(const std::string& path) {
  auto lines = ReadDataLines(path);
  if (!lines.ok()) return lines.status();
  std::map<std::string, Projection> labelled;
  std::vector<Projection> unlabelled;
  for (const DataLine& line : *lines) {
    DataLine numbers_line = line;
    std::string label;
    const size_t colon = line.text.find(':');
    if (colon != std::string::npos) {
      label = line.text.substr(0, colon);
      numbers_line.text = line.text.substr(colon + 1);
    }
    auto v = ParseNumbers(numbers_line, 12, path);
    if (!v.ok()) return v.status();
    if (v->size() != 12) {
      return ParseError(path + " line " + std::to_string(line.number) +
                        ": expected 12 numbers (a 3x4 projection matrix), found " +
                        std::to_string(v->size()));
    }
    Projection p;
    for (int r = 0; r < 3; ++r) {
      for (int c = 0; c < 4; ++c) p(r, c) = (*v)[r * 4 + c];
    }
    if (label.empty()) {
      unlabelled.push_back(p);
    } else {
      labelled[label] = p;
    }
  }
  std::optional<Projection> p0, p1;
  if (labelled.count("P0")) p0 = labelled["P0"];
  if (labelled.count("P1")) p1 = labelled["P1"];
  size_t next = 0;
  if (!p0 && next < unlabelled.size()) p0 = unlabelled[next++];
  if (!p1 && next < unlabelled.size()) p1 = unlabelled[next++];
  if (!p0 || !p1) {
    return ParseError(path +
                      ": expected the projection matrices P0 and P1 (two lines of 12 "
                      "numbers, optionally labelled 'P0:' and 'P1:'), found " +
                      std::to_string(lines->size()) + " line(s)");
  }
  return std::make_pair(*p0, *p1);
}

PinholeCamera CameraFromProjection(const Projection& p, int width, int height) {
  PinholeCamera c;
  c.width = width;
  c.height = height;
  c.fx = p(0, 0);
  c.fy = p(1, 1);
  c.cx = p(0, 2);
  c.cy = p(1, 2);
  return c;
}

// Camera centre offset encoded in the 4th column of a rectified projection: K * t.
Eigen::Vector3d ProjectionTranslation(const Projection& p) {
  return p.leftCols<3>().inverse() * p.col(3);
}

}  // namespace

Status KittiSource::Open() {
  if (!DirectoryExists(folder_)) return NotFound(folder_ + ": no such folder");
  SourceInfo info;
  info.format = "KITTI odometry";
  info.path = folder_;
  info.kind = SourceKind::kStereo;

  std::string left_dir, right_dir;
  for (const auto& [l, r] : {std::pair{"image_0", "image_1"}, std::pair{"image_l", "image_r"}}) {
    if (DirectoryExists(JoinPath(folder_, l))) {
      left_dir = JoinPath(folder_, l);
      right_dir = JoinPath(folder_, r);
      break;
    }
  }
  if (left_dir.empty()) {
    return NotFound(folder_ + ": no image_0/ or image_l/ folder (KITTI layout expected)");
  }
  if (!DirectoryExists(right_dir)) return NotFound(right_dir + ": no such folder");
  auto names = ListFiles(left_dir, ImageExtensions());
  if (!names.ok()) return names.status();
  if (names->empty()) return NotFound(left_dir + ": no images (.png, .jpg)");
  std::vector<std::string> left_files, right_files;
  for (const std::string& name : *names) {
    left_files.push_back(JoinPath(left_dir, name));
    right_files.push_back(JoinPath(right_dir, name));
    SIGHTLINE_RETURN_IF_ERROR(CheckFileExists(right_files.back()));
  }
  const size_t n = left_files.size();

  const std::string calib_path = JoinPath(folder_, "calib.txt");
  auto projections = ReadCalibration(calib_path);
  if (!projections.ok()) return projections.status();
  auto first = LoadImage8(left_files[0]);
  if (!first.ok()) return first.status();
  info.width = first->cols;
  info.height = first->rows;
  StereoRig rig;
  rig.left = CameraFromProjection(projections->first, info.width, info.height);
  rig.right = CameraFromProjection(projections->second, info.width, info.height);
  rig.rectified = true;
  for (const auto& [name, camera] : {std::pair{"P0", rig.left}, std::pair{"P1", rig.right}}) {
    if (std::optional<FieldProblem> problem = CheckCameraValues(camera, CameraKeys{})) {
      return ParseError(calib_path + ": " + name + ": " + problem->what);
    }
  }
  // Rectified cameras share a rotation; x_in_right = x_in_left + (t1 - t0).
  rig.right_from_left.translation() =
      ProjectionTranslation(projections->second) - ProjectionTranslation(projections->first);
  if (Status valid = rig.Validate(); !valid.ok()) {
    return ParseError(calib_path + ": " + valid.message());
  }
  info.camera = rig.left;
  info.stereo = rig;

  std::vector<double> times;
  if (const std::string times_path = JoinPath(folder_, "times.txt"); PathExists(times_path)) {
    auto read = ReadTimesFile(times_path);
    if (!read.ok()) return read.status();
    if (read->size() != n) {
      return ParseError(times_path + ": " + std::to_string(read->size()) + " times for " +
                        std::to_string(n) + " image pairs");
    }
    times = std::move(*read);
  } else {
    for (size_t i = 0; i < n; ++i) times.push_back(0.1 * static_cast<double>(i));
    info.rate_hz = 10;
    info.notes.push_back("no times.txt: timestamps synthesized at 10 Hz (t = 0.1 s * index)");
  }

  std::optional<Trajectory> ground_truth;
  std::string poses_path = JoinPath(folder_, "poses.txt");
  if (!PathExists(poses_path)) {
    // KITTI's own tree: dataset/sequences/NN/ and dataset/poses/NN.txt.
    poses_path = JoinPath(JoinPath(folder_, "../../poses"), BaseName(folder_) + ".txt");
  }
  if (PathExists(poses_path)) {
    auto read = ReadKittiTrajectory(poses_path);
    if (!read.ok()) return read.status();
    if (read->size() != n) {
      return ParseError(poses_path + ": " + std::to_string(read->size()) + " poses for " +
                        std::to_string(n) + " image pairs");
    }
    for (size_t i = 0; i < n; ++i) read->mutable_poses()[i].time_s = times[i];
    ground_truth = std::move(*read);
    info.notes.push_back("ground truth from " + BaseName(poses_path) +
                         ": left camera in the frame of the left camera at image 0");
  }
  left_files_ = std::move(left_files);
  right_files_ = std::move(right_files);
  return Commit(std::move(info), std::move(times), std::move(ground_truth));
}

StatusOr<Frame> KittiSource::Load(int64_t index) {
  const size_t i = static_cast<size_t>(index);
  StatusOr<StereoFrame> pair = LoadStereoPair(left_files_[i], right_files_[i]);
  if (!pair.ok()) return pair.status();
  StereoFrame frame = std::move(*pair);
  frame.stamp = MakeStamp(index);
  return Frame(std::move(frame));
}

std::string KittiSource::FrameFile(int64_t index) const {
  return left_files_[static_cast<size_t>(index)];
}

}  // namespace sightline
