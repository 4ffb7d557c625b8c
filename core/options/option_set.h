// The options registry: every declared option with its current value; YAML profiles and
// `--set key=value` overrides. Unknown keys and out-of-range values are errors that name the key
// and, for files, the file and line.
#pragma once

#include <cstddef>
#include <map>
#include <string>
#include <vector>

#include "core/common/status.h"
#include "core/options/option_spec.h"
#include "core/options/option_table.h"

namespace sightline {

// A profile is a short list of options: anything far larger is not one (and a small file of
// nested aliases would otherwise expand to gigabytes). LoadYaml refuses larger files unread,
// and more values or deeper nesting before they are expanded.
inline constexpr size_t kMaxProfileBytes = size_t{1} << 20;
inline constexpr size_t kMaxProfileEntries = 10000;
inline constexpr int kMaxProfileDepth = 16;

class JsonWriter;

// A value type: copy it to hand options to a worker thread.
//
//   OptionSet options;
//   options.Declare(MappingOptions::Describe());
//   SIGHTLINE_RETURN_IF_ERROR(options.LoadYaml("profile.yaml"));
//   SIGHTLINE_RETURN_IF_ERROR(options.ApplyOverride("mapping.ransac.max_iterations=500"));
//   MappingOptions mapping = options.Extract(MappingOptions::Describe());
class OptionSet {
 public:
  // Adds an option with its default as current value. Fails on a duplicate key or a default
  // that violates the spec's own range.
  Status Declare(const OptionSpec& spec);
  // Declares every option of a Describe() table with defaults from `defaults`.
  template <typename T>
  Status Declare(const OptionTable<T>& table, const T& defaults = T()) {
    for (const OptionSpec& spec : table.Specs(defaults)) SIGHTLINE_RETURN_IF_ERROR(Declare(spec));
    return Status::Ok();
  }

  // Specs in declaration order.
  const std::vector<OptionSpec>& specs() const { return specs_; }
  const OptionSpec* FindSpec(const std::string& key) const;
  bool Has(const std::string& key) const { return FindSpec(key) != nullptr; }

  // The current value; NotFound for an unknown key.
  StatusOr<OptionValue> Get(const std::string& key) const;
  // Checks type and range; `origin` (e.g. "profile.yaml line 4") prefixes errors.
  Status Set(const std::string& key, const OptionValue& value, const std::string& origin = "");
  Status SetFromString(const std::string& key, const std::string& text,
                       const std::string& origin = "");
  // Applies "key=value" as given to `--set`.
  Status ApplyOverride(const std::string& assignment);
  void ResetToDefaults();
  void Reset(const std::string& key);

  // Reads a profile: nested maps ("mapping: {ransac: {max_iterations: 500}}") or dotted keys.
  // All or nothing: on error the set is unchanged.
  Status LoadYaml(const std::string& path);
  Status LoadYamlText(const std::string& text, const std::string& origin);
  // Writes every option as nested YAML with descriptions as comments.
  Status SaveYaml(const std::string& path) const;
  std::string ToYaml() const;
  // Writes {"key": value, ...} (flat dotted keys) as one JSON object value.
  void WriteJson(JsonWriter* writer) const;

  // A copy without the options whose keys start with `prefix` (e.g. "view." for a profile that
  // holds only a pipeline's options).
  OptionSet Without(const std::string& prefix) const;

  // Fills a typed Options struct from the current values of the table's keys.
  template <typename T>
  T Extract(const OptionTable<T>& table, T options = T()) const {
    for (const auto& [key, unused] : table.Values(options)) {
      auto it = values_.find(key);
      if (it != values_.end()) table.SetValue(&options, key, it->second);
    }
    return options;
  }
  // Copies the fields of a typed Options struct into the set (keys must be declared).
  template <typename T>
  Status Store(const OptionTable<T>& table, const T& options) {
    for (const auto& [key, value] : table.Values(options))
      SIGHTLINE_RETURN_IF_ERROR(Set(key, value));
    return Status::Ok();
  }

 private:
  std::vector<OptionSpec> specs_;
  std::map<std::string, OptionValue> values_;
};

}  // namespace sightline
