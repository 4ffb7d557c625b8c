#include "core/io/hand_eye_file.h"

#include <cmath>
#include <set>

#include "core/io/calibration_checks.h"
#include "core/io/yaml_file.h"

namespace sightline {
namespace {

const char* const kMount = "end_effector_from_camera";
const char* const kBase = "world_from_base";
const char* const kFitKeys[5] = {"method", "pairs", "max_rotation_deg", "board_rotation_rms_deg",
                                 "board_translation_rms_m"};

// Why a quaternion is not a unit quaternion, or nothing.
std::optional<std::string> CheckQuaternion(const Eigen::Quaterniond& q) {
  if (!q.coeffs().allFinite()) return "holds a value that is not finite";
  const double off = std::abs(q.norm() - 1);
  if (!(off <= kRotationTolerance)) {
    return "has length " + NumberText(q.norm()) + ", not 1 (within " +
           NumberText(kRotationTolerance) + ")";
  }
  return std::nullopt;
}

StatusOr<Eigen::Isometry3d> ReadPose(const YAML::Node& root, const std::string& key,
                                     const std::string& path) {
  const YAML::Node node = root[key];
  if (!node) return YamlKeyError(path, node, key, "missing");
  if (!node.IsMap()) {
    return YamlKeyError(path, node, key, "expected a map with translation and quaternion_xyzw");
  }
  SIGHTLINE_RETURN_IF_ERROR(
      CheckKnownKeys(node, {"translation", "quaternion_xyzw"}, path, key + "."));
  StatusOr<std::vector<double>> t =
      YamlNumbers(node, "translation", path, 3, 3, key + ".translation");
  if (!t.ok()) return t.status();
  const std::string q_label = key + ".quaternion_xyzw";
  StatusOr<std::vector<double>> q = YamlNumbers(node, "quaternion_xyzw", path, 4, 4, q_label);
  if (!q.ok()) return q.status();
  const Eigen::Quaterniond quaternion((*q)[3], (*q)[0], (*q)[1], (*q)[2]);
  if (std::optional<std::string> problem = CheckQuaternion(quaternion)) {
    return YamlKeyError(path, node["quaternion_xyzw"], q_label, *problem);
  }
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  // Within 1e-6 of unit length: normalising only removes the rounding of the printed digits.
  pose.linear() = quaternion.normalized().toRotationMatrix();
  pose.translation() = Eigen::Vector3d((*t)[0], (*t)[1], (*t)[2]);
  return pose;
}

// The optional rotation matrix must be a rotation and agree with the mount's quaternion.
Status CheckRotationKey(const YAML::Node& root, const Eigen::Matrix3d& mount,
                        const std::string& path) {
  if (!root["rotation"]) return Status::Ok();
  StatusOr<std::vector<double>> r = YamlNumbers(root, "rotation", path, 9, 9);
  if (!r.ok()) return r.status();
  Eigen::Matrix3d rotation;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) rotation(i, j) = (*r)[3 * i + j];
  }
  if (std::optional<std::string> problem = CheckRotation(rotation)) {
    return YamlKeyError(path, root["rotation"], "rotation", *problem);
  }
  const double off = (rotation - mount).cwiseAbs().maxCoeff();
  if (!(off <= kRotationTolerance)) {
    return YamlKeyError(path, root["rotation"], "rotation",
                        "differs from end_effector_from_camera.quaternion_xyzw by " +
                            NumberText(off) + " (limit 1e-6)");
  }
  return Status::Ok();
}

StatusOr<double> NonNegative(const YAML::Node& root, const std::string& key,
                             const std::string& path) {
  StatusOr<double> v = YamlNumber(root, key, path);
  if (v.ok() && !(*v >= 0)) return YamlKeyError(path, root[key], key, "must not be negative");
  return v;
}

StatusOr<std::optional<HandEyeFit>> ReadFit(const YAML::Node& root, const std::string& path) {
  int present = 0;
  for (const char* key : kFitKeys) present += root[key] ? 1 : 0;
  if (present == 0) return std::optional<HandEyeFit>();
  HandEyeFit fit;
  StatusOr<std::string> method = YamlString(root, "method", path);
  if (!method.ok()) return method.status();
  fit.method = *method;
  StatusOr<int> pairs = YamlWholeNumber(root, "pairs", path);
  if (!pairs.ok()) return pairs.status();
  if (*pairs < 1) return YamlKeyError(path, root["pairs"], "pairs", "must be positive");
  fit.pairs = *pairs;
  for (auto [key, value] :
       {std::pair<const char*, double*>{"max_rotation_deg", &fit.max_rotation_deg},
        {"board_rotation_rms_deg", &fit.board_rotation_rms_deg},
        {"board_translation_rms_m", &fit.board_translation_rms_m}}) {
    StatusOr<double> v = NonNegative(root, key, path);
    if (!v.ok()) return v.status();
    *value = *v;
  }
  return std::optional<HandEyeFit>(fit);
}

}  // namespace

StatusOr<HandEye> ReadHandEyeFile(const std::string& path) {
  StatusOr<YAML::Node> root = LoadYamlFile(path);
  if (!root.ok()) return root.status();
  std::set<std::string> known = {kMount, kBase, "rotation"};
  known.insert(std::begin(kFitKeys), std::end(kFitKeys));
  SIGHTLINE_RETURN_IF_ERROR(CheckKnownKeys(*root, known, path));
  HandEye out;
  StatusOr<Eigen::Isometry3d> mount = ReadPose(*root, kMount, path);
  if (!mount.ok()) return mount.status();
  out.end_effector_from_camera = *mount;
  SIGHTLINE_RETURN_IF_ERROR(CheckRotationKey(*root, mount->linear(), path));
  if ((*root)[kBase]) {
    StatusOr<Eigen::Isometry3d> base = ReadPose(*root, kBase, path);
    if (!base.ok()) return base.status();
    out.world_from_base = *base;
  }
  StatusOr<std::optional<HandEyeFit>> fit = ReadFit(*root, path);
  if (!fit.ok()) return fit.status();
  out.fit = *fit;
  return out;
}

namespace {

Status CheckWritablePose(const Eigen::Isometry3d& pose, const std::string& key,
                         const std::string& path) {
  if (!pose.translation().allFinite()) {
    return InvalidArgument("hand-eye file " + path + " not written: " + key +
                           ".translation is not finite");
  }
  if (std::optional<std::string> problem = CheckRotation(pose.linear())) {
    return InvalidArgument("hand-eye file " + path + " not written: " + key + " rotation " +
                           *problem);
  }
  return Status::Ok();
}

void WritePose(YamlWriter& out, const std::string& key, const Eigen::Isometry3d& pose) {
  const Eigen::Quaterniond q(pose.linear());
  const Eigen::Vector3d t = pose.translation();
  out.Map(key);
  out.List("translation", {t.x(), t.y(), t.z()}, 1);
  out.List("quaternion_xyzw", {q.x(), q.y(), q.z(), q.w()}, 1);
}

void WriteFit(YamlWriter& out, const HandEyeFit& fit) {
  out.Text("method", fit.method);
  out.Integer("pairs", fit.pairs);
  out.Number("max_rotation_deg", fit.max_rotation_deg);
  out.Number("board_rotation_rms_deg", fit.board_rotation_rms_deg);
  out.Number("board_translation_rms_m", fit.board_translation_rms_m);
}

}  // namespace

Status WriteHandEyeFile(const HandEye& hand_eye, const std::string& path,
                        const FileComments& comments) {
  SIGHTLINE_RETURN_IF_ERROR(CheckWritablePose(hand_eye.end_effector_from_camera, kMount, path));
  if (hand_eye.world_from_base) {
    SIGHTLINE_RETURN_IF_ERROR(CheckWritablePose(*hand_eye.world_from_base, kBase, path));
  }
  if (hand_eye.fit) {
    const HandEyeFit& f = *hand_eye.fit;
    if (!(f.pairs >= 1)) {
      return InvalidArgument("hand-eye file " + path + " not written: pairs must be positive");
    }
    for (double figure :
         {f.max_rotation_deg, f.board_rotation_rms_deg, f.board_translation_rms_m}) {
      if (!(std::isfinite(figure) && figure >= 0)) {
        return InvalidArgument("hand-eye file " + path +
                               " not written: the fit's figures must be finite and >= 0");
      }
    }
  }
  YamlWriter out(/*opencv_header=*/true);
  out.Comments(
      comments.header.empty()
          ? std::vector<std::string>{"Sightline hand-eye file (see core/io/hand_eye_file.h)"}
          : comments.header);
  WritePose(out, kMount, hand_eye.end_effector_from_camera);
  if (hand_eye.world_from_base) WritePose(out, kBase, *hand_eye.world_from_base);
  out.Matrix("rotation", hand_eye.end_effector_from_camera.linear());
  if (hand_eye.fit) WriteFit(out, *hand_eye.fit);
  out.Comments(comments.footer);
  return out.WriteTo(path);
}

}  // namespace sightline
