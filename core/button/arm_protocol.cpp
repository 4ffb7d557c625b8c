#include "core/button/arm_protocol.h"

#include <cctype>
#include <cmath>
#include <cstdio>

#include "core/common/json_writer.h"

namespace sightline {

namespace {

// Seconds with microsecond resolution: epoch stamps need 16 significant digits.
std::string Seconds(double s) {
  if (!std::isfinite(s)) return "null";
  char text[64];
  std::snprintf(text, sizeof(text), "%.6f", s);
  return text;
}

JsonWriter& Header(JsonWriter& w, const char* type, int64_t seq, double now_s) {
  w.BeginObject();
  w.Key("version").Int(kArmProtocolVersion);
  w.Key("type").String(type);
  w.Key("seq").Int(seq);
  w.Key("stamp").Raw(Seconds(now_s));
  return w;
}

void Vector(JsonWriter& w, const Eigen::Vector3d& v) {
  w.BeginArray();
  for (int i = 0; i < 3; ++i) w.Double(v[i]);
  w.EndArray();
}

}  // namespace

std::string TargetLine(int64_t seq, double now_s, const ArmTarget& t) {
  JsonWriter w(false);
  Header(w, "target", seq, now_s);
  w.Key("frame_stamp").Raw(Seconds(t.stamp_s));
  w.Key("frame_id").String(t.frame_id);
  w.Key("position_m");
  Vector(w, t.position_m);
  w.Key("approach");
  Vector(w, t.approach);
  w.Key("uncertainty_m").Double(t.uncertainty_m);
  w.Key("approach_sigma_deg").Double(t.approach_sigma_deg);
  w.Key("source_frames").BeginArray();
  for (int64_t f : t.source_frames) w.Int(f);
  w.EndArray();
  w.EndObject();
  return w.str() + "\n";
}

std::string HeartbeatLine(int64_t seq, double now_s, bool targets_enabled) {
  JsonWriter w(false);
  Header(w, "heartbeat", seq, now_s);
  w.Key("targets_enabled").Bool(targets_enabled);
  w.EndObject();
  return w.str() + "\n";
}

std::string StopLine(int64_t seq, double now_s, const std::string& reason) {
  JsonWriter w(false);
  Header(w, "stop", seq, now_s);
  w.Key("reason").String(reason);
  w.EndObject();
  return w.str() + "\n";
}

namespace {

// A tiny strict reader for one flat JSON object.
class FlatReader {
 public:
  explicit FlatReader(const std::string& s) : s_(s) {}

  std::optional<std::string> Token() {
    std::optional<std::string> token;
    Skip();
    if (!Eat('{')) return std::nullopt;
    Skip();
    if (Eat('}')) return End() ? token : std::nullopt;
    while (true) {
      Skip();
      std::string key;
      if (!String(&key)) return std::nullopt;
      Skip();
      if (!Eat(':')) return std::nullopt;
      Skip();
      std::string value;
      bool is_string = false;
      if (Peek() == '"') {
        if (!String(&value)) return std::nullopt;
        is_string = true;
      } else if (!Scalar()) {
        return std::nullopt;
      }
      if (key == "token") token = is_string ? std::optional<std::string>(value) : std::nullopt;
      Skip();
      if (Eat('}')) break;
      if (!Eat(',')) return std::nullopt;
    }
    return End() ? token : std::nullopt;
  }

 private:
  char Peek() const { return i_ < s_.size() ? s_[i_] : '\0'; }
  bool Eat(char c) {
    if (Peek() != c) return false;
    ++i_;
    return true;
  }
  void Skip() {
    while (i_ < s_.size() && std::isspace(static_cast<unsigned char>(s_[i_]))) ++i_;
  }
  bool End() {
    Skip();
    return i_ == s_.size();
  }
  bool String(std::string* out) {
    if (!Eat('"')) return false;
    while (i_ < s_.size()) {
      const char c = s_[i_++];
      if (c == '"') return true;
      if (static_cast<unsigned char>(c) < 0x20) return false;
      if (c == '\\') {
        if (i_ >= s_.size()) return false;
        const char e = s_[i_++];
        switch (e) {
          case '"':
          case '\\':
          case '/':
            out->push_back(e);
            break;
          case 'n':
            out->push_back('\n');
            break;
          case 't':
            out->push_back('\t');
            break;
          case 'r':
            out->push_back('\r');
            break;
          case 'b':
            out->push_back('\b');
            break;
          case 'f':
            out->push_back('\f');
            break;
          default:
            return false;  // \u escapes are not used by tokens.
        }
      } else {
        out->push_back(c);
      }
    }
    return false;
  }
  bool Scalar() {
    const size_t start = i_;
    while (i_ < s_.size() && (std::isalnum(static_cast<unsigned char>(s_[i_])) || s_[i_] == '-' ||
                              s_[i_] == '+' || s_[i_] == '.')) {
      ++i_;
    }
    const std::string word = s_.substr(start, i_ - start);
    if (word == "true" || word == "false" || word == "null") return true;
    if (word.empty()) return false;
    for (char c : word) {
      if (!std::isdigit(static_cast<unsigned char>(c)) && c != '-' && c != '+' && c != '.' &&
          c != 'e' && c != 'E') {
        return false;
      }
    }
    return true;
  }

  const std::string& s_;
  size_t i_ = 0;
};

}  // namespace

std::optional<std::string> ParseTokenLine(const std::string& line) {
  return FlatReader(line).Token();
}

bool TokensMatch(const std::string& presented, const std::string& expected) {
  // Every byte of `expected` is visited whatever `presented` holds; no early exit.
  volatile unsigned char diff = presented.size() == expected.size() ? 0 : 1;
  for (size_t i = 0; i < expected.size(); ++i) {
    const unsigned char p = i < presented.size() ? static_cast<unsigned char>(presented[i]) : 0;
    diff = diff | (p ^ static_cast<unsigned char>(expected[i]));
  }
  return diff == 0;
}

}  // namespace sightline
