#include "core/button/server_lines.h"

#include <cctype>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <map>
#include <vector>

namespace sightline {
namespace {

// A member's value: a string, a number, a numeric array, a bool or null.
struct Value {
  enum Kind { kString, kNumber, kArray, kBool, kNull } kind = kNull;
  std::string text;
  double number = 0;
  bool flag = false;
  std::vector<double> array;
};

Status Bad(const std::string& what) { return InvalidArgument("server line: " + what); }

// A strict reader of one flat JSON object (scalars and numeric arrays).
class Reader {
 public:
  explicit Reader(const std::string& s) : s_(s) {}

  Status Object(std::map<std::string, Value>* members) {
    if (!Eat('{')) return Bad("not a JSON object");
    if (!Eat('}')) {
      do {
        std::string key;
        if (!String(&key)) return Bad("expected a member name");
        if (!Eat(':')) return Bad("expected ':' after \"" + key + "\"");
        Value value;
        SIGHTLINE_RETURN_IF_ERROR(Member(key, &value));
        if (!members->emplace(key, std::move(value)).second) {
          return Bad("duplicate \"" + key + "\"");
        }
      } while (Eat(','));
      if (!Eat('}')) return Bad("expected ',' or '}'");
    }
    Skip();
    return i_ == s_.size() ? Status::Ok() : Bad("text after the object");
  }

 private:
  void Skip() {
    while (i_ < s_.size() && std::isspace(static_cast<unsigned char>(s_[i_]))) ++i_;
  }
  bool Eat(char c) {
    Skip();
    if (i_ >= s_.size() || s_[i_] != c) return false;
    ++i_;
    return true;
  }
  bool String(std::string* out) {
    if (!Eat('"')) return false;
    while (i_ < s_.size()) {
      const char c = s_[i_++];
      if (c == '"') return true;
      if (static_cast<unsigned char>(c) < 0x20) return false;
      if (c != '\\') {
        out->push_back(c);
        continue;
      }
      if (i_ >= s_.size()) return false;
      const char e = s_[i_++];
      const char* from = "\"\\/bfnrt";
      const char* to = "\"\\/\b\f\n\r\t";
      const char* at = std::strchr(from, e);
      if (at == nullptr || e == '\0') return false;  // \u escapes are not used by the server.
      out->push_back(to[at - from]);
    }
    return false;
  }
  bool Number(double* out) {
    Skip();
    const char* start = s_.c_str() + i_;
    if (*start != '-' && !std::isdigit(static_cast<unsigned char>(*start))) return false;
    char* end = nullptr;
    *out = std::strtod(start, &end);
    for (const char* c = start; c < end; ++c) {  // Plain decimal numbers only (no hex, inf).
      if (!std::isdigit(static_cast<unsigned char>(*c)) && !std::strchr("+-.eE", *c)) return false;
    }
    i_ += static_cast<size_t>(end - start);
    return end != start;
  }
  Status Member(const std::string& key, Value* v) {
    Skip();
    const char c = i_ < s_.size() ? s_[i_] : '\0';
    if (c == '"') {
      v->kind = Value::kString;
      return String(&v->text) ? Status::Ok() : Bad("bad string in \"" + key + "\"");
    }
    if (c == '[') {
      ++i_;
      v->kind = Value::kArray;
      if (Eat(']')) return Status::Ok();
      do {
        double x = 0;
        if (!Number(&x) || v->array.size() >= 4096) return Bad("\"" + key + "\": numbers only");
        v->array.push_back(x);
      } while (Eat(','));
      return Eat(']') ? Status::Ok() : Bad("\"" + key + "\": expected ']'");
    }
    for (const char* word : {"true", "false", "null"}) {
      if (s_.compare(i_, std::strlen(word), word) == 0) {
        i_ += std::strlen(word);
        v->kind = word[0] == 'n' ? Value::kNull : Value::kBool;
        v->flag = word[0] == 't';
        return Status::Ok();
      }
    }
    v->kind = Value::kNumber;
    return Number(&v->number) ? Status::Ok() : Bad("bad value of \"" + key + "\"");
  }

  const std::string& s_;
  size_t i_ = 0;
};

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
  SIGHTLINE_RETURN_IF_ERROR(Reader(line).Object(&m));
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
