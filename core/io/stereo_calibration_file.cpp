#include "core/io/stereo_calibration_file.h"

#include <cmath>
#include <set>

#include "core/io/calibration_checks.h"
#include "core/io/yaml_file.h"

namespace sightline {
namespace {

constexpr double kMinBaselineM = 1e-4;

CameraKeys KeysOf(const std::string& k_key, const std::string& d_key) {
  CameraKeys keys;
  keys.width = "image_width";
  keys.height = "image_height";
  keys.fx = keys.fy = keys.cx = keys.cy = k_key;
  keys.distortion = d_key;
  return keys;
}

// The 9 numbers of an intrinsic matrix [fx 0 cx; 0 fy cy; 0 0 1] (row-major) into `c`.
Status ReadIntrinsicMatrix(const YAML::Node& root, const std::string& key, const std::string& path,
                           PinholeCamera* c) {
  StatusOr<std::vector<double>> k = YamlNumbers(root, key, path, 9, 9);
  if (!k.ok()) return k.status();
  const std::vector<double>& m = *k;
  if (std::abs(m[1]) > 1e-9 || std::abs(m[3]) > 1e-9 || std::abs(m[6]) > 1e-9 ||
      std::abs(m[7]) > 1e-9 || std::abs(m[8] - 1) > 1e-9) {
    return YamlKeyError(path, root[key], key,
                        "must be an intrinsic matrix [fx 0 cx; 0 fy cy; 0 0 1] (no skew)");
  }
  c->fx = m[0];
  c->cx = m[2];
  c->fy = m[4];
  c->cy = m[5];
  return Status::Ok();
}

Status ReadCamera(const YAML::Node& root, const std::string& k_key, const std::string& d_key,
                  int width, int height, const std::string& path, PinholeCamera* c) {
  c->width = width;
  c->height = height;
  SIGHTLINE_RETURN_IF_ERROR(ReadIntrinsicMatrix(root, k_key, path, c));
  StatusOr<std::vector<double>> d = YamlNumbers(root, d_key, path, 4, 5);
  if (!d.ok()) return d.status();
  for (size_t i = 0; i < d->size(); ++i) c->distortion[i] = (*d)[i];
  if (std::optional<FieldProblem> problem = CheckCameraValues(*c, KeysOf(k_key, d_key))) {
    return YamlKeyError(path, root[problem->key], problem->key, problem->what);
  }
  return Status::Ok();
}

Status ReadExtrinsics(const YAML::Node& root, const std::string& path, StereoRig* rig) {
  StatusOr<std::vector<double>> r = YamlNumbers(root, "R", path, 9, 9);
  if (!r.ok()) return r.status();
  StatusOr<std::vector<double>> t = YamlNumbers(root, "T", path, 3, 3);
  if (!t.ok()) return t.status();
  Eigen::Matrix3d rotation;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) rotation(i, j) = (*r)[3 * i + j];
  }
  if (std::optional<std::string> problem = CheckRotation(rotation)) {
    return YamlKeyError(path, root["R"], "R", *problem);
  }
  rig->right_from_left.linear() = rotation;
  rig->right_from_left.translation() = Eigen::Vector3d((*t)[0], (*t)[1], (*t)[2]);
  if (!(rig->BaselineM() >= kMinBaselineM)) {
    return YamlKeyError(path, root["T"], "T",
                        "baseline " + NumberText(rig->BaselineM()) +
                            " m: the cameras must be at least 0.1 mm apart");
  }
  return Status::Ok();
}

}  // namespace

StatusOr<StereoRig> ReadStereoCalibration(const std::string& path) {
  StatusOr<YAML::Node> root = LoadYamlFile(path);
  if (!root.ok()) return root.status();
  StatusOr<int> width = YamlWholeNumber(*root, "image_width", path);
  if (!width.ok()) return width.status();
  StatusOr<int> height = YamlWholeNumber(*root, "image_height", path);
  if (!height.ok()) return height.status();
  StereoRig rig;
  SIGHTLINE_RETURN_IF_ERROR(ReadCamera(*root, "M1", "D1", *width, *height, path, &rig.left));
  SIGHTLINE_RETURN_IF_ERROR(ReadCamera(*root, "M2", "D2", *width, *height, path, &rig.right));
  SIGHTLINE_RETURN_IF_ERROR(ReadExtrinsics(*root, path, &rig));
  return rig;
}

namespace {

// Extra keys must be new: the reader rejects a key given twice.
Status CheckExtraKeys(const StereoFileExtras& extras, const std::string& not_written) {
  std::set<std::string> keys = {"image_width", "image_height", "M1", "D1", "M2", "D2", "R", "T"};
  for (const auto& [key, m] : extras.matrices) {
    if (!keys.insert(key).second) return InvalidArgument(not_written + "key '" + key + "' twice");
  }
  for (const auto& [key, v] : extras.numbers) {
    if (!keys.insert(key).second) return InvalidArgument(not_written + "key '" + key + "' twice");
  }
  return Status::Ok();
}

Status CheckWritable(const StereoRig& rig, const StereoFileExtras& extras,
                     const std::string& path) {
  const std::string not_written = "stereo calibration " + path + " not written: ";
  SIGHTLINE_RETURN_IF_ERROR(CheckExtraKeys(extras, not_written));
  for (const auto& [camera, name] :
       {std::pair<const PinholeCamera*, const char*>{&rig.left, "left"}, {&rig.right, "right"}}) {
    if (std::optional<FieldProblem> problem = CheckCameraValues(*camera, CameraKeys{})) {
      return InvalidArgument(not_written + name + " camera: " + problem->what);
    }
  }
  if (rig.left.width != rig.right.width || rig.left.height != rig.right.height) {
    return InvalidArgument(not_written + "the file holds one image size, the cameras differ");
  }
  if (std::optional<std::string> problem = CheckRotation(rig.right_from_left.linear())) {
    return InvalidArgument(not_written + "R " + *problem);
  }
  if (!(rig.BaselineM() >= kMinBaselineM) || !rig.right_from_left.translation().allFinite()) {
    return InvalidArgument(not_written + "the baseline must be finite and at least 0.1 mm");
  }
  return Status::Ok();
}

Eigen::MatrixXd Distortion(const PinholeCamera& c) {
  Eigen::MatrixXd d(1, 5);
  for (int i = 0; i < 5; ++i) d(0, i) = c.distortion[i];
  return d;
}

}  // namespace

Status WriteStereoCalibration(const StereoRig& rig, const std::string& path,
                              const StereoFileExtras& extras) {
  SIGHTLINE_RETURN_IF_ERROR(CheckWritable(rig, extras, path));
  YamlWriter out(/*opencv_header=*/true);
  out.Comments(extras.comments.header.empty()
                   ? std::vector<std::string>{"Sightline stereo calibration (OpenCV stereo "
                                              "layout); x_right = R x_left + T"}
                   : extras.comments.header);
  out.Integer("image_width", rig.left.width);
  out.Integer("image_height", rig.left.height);
  out.Matrix("M1", rig.left.K());
  out.Matrix("D1", Distortion(rig.left));
  out.Matrix("M2", rig.right.K());
  out.Matrix("D2", Distortion(rig.right));
  out.Matrix("R", rig.right_from_left.linear());
  out.Matrix("T", rig.right_from_left.translation());
  for (const auto& [key, m] : extras.matrices) out.Matrix(key, m);
  for (const auto& [key, v] : extras.numbers) {
    // Whole numbers (board size) as integers, as cv::FileStorage writes them.
    if (v == std::round(v) && std::abs(v) < 1e15) {
      out.Integer(key, static_cast<long long>(v));
    } else {
      out.Number(key, v);
    }
  }
  out.Comments(extras.comments.footer);
  return out.WriteTo(path);
}

}  // namespace sightline
