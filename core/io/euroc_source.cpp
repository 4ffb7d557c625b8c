#include "core/io/euroc_source.h"

#include <charconv>
#include <cmath>
#include <map>
#include <optional>

#include "core/common/text_file.h"
#include "core/io/calibration_checks.h"
#include "core/io/image_loading.h"
#include "core/io/timed_file_list.h"
#include "core/io/yaml_file.h"

namespace sightline {
namespace {

// What one EuRoC sensor.yaml says about a camera.
struct EurocCamera {
  PinholeCamera camera;
  Eigen::Isometry3d body_from_camera = Eigen::Isometry3d::Identity();
  double rate_hz = 0;
};

// T_BS as a rigid transform. ParseError when it is not one (bad last row, not a rotation).
StatusOr<Eigen::Isometry3d> ReadTbs(const YAML::Node& root, const std::string& path) {
  auto data = YamlNumbers(root, "T_BS", path, 16, 16);
  if (!data.ok()) return data.status();
  Eigen::Matrix4d m;
  for (int r = 0; r < 4; ++r) {
    for (int c = 0; c < 4; ++c) m(r, c) = (*data)[r * 4 + c];
  }
  const Eigen::Matrix3d rotation = m.topLeftCorner<3, 3>();
  if ((m.row(3) - Eigen::RowVector4d(0, 0, 0, 1)).norm() > 1e-6 ||
      (rotation.transpose() * rotation - Eigen::Matrix3d::Identity()).norm() > 1e-3 ||
      rotation.determinant() < 0) {
    return ParseError(path +
                      ": key 'T_BS': not a rigid transform (rotation | translation; "
                      "0 0 0 1)");
  }
  Eigen::Isometry3d transform = Eigen::Isometry3d::Identity();
  transform.linear() = Eigen::Quaterniond(rotation).normalized().toRotationMatrix();
  transform.translation() = m.topRightCorner<3, 1>();
  return transform;
}

// The checks of every calibration file, naming sensor.yaml's keys.
Status CheckEurocCamera(const YAML::Node& root, const PinholeCamera& c, const std::string& path) {
  CameraKeys keys;
  keys.width = keys.height = "resolution";
  keys.fx = keys.fy = keys.cx = keys.cy = "intrinsics";
  keys.distortion = "distortion_coefficients";
  if (std::optional<FieldProblem> problem = CheckCameraValues(c, keys)) {
    return YamlKeyError(path, root[problem->key], problem->key, problem->what);
  }
  return Status::Ok();
}

StatusOr<EurocCamera> ReadEurocCamera(const std::string& path) {
  auto root = LoadYamlFile(path);
  if (!root.ok()) return root.status();
  EurocCamera result;
  if (const YAML::Node model = (*root)["camera_model"];
      model && !(model.IsScalar() && model.Scalar() == "pinhole")) {
    return ParseError(path + ": key 'camera_model': only 'pinhole' is supported");
  }
  auto intrinsics = YamlNumbers(*root, "intrinsics", path, 4, 4);
  if (!intrinsics.ok()) return intrinsics.status();
  auto resolution = YamlNumbers(*root, "resolution", path, 2, 2);
  if (!resolution.ok()) return resolution.status();
  PinholeCamera& c = result.camera;
  c.fx = (*intrinsics)[0];
  c.fy = (*intrinsics)[1];
  c.cx = (*intrinsics)[2];
  c.cy = (*intrinsics)[3];
  c.width = static_cast<int>((*resolution)[0]);
  c.height = static_cast<int>((*resolution)[1]);
  if ((*root)["distortion_coefficients"]) {
    if (const YAML::Node model = (*root)["distortion_model"]; model) {
      const std::string name = model.IsScalar() ? model.Scalar() : "?";
      if (name != "radial-tangential" && name != "radtan" && name != "plumb_bob") {
        return ParseError(path + ": key 'distortion_model': '" + name +
                          "' is not supported (radial-tangential)");
      }
    }
    auto d = YamlNumbers(*root, "distortion_coefficients", path, 4, 5);
    if (!d.ok()) return d.status();
    for (size_t i = 0; i < d->size(); ++i) c.distortion[i] = (*d)[i];
  }
  SIGHTLINE_RETURN_IF_ERROR(CheckEurocCamera(*root, c, path));
  auto body_from_camera = ReadTbs(*root, path);
  if (!body_from_camera.ok()) return body_from_camera.status();
  result.body_from_camera = *body_from_camera;
  if ((*root)["rate_hz"]) {
    auto rate = YamlNumber(*root, "rate_hz", path);
    if (!rate.ok()) return rate.status();
    result.rate_hz = *rate;
  }
  return result;
}

// A data.csv row: nanosecond timestamp and image file name.
struct CsvImage {
  int64_t time_ns = 0;
  std::string file;
};

StatusOr<std::vector<CsvImage>> ReadImageCsv(const std::string& path) {
  auto lines = ReadDataLines(path);
  if (!lines.ok()) return lines.status();
  std::vector<CsvImage> images;
  for (const DataLine& line : *lines) {
    const std::vector<std::string> f = SplitFields(line.text);
    const std::string where = path + " line " + std::to_string(line.number);
    if (f.size() < 2) {
      return ParseError(where + ": expected 'timestamp [ns],filename', found " +
                        std::to_string(f.size()) + " field(s) (truncated line?)");
    }
    CsvImage image;
    const char* end = f[0].data() + f[0].size();
    auto [ptr, ec] = std::from_chars(f[0].data(), end, image.time_ns);
    if (ec != std::errc() || ptr != end) {
      return ParseError(where + ": timestamp '" + f[0] + "' is not an integer of nanoseconds");
    }
    if (!images.empty() && image.time_ns <= images.back().time_ns) {
      return ParseError(where + ": timestamp " + f[0] + " is " +
                        (image.time_ns == images.back().time_ns ? "equal to" : "before") +
                        " the previous one (" + std::to_string(images.back().time_ns) +
                        "): timestamps must increase");
    }
    SIGHTLINE_RETURN_IF_ERROR(CheckListedPath(f[1], path, line.number));
    image.file = f[1];
    images.push_back(std::move(image));
  }
  return images;
}

// EuRoC ground-truth CSV: "ns, px, py, pz, qw, qx, qy, qz, ..." (pose of the GT sensor).
StatusOr<Trajectory> ReadEurocGroundTruthCsv(const std::string& path) {
  auto lines = ReadDataLines(path);
  if (!lines.ok()) return lines.status();
  Trajectory trajectory;
  for (const DataLine& line : *lines) {
    auto v = ParseNumbers(line, 8, path);
    if (!v.ok()) return v.status();
    StatusOr<Eigen::Quaterniond> q =
        PoseFileQuaternion((*v)[4], (*v)[5], (*v)[6], (*v)[7], path, line.number);
    if (!q.ok()) return q.status();
    Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
    pose.linear() = q->toRotationMatrix();
    pose.translation() = Eigen::Vector3d((*v)[1], (*v)[2], (*v)[3]);
    const double t = (*v)[0] * 1e-9;
    if (!trajectory.empty()) {
      SIGHTLINE_RETURN_IF_ERROR(
          CheckTimeIncreases(trajectory.poses().back().time_s, t, path, line.number));
    }
    trajectory.Add(t, pose);
  }
  return trajectory;
}

// The left-camera ground truth, or nullopt when the recording has none.
StatusOr<std::optional<Trajectory>> ReadGroundTruth(const std::string& mav0,
                                                    const Eigen::Isometry3d& body_from_cam0,
                                                    std::string* source_file) {
  const std::string folder = JoinPath(mav0, "state_groundtruth_estimate0");
  std::optional<Trajectory> gt;
  if (const std::string tum = JoinPath(folder, "groundtruth_tum.txt"); PathExists(tum)) {
    auto read = ReadTumTrajectory(tum);
    if (!read.ok()) return read.status();
    gt = std::move(*read);
    *source_file = tum;
  } else if (const std::string csv = JoinPath(folder, "data.csv"); PathExists(csv)) {
    auto read = ReadEurocGroundTruthCsv(csv);
    if (!read.ok()) return read.status();
    gt = std::move(*read);
    *source_file = csv;
  } else {
    return gt;
  }
  // The estimate is of its own "sensor" frame S, body_from_S = its T_BS (identity in EuRoC).
  Eigen::Isometry3d body_from_gt = Eigen::Isometry3d::Identity();
  if (const std::string yaml = JoinPath(folder, "sensor.yaml"); PathExists(yaml)) {
    auto root = LoadYamlFile(yaml);
    if (!root.ok()) return root.status();
    if ((*root)["T_BS"]) {
      auto tbs = ReadTbs(*root, yaml);
      if (!tbs.ok()) return tbs.status();
      body_from_gt = *tbs;
    }
  }
  const Eigen::Isometry3d gt_from_cam0 = body_from_gt.inverse() * body_from_cam0;
  for (TimedPose& pose : gt->mutable_poses()) {
    pose.world_from_sensor = pose.world_from_sensor * gt_from_cam0;
  }
  return gt;
}

}  // namespace

Status EurocSource::Open() {
  std::string mav0;
  if (DirectoryExists(JoinPath(path_, "mav0"))) {
    mav0 = JoinPath(path_, "mav0");
  } else if (DirectoryExists(JoinPath(path_, "cam0"))) {
    mav0 = path_;
  } else if (!DirectoryExists(path_)) {
    return NotFound(path_ + ": no such folder");
  } else {
    return NotFound(path_ + ": no mav0/ or cam0/ folder (EuRoC ASL layout expected)");
  }
  SourceInfo info;
  info.format = "EuRoC MAV";
  info.path = path_;
  info.kind = SourceKind::kStereo;

  const std::string cam0 = JoinPath(mav0, "cam0"), cam1 = JoinPath(mav0, "cam1");
  auto left_cam = ReadEurocCamera(JoinPath(cam0, "sensor.yaml"));
  if (!left_cam.ok()) return left_cam.status();
  auto right_cam = ReadEurocCamera(JoinPath(cam1, "sensor.yaml"));
  if (!right_cam.ok()) return right_cam.status();
  auto left_csv = ReadImageCsv(JoinPath(cam0, "data.csv"));
  if (!left_csv.ok()) return left_csv.status();
  auto right_csv = ReadImageCsv(JoinPath(cam1, "data.csv"));
  if (!right_csv.ok()) return right_csv.status();

  // Pairs: equal timestamps.
  std::map<int64_t, std::string> right_by_time;
  for (const CsvImage& image : *right_csv) right_by_time[image.time_ns] = image.file;
  std::vector<std::string> left_files, right_files;
  std::vector<double> times;
  for (const CsvImage& image : *left_csv) {
    auto it = right_by_time.find(image.time_ns);
    if (it == right_by_time.end()) continue;
    left_files.push_back(JoinPath(JoinPath(cam0, "data"), image.file));
    right_files.push_back(JoinPath(JoinPath(cam1, "data"), it->second));
    times.push_back(static_cast<double>(image.time_ns) * 1e-9);
  }
  if (left_files.empty()) {
    return ParseError(mav0 + ": no cam0 and cam1 images share a timestamp in data.csv");
  }
  if (left_files.size() < left_csv->size() || left_files.size() < right_csv->size()) {
    info.notes.push_back(std::to_string(left_csv->size() - left_files.size()) + " cam0 and " +
                         std::to_string(right_csv->size() - left_files.size()) +
                         " cam1 images without a partner of equal timestamp skipped");
  }
  for (size_t i = 0; i < left_files.size(); ++i) {
    SIGHTLINE_RETURN_IF_ERROR(CheckFileExists(left_files[i]));
    SIGHTLINE_RETURN_IF_ERROR(CheckFileExists(right_files[i]));
  }

  StereoRig rig;
  rig.left = left_cam->camera;
  rig.right = right_cam->camera;
  rig.right_from_left = right_cam->body_from_camera.inverse() * left_cam->body_from_camera;
  rig.rectified = false;
  if (Status valid = rig.Validate(); !valid.ok()) {
    return ParseError(JoinPath(cam1, "sensor.yaml") + ": " + valid.message());
  }

  // The first pair proves the images decode and match sensor.yaml's resolution.
  for (const auto& [file, camera] :
       {std::pair{left_files[0], rig.left}, std::pair{right_files[0], rig.right}}) {
    auto image = LoadImage8(file);
    if (!image.ok()) return image.status();
    if (image->cols != camera.width || image->rows != camera.height) {
      return ParseError(file + ": image is " + std::to_string(image->cols) + "x" +
                        std::to_string(image->rows) + " but sensor.yaml says " +
                        std::to_string(camera.width) + "x" + std::to_string(camera.height));
    }
  }
  info.width = rig.left.width;
  info.height = rig.left.height;
  info.camera = rig.left;
  info.stereo = rig;
  info.rate_hz = left_cam->rate_hz;
  info.notes.push_back("raw images (not rectified), radial-tangential distortion");

  std::string gt_file;
  auto gt = ReadGroundTruth(mav0, left_cam->body_from_camera, &gt_file);
  if (!gt.ok()) return gt.status();
  if (gt->has_value()) {
    info.notes.push_back("ground truth from " + gt_file +
                         " is of the body (IMU) frame; transformed to cam0 with cam0's T_BS "
                         "(world_from_cam0 = world_from_body * body_from_cam0)");
    size_t covered = 0;
    for (double t : times) covered += (*gt)->Nearest(t, 0.02) ? 1 : 0;
    if (covered < times.size()) {
      info.notes.push_back("ground truth within 0.02 s for " + std::to_string(covered) + " of " +
                           std::to_string(times.size()) + " frames");
    }
  }
  left_files_ = std::move(left_files);
  right_files_ = std::move(right_files);
  return Commit(std::move(info), std::move(times), std::move(*gt));
}

StatusOr<Frame> EurocSource::Load(int64_t index) {
  const size_t i = static_cast<size_t>(index);
  StatusOr<StereoFrame> pair = LoadStereoPair(left_files_[i], right_files_[i]);
  if (!pair.ok()) return pair.status();
  StereoFrame frame = std::move(*pair);
  frame.stamp = MakeStamp(index);
  return Frame(std::move(frame));
}

std::string EurocSource::FrameFile(int64_t index) const {
  return left_files_[static_cast<size_t>(index)];
}

}  // namespace sightline
