#include "core/button/server_lines.h"

#include <cctype>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <map>
#include <vector>

#include "core/button/flat_json.h"

namespace sightline {
namespace {

using Value = FlatJsonValue;

Status Bad(const std::string& what) { return InvalidArgument("server line: " + what); }

using Members = std::map<std::string, Value>;

StatusOr<double> NumberOf(const Members& m, const std::string& key) {
  auto it = m.find(key);
  if (it == m.end() || it->second.kind != Value::kNumber || !std::isfinite(it->second.number)) {
    return Bad("\"" + key + "\" must be a finite number");
  }
  return it->second.number;
}

StatusOr<std::string> StringOf(const Members& m, const std::string& key) {
  auto it = m.find(key);
  if (it == m.end() || it->second.kind != Value::kString) {
    return Bad("\"" + key + "\" must be a string");
  }
  return it->second.text;
}

StatusOr<Eigen::Vector3d> VectorOf(const Members& m, const std::string& key) {
  auto it = m.find(key);
  if (it == m.end() || it->second.kind != Value::kArray || it->second.array.size() != 3) {
    return Bad("\"" + key + "\" must be an array of 3 numbers");
  }
  const std::vector<double>& a = it->second.array;
  const Eigen::Vector3d v(a[0], a[1], a[2]);
  if (!v.allFinite()) return Bad("\"" + key + "\" is not finite");
  return v;
}

Status ReadTarget(const Members& m, ArmTarget* t) {
  StatusOr<double> frame_stamp = NumberOf(m, "frame_stamp");
  if (!frame_stamp.ok()) return frame_stamp.status();
  t->stamp_s = *frame_stamp;
  StatusOr<std::string> frame_id = StringOf(m, "frame_id");
  if (!frame_id.ok()) return frame_id.status();
  t->frame_id = *frame_id;
  StatusOr<Eigen::Vector3d> position = VectorOf(m, "position_m");
  if (!position.ok()) return position.status();
  t->position_m = *position;
  StatusOr<Eigen::Vector3d> approach = VectorOf(m, "approach");
  if (!approach.ok()) return approach.status();
  if (!(approach->norm() > 0.5 && approach->norm() < 1.5)) {
    return Bad("\"approach\" is not a unit vector");
  }
  t->approach = approach->normalized();
  if (StatusOr<double> u = NumberOf(m, "uncertainty_m"); u.ok()) t->uncertainty_m = *u;
  if (StatusOr<double> a = NumberOf(m, "approach_sigma_deg"); a.ok()) t->approach_sigma_deg = *a;
  if (auto it = m.find("source_frames"); it != m.end() && it->second.kind == Value::kArray) {
    for (double id : it->second.array) t->source_frames.push_back(static_cast<int64_t>(id));
  }
  return Status::Ok();
}

}  // namespace

StatusOr<ServerLine> ParseServerLine(const std::string& line) {
  Members m;
  FlatJsonRules rules;
  rules.prefix = "server line: ";
  rules.max_array = 4096;
  SIGHTLINE_RETURN_IF_ERROR(ReadFlatJson(line, rules, &m));
  ServerLine out;
  StatusOr<double> version = NumberOf(m, "version");
  if (!version.ok()) return version.status();
  if (*version != kArmProtocolVersion) {
    return Bad("\"version\" is " + std::to_string(*version) + ", this arm speaks version " +
               std::to_string(kArmProtocolVersion));
  }
  out.version = kArmProtocolVersion;
  StatusOr<double> seq = NumberOf(m, "seq");
  if (!seq.ok()) return seq.status();
  out.seq = static_cast<int64_t>(*seq);
  StatusOr<double> stamp = NumberOf(m, "stamp");
  if (!stamp.ok()) return stamp.status();
  out.stamp_s = *stamp;
  StatusOr<std::string> type = StringOf(m, "type");
  if (!type.ok()) return type.status();
  if (*type == "target") {
    out.type = ServerLine::Type::kTarget;
    SIGHTLINE_RETURN_IF_ERROR(ReadTarget(m, &out.target));
  } else if (*type == "heartbeat") {
    out.type = ServerLine::Type::kHeartbeat;
    auto it = m.find("targets_enabled");
    if (it == m.end() || it->second.kind != Value::kBool) {
      return Bad("\"targets_enabled\" must be true or false");
    }
    out.targets_enabled = it->second.flag;
  } else if (*type == "stop") {
    out.type = ServerLine::Type::kStop;
    if (StatusOr<std::string> reason = StringOf(m, "reason"); reason.ok()) out.reason = *reason;
  } else {
    return Bad("unknown \"type\" '" + *type + "'");
  }
  return out;
}

}  // namespace sightline
