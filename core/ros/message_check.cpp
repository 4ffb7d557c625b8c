#include "core/ros/message_check.h"

#include <map>
#include <memory>
#include <mutex>
#include <sstream>

namespace sightline {
namespace {

struct Field {
  std::string type;  // Builtin ("float64", "string", ...) or a full message name ("pkg/Name").
  std::string name;
  bool is_array = false;
  int64_t fixed_count = -1;  // For "type[N]"; -1 for a variable-length array.
};

using Schema = std::map<std::string, std::vector<Field>>;

// Bytes of a fixed-size builtin; 0 for string and for message types.
size_t BuiltinSize(const std::string& type) {
  static const std::map<std::string, size_t> sizes = {
      {"bool", 1},  {"int8", 1},   {"uint8", 1},   {"byte", 1},   {"char", 1},
      {"int16", 2}, {"uint16", 2}, {"int32", 4},   {"uint32", 4}, {"float32", 4},
      {"int64", 8}, {"uint64", 8}, {"float64", 8}, {"time", 8},   {"duration", 8}};
  auto it = sizes.find(type);
  return it == sizes.end() ? 0 : it->second;
}

bool IsBuiltin(const std::string& type) { return type == "string" || BuiltinSize(type) > 0; }

std::string Trim(const std::string& s) {
  const size_t b = s.find_first_not_of(" \t\r");
  if (b == std::string::npos) return "";
  return s.substr(b, s.find_last_not_of(" \t\r") - b + 1);
}

// A field's type as written ("Header", "Point", "geometry_msgs/Point") as a full message name.
std::string Qualify(const std::string& type, const std::string& package) {
  if (IsBuiltin(type) || type.find('/') != std::string::npos) return type;
  if (type == "Header") return "std_msgs/Header";
  return package + "/" + type;
}

StatusOr<Schema> ParseDefinition(const std::string& type, const std::string& definition) {
  Schema schema;
  std::string current = type;
  schema[current];
  std::istringstream lines(definition);
  std::string line;
  while (std::getline(lines, line)) {
    line = Trim(line.substr(0, line.find('#')));
    if (line.empty()) continue;
    if (line.rfind("====", 0) == 0) continue;
    if (line.rfind("MSG:", 0) == 0) {
      current = Trim(line.substr(4));
      schema[current];
      continue;
    }
    std::istringstream words(line);
    std::string field_type, name;
    words >> field_type >> name;
    if (name.empty()) {
      return InvalidArgument("the definition of " + current + " has a line without a name: \"" +
                             line + "\"");
    }
    if (line.find('=') != std::string::npos) continue;  // A constant: not serialized.
    Field f;
    f.name = name;
    const size_t bracket = field_type.find('[');
    if (bracket != std::string::npos) {
      f.is_array = true;
      const std::string count = field_type.substr(bracket + 1, field_type.size() - bracket - 2);
      if (!count.empty()) {
        if (count.size() > 9 || count.find_first_not_of("0123456789") != std::string::npos) {
          return InvalidArgument("the definition of " + current + " has an array size \"" + count +
                                 "\" in \"" + line + "\"");
        }
        f.fixed_count = std::stoll(count);
      }
      field_type = field_type.substr(0, bracket);
    }
    const std::string package = current.substr(0, current.find('/'));
    f.type = Qualify(field_type, package);
    schema[current].push_back(f);
  }
  return schema;
}

class Walker {
 public:
  Walker(const Schema& schema, const uint8_t* data, size_t size)
      : schema_(schema), data_(data), size_(size) {}

  Status Message(const std::string& type, const std::string& path, int depth) {
    if (depth > 32) return InvalidArgument(path + ": message types nest more than 32 deep");
    auto it = schema_.find(type);
    if (it == schema_.end()) {
      return InvalidArgument("the definition does not define " + type + " (field " + path + ")");
    }
    for (const Field& f : it->second) {
      const std::string name = path.empty() ? f.name : path + "." + f.name;
      Status ok = f.is_array ? Array(f, name, depth) : Value(f.type, name, depth);
      if (!ok.ok()) return ok;
    }
    return Status::Ok();
  }

 private:
  size_t Left() const { return size_ - pos_; }

  Status Need(size_t bytes, const std::string& name) {
    if (bytes > Left()) {
      return InvalidArgument("field " + name + " needs " + std::to_string(bytes) +
                             " bytes but the message has " + std::to_string(Left()) + " left");
    }
    pos_ += bytes;
    return Status::Ok();
  }

  StatusOr<uint32_t> Count(const std::string& name) {
    if (Left() < 4) {
      return InvalidArgument("field " + name + ": the message ends before its length");
    }
    uint32_t n = 0;
    for (int i = 3; i >= 0; --i) n = (n << 8) | data_[pos_ + static_cast<size_t>(i)];
    pos_ += 4;
    return n;
  }

  Status Value(const std::string& type, const std::string& name, int depth) {
    if (type == "string") {
      StatusOr<uint32_t> n = Count(name);
      if (!n.ok()) return n.status();
      return Need(*n, name);
    }
    if (const size_t bytes = BuiltinSize(type)) return Need(bytes, name);
    return Message(type, name, depth + 1);
  }

  Status Array(const Field& f, const std::string& name, int depth) {
    uint64_t n = 0;
    if (f.fixed_count >= 0) {
      n = static_cast<uint64_t>(f.fixed_count);
    } else {
      StatusOr<uint32_t> count = Count(name);
      if (!count.ok()) return count.status();
      n = *count;
    }
    if (const size_t bytes = BuiltinSize(f.type)) {
      if (n > Left() / bytes) {
        return InvalidArgument("field " + name + " declares " + std::to_string(n) + " " + f.type +
                               " values (" + std::to_string(n * bytes) +
                               " bytes) but the message has " + std::to_string(Left()) +
                               " bytes left");
      }
      pos_ += static_cast<size_t>(n * bytes);
      return Status::Ok();
    }
    // Strings and messages: each element takes at least one byte here except an empty message,
    // so a count beyond the bytes left is a lie whatever the elements are.
    if (n > Left()) {
      return InvalidArgument("field " + name + " declares " + std::to_string(n) +
                             " elements but the message has " + std::to_string(Left()) +
                             " bytes left");
    }
    for (uint64_t i = 0; i < n; ++i) {
      Status ok = Value(f.type, name + "[" + std::to_string(i) + "]", depth);
      if (!ok.ok()) return ok;
    }
    return Status::Ok();
  }

  const Schema& schema_;
  const uint8_t* data_;
  size_t size_;
  size_t pos_ = 0;
};

}  // namespace

Status CheckSerializedMessage(const std::string& type, const std::string& definition,
                              const uint8_t* data, size_t size) {
  // Every message of a type has the same definition: parse it once, not for every message the
  // readers check (every image of a bag or a live topic). Bounded: callers use a few types.
  static std::mutex mutex;
  static std::map<std::string, std::shared_ptr<const Schema>> parsed;
  const std::string key = type + '\n' + definition;
  std::shared_ptr<const Schema> schema;
  {
    std::lock_guard<std::mutex> lock(mutex);
    if (auto it = parsed.find(key); it != parsed.end()) schema = it->second;
  }
  if (!schema) {
    StatusOr<Schema> fresh = ParseDefinition(type, definition);
    if (!fresh.ok()) return fresh.status();
    schema = std::make_shared<const Schema>(std::move(*fresh));
    std::lock_guard<std::mutex> lock(mutex);
    if (parsed.size() < 64) parsed.emplace(key, schema);
  }
  Status ok = Walker(*schema, data, size).Message(type, "", 0);
  if (!ok.ok()) return ok.WithContext(type);
  return ok;
}

}  // namespace sightline
