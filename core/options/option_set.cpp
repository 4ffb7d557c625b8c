#include "core/options/option_set.h"

#include <yaml-cpp/yaml.h>

#include <fstream>
#include <map>
#include <sstream>

#include "core/common/json_writer.h"
#include "core/common/text_file.h"

namespace sightline {

Status OptionSet::Declare(const OptionSpec& spec) {
  if (spec.key.empty()) return InvalidArgument("an option has an empty key");
  if (Has(spec.key)) return InvalidArgument("option '" + spec.key + "' is declared twice");
  SIGHTLINE_RETURN_IF_ERROR(
      CheckOptionValue(spec, spec.default_value).WithContext("default of a declared option"));
  specs_.push_back(spec);
  values_[spec.key] = spec.default_value;
  return Status::Ok();
}

const OptionSpec* OptionSet::FindSpec(const std::string& key) const {
  for (const OptionSpec& s : specs_) {
    if (s.key == key) return &s;
  }
  return nullptr;
}

StatusOr<OptionValue> OptionSet::Get(const std::string& key) const {
  auto it = values_.find(key);
  if (it == values_.end()) return NotFound("unknown option '" + key + "'");
  return it->second;
}

Status OptionSet::Set(const std::string& key, const OptionValue& value, const std::string& origin) {
  const OptionSpec* spec = FindSpec(key);
  Status status;
  if (spec == nullptr) {
    status = NotFound("unknown option '" + key + "'");
  } else {
    // An integer given where a number is expected is fine.
    OptionValue v = value;
    if (spec->type == OptionType::kDouble && std::holds_alternative<int64_t>(v)) {
      v = static_cast<double>(std::get<int64_t>(v));
    }
    status = CheckOptionValue(*spec, v);
    if (status.ok()) values_[key] = v;
  }
  return origin.empty() ? status : status.WithContext(origin);
}

Status OptionSet::SetFromString(const std::string& key, const std::string& text,
                                const std::string& origin) {
  const OptionSpec* spec = FindSpec(key);
  if (spec == nullptr) {
    Status s = NotFound("unknown option '" + key + "'");
    return origin.empty() ? s : s.WithContext(origin);
  }
  StatusOr<OptionValue> value = ParseOptionValue(*spec, text);
  if (!value.ok()) return origin.empty() ? value.status() : value.status().WithContext(origin);
  return Set(key, *value, origin);
}

Status OptionSet::ApplyOverride(const std::string& assignment) {
  const size_t eq = assignment.find('=');
  if (eq == std::string::npos || eq == 0) {
    return InvalidArgument("--set '" + assignment + "': expected key=value");
  }
  return SetFromString(assignment.substr(0, eq), assignment.substr(eq + 1), "--set " + assignment);
}

void OptionSet::ResetToDefaults() {
  for (const OptionSpec& s : specs_) values_[s.key] = s.default_value;
}

void OptionSet::Reset(const std::string& key) {
  if (const OptionSpec* s = FindSpec(key)) values_[key] = s->default_value;
}

namespace {

using ProfileEntries = std::vector<std::tuple<std::string, std::string, int>>;

// Rejects [ and { nested deeper than a profile ever needs before the parser, which recurses
// once per level, sees them.
Status CheckFlowNesting(const std::string& text, const std::string& origin) {
  int depth = 0, line = 1;
  char quote = 0;
  for (char c : text) {
    if (c == '\n') ++line;
    if (quote != 0) {
      if (c == quote || c == '\n') quote = 0;
      continue;
    }
    if (c == '"' || c == '\'') {
      quote = c;
    } else if (c == '[' || c == '{') {
      if (++depth > kMaxProfileDepth) {
        return ParseError(origin + " line " + std::to_string(line) +
                          ": lists or maps nest deeper than " + std::to_string(kMaxProfileDepth) +
                          " levels");
      }
    } else if ((c == ']' || c == '}') && depth > 0) {
      --depth;
    }
  }
  return Status::Ok();
}

std::string At(const std::string& origin, int line) {
  return origin + " line " + std::to_string(line);
}

// Collects (dotted key, scalar text, line) from a YAML tree. Keys must be plain words; a key
// given twice (also once nested and once dotted) is an error naming both lines.
Status Flatten(const YAML::Node& node, const std::string& prefix, const std::string& origin,
               int depth, std::map<std::string, int>* lines, ProfileEntries* out) {
  const int line = node.Mark().line + 1;
  if (depth > kMaxProfileDepth) {
    return ParseError(At(origin, line) + ": options nest deeper than " +
                      std::to_string(kMaxProfileDepth) + " levels");
  }
  if (node.IsMap()) {
    for (const auto& item : node) {
      if (!item.first.IsScalar()) {
        return ParseError(At(origin, item.first.Mark().line + 1) +
                          ": an option key must be a word, not a list or map");
      }
      const std::string key = item.first.Scalar();
      SIGHTLINE_RETURN_IF_ERROR(Flatten(item.second, prefix.empty() ? key : prefix + "." + key,
                                        origin, depth + 1, lines, out));
    }
    return Status::Ok();
  }
  if (node.IsScalar()) {
    if (out->size() >= kMaxProfileEntries) {
      return ParseError(origin + ": more than " + std::to_string(kMaxProfileEntries) +
                        " values (aliases expanding?); a profile lists each option once");
    }
    const auto [it, inserted] = lines->emplace(prefix, line);
    if (!inserted) {
      return ParseError(At(origin, line) + ": option '" + prefix + "' is given twice (also line " +
                        std::to_string(it->second) + ")");
    }
    out->emplace_back(prefix, node.Scalar(), line);
    return Status::Ok();
  }
  if (node.IsNull()) {
    return ParseError(At(origin, line) + ": option '" + prefix + "' has no value");
  }
  return ParseError(At(origin, line) + ": option '" + prefix +
                    "' must be a single value, not a list");
}

}  // namespace

Status OptionSet::LoadYamlText(const std::string& text, const std::string& origin) {
  SIGHTLINE_RETURN_IF_ERROR(CheckFlowNesting(text, origin));
  YAML::Node root;
  try {
    root = YAML::Load(text);
  } catch (const YAML::Exception& e) {
    return ParseError(origin + " line " + std::to_string(e.mark.line + 1) + ": " + e.msg);
  } catch (const std::exception& e) {
    return ParseError(origin + ": not a readable YAML profile: " + e.what());
  }
  if (root.IsNull()) return Status::Ok();  // An empty profile changes nothing.
  if (!root.IsMap()) return ParseError(origin + ": a profile must be a map of option keys");
  ProfileEntries entries;
  std::map<std::string, int> lines;
  SIGHTLINE_RETURN_IF_ERROR(Flatten(root, "", origin, 0, &lines, &entries));
  OptionSet updated = *this;
  for (const auto& [key, value, line] : entries) {
    SIGHTLINE_RETURN_IF_ERROR(
        updated.SetFromString(key, value, origin + " line " + std::to_string(line)));
  }
  *this = std::move(updated);
  return Status::Ok();
}

Status OptionSet::LoadYaml(const std::string& path) {
  StatusOr<std::string> text = ReadWholeTextFile(path, kMaxProfileBytes, "profile");
  if (!text.ok()) return text.status();
  return LoadYamlText(*text, path);
}

OptionSet OptionSet::Without(const std::string& prefix) const {
  OptionSet subset;
  for (const OptionSpec& spec : specs_) {
    if (spec.key.compare(0, prefix.size(), prefix) == 0) continue;
    subset.specs_.push_back(spec);
    subset.values_[spec.key] = values_.at(spec.key);
  }
  return subset;
}

std::string OptionSet::ToYaml() const {
  // Written by hand rather than by YAML::Emitter, whose comments land after the previous key:
  // here each description stands on its own key's line. Scalars are still quoted by the
  // emitter so that every value reads back as written.
  std::string text;
  std::vector<std::string> open;  // Currently open path components.
  for (const OptionSpec& spec : specs_) {
    std::vector<std::string> parts;
    std::stringstream ss(spec.key);
    for (std::string p; std::getline(ss, p, '.');) parts.push_back(p);
    size_t common = 0;
    while (common < open.size() && common + 1 < parts.size() && open[common] == parts[common]) {
      ++common;
    }
    open.resize(common);
    for (size_t i = common; i + 1 < parts.size(); ++i) {
      text += std::string(2 * open.size(), ' ') + parts[i] + ":\n";
      open.push_back(parts[i]);
    }
    YAML::Emitter scalar;
    scalar << FormatOptionValue(values_.at(spec.key));
    std::string comment = spec.description;
    if (!spec.unit.empty()) comment += " [" + spec.unit + "]";
    for (char& c : comment) {
      if (c == '\n' || c == '\r') c = ' ';
    }
    text += std::string(2 * open.size(), ' ') + parts.back() + ": " + scalar.c_str();
    if (!comment.empty()) text += "  # " + comment;
    text += "\n";
  }
  return text;
}

Status OptionSet::SaveYaml(const std::string& path) const {
  std::ofstream out(path);
  if (!out) return NotFound("cannot write profile " + path);
  out << "# Sightline options profile\n" << ToYaml();
  out.flush();
  if (!out) return Unavailable("write to " + path + " failed (disk full?)");
  return Status::Ok();
}

void OptionSet::WriteJson(JsonWriter* writer) const {
  writer->BeginObject();
  for (const OptionSpec& spec : specs_) {
    writer->Key(spec.key);
    const OptionValue& v = values_.at(spec.key);
    if (const bool* b = std::get_if<bool>(&v)) {
      writer->Bool(*b);
    } else if (const int64_t* i = std::get_if<int64_t>(&v)) {
      writer->Int(*i);
    } else if (const double* d = std::get_if<double>(&v)) {
      writer->Double(*d);
    } else {
      writer->String(std::get<std::string>(v));
    }
  }
  writer->EndObject();
}

}  // namespace sightline
