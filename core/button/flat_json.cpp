#include "core/button/flat_json.h"

#include <cctype>
#include <cstdlib>
#include <cstring>

namespace sightline {
namespace {

class Reader {
 public:
  Reader(const std::string& s, const FlatJsonRules& rules) : s_(s), rules_(rules) {}

  Status Object(std::map<std::string, FlatJsonValue>* members) {
    if (!Eat('{')) return Bad(rules_.not_object);
    if (Eat('}')) return End();
    do {
      std::string key;
      if (!String(&key)) return Bad("expected a member name");
      if (!Eat(':')) return Bad("expected ':' after \"" + key + "\"");
      FlatJsonValue value;
      SIGHTLINE_RETURN_IF_ERROR(Member(key, &value));
      if (!members->emplace(key, std::move(value)).second) return Bad("duplicate \"" + key + "\"");
    } while (Eat(','));
    if (!Eat('}')) return Bad("expected ',' or '}'");
    return End();
  }

 private:
  Status Bad(const std::string& what) const { return InvalidArgument(rules_.prefix + what); }
  void Skip() {
    while (i_ < s_.size() && std::isspace(static_cast<unsigned char>(s_[i_]))) ++i_;
  }
  bool Eat(char c) {
    Skip();
    if (i_ >= s_.size() || s_[i_] != c) return false;
    ++i_;
    return true;
  }
  Status End() {
    Skip();
    return i_ == s_.size() ? Status::Ok() : Bad("text after the object");
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
      if (!rules_.escapes || i_ >= s_.size()) return false;
      const char e = s_[i_++];
      const char* from = "\"\\/bfnrt";
      const char* to = "\"\\/\b\f\n\r\t";
      const char* at = std::strchr(from, e);
      if (at == nullptr || e == '\0') return false;  // \u escapes are not used by the protocol.
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
    if (end == start) return false;
    for (const char* c = start; c < end; ++c) {  // Plain decimal numbers only (no hex, inf).
      if (!std::isdigit(static_cast<unsigned char>(*c)) && !std::strchr("+-.eE", *c)) return false;
    }
    i_ += static_cast<size_t>(end - start);
    return true;
  }
  Status Member(const std::string& key, FlatJsonValue* v) {
    Skip();
    const char c = i_ < s_.size() ? s_[i_] : '\0';
    if (c == '"') {
      v->kind = FlatJsonValue::kString;
      return String(&v->text) ? Status::Ok() : Bad("bad string in \"" + key + "\"");
    }
    if (c == '[') {
      ++i_;
      v->kind = FlatJsonValue::kArray;
      if (Eat(']')) return Status::Ok();
      do {
        double x = 0;
        if (!Number(&x) || v->array.size() >= rules_.max_array) {
          return Bad("\"" + key + "\": numbers only");
        }
        v->array.push_back(x);
      } while (Eat(','));
      return Eat(']') ? Status::Ok() : Bad("\"" + key + "\": expected ']'");
    }
    for (const char* word : {"true", "false", "null"}) {
      if (s_.compare(i_, std::strlen(word), word) == 0) {
        i_ += std::strlen(word);
        v->kind = word[0] == 'n' ? FlatJsonValue::kNull : FlatJsonValue::kBool;
        v->flag = word[0] == 't';
        return Status::Ok();
      }
    }
    v->kind = FlatJsonValue::kNumber;
    return Number(&v->number) ? Status::Ok() : Bad("bad value of \"" + key + "\"");
  }

  const std::string& s_;
  const FlatJsonRules& rules_;
  size_t i_ = 0;
};

}  // namespace

Status ReadFlatJson(const std::string& text, const FlatJsonRules& rules,
                    std::map<std::string, FlatJsonValue>* members) {
  return Reader(text, rules).Object(members);
}

}  // namespace sightline
