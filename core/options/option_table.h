// Binds the fields of a typed Options struct to OptionSpecs, so that one struct feeds the
// GUI's tuning panel, YAML profiles and CLI overrides without string-typed parameter maps.
#pragma once

#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "core/options/option_spec.h"

namespace sightline {

// The Describe() table of an Options struct T.
//
//   struct RansacOptions {
//     int max_iterations = 250;  // Iterations per line.
//     static OptionTable<RansacOptions> Describe() {
//       return OptionTable<RansacOptions>("mapping.ransac")
//           .Int("max_iterations", &RansacOptions::max_iterations, "", 1, 100000, 1,
//                "RANSAC iterations per line before giving up.");
//     }
//   };
template <typename T>
class OptionTable {
 public:
  // One option: its spec (with key relative to the table's prefix) and typed access.
  struct Entry {
    OptionSpec spec;
    std::function<OptionValue(const T&)> get;
    std::function<void(T*, const OptionValue&)> set;
  };

  explicit OptionTable(std::string prefix) : prefix_(std::move(prefix)) {}

  OptionTable& Double(const std::string& key, double T::*field, const std::string& unit, double min,
                      double max, double step, const std::string& description) {
    return Add(
        key, OptionType::kDouble, unit, min, max, step, {}, description,
        [field](const T& o) { return OptionValue(o.*field); },
        [field](T* o, const OptionValue& v) { o->*field = std::get<double>(v); });
  }
  OptionTable& Int(const std::string& key, int T::*field, const std::string& unit, double min,
                   double max, double step, const std::string& description) {
    return Add(
        key, OptionType::kInt, unit, min, max, step, {}, description,
        [field](const T& o) { return OptionValue(static_cast<int64_t>(o.*field)); },
        [field](T* o, const OptionValue& v) {
          o->*field = static_cast<int>(std::get<int64_t>(v));
        });
  }
  OptionTable& Bool(const std::string& key, bool T::*field, const std::string& description) {
    return Add(
        key, OptionType::kBool, "", 0, 1, 1, {}, description,
        [field](const T& o) { return OptionValue(o.*field); },
        [field](T* o, const OptionValue& v) { o->*field = std::get<bool>(v); });
  }
  OptionTable& String(const std::string& key, std::string T::*field,
                      const std::string& description) {
    return Add(
        key, OptionType::kString, "", 0, 0, 1, {}, description,
        [field](const T& o) { return OptionValue(o.*field); },
        [field](T* o, const OptionValue& v) { o->*field = std::get<std::string>(v); });
  }
  OptionTable& Choice(const std::string& key, std::string T::*field,
                      const std::vector<std::string>& choices, const std::string& description) {
    return Add(
        key, OptionType::kChoice, "", 0, 0, 1, choices, description,
        [field](const T& o) { return OptionValue(o.*field); },
        [field](T* o, const OptionValue& v) { o->*field = std::get<std::string>(v); });
  }
  // Includes the table of a member struct, e.g. the RANSAC options inside mapping's options.
  template <typename U>
  OptionTable& Nested(U T::*field, const OptionTable<U>& table) {
    for (const auto& e : table.entries()) {
      Entry entry;
      entry.spec = e.spec;
      entry.spec.key = Join(table.prefix().empty() ? "" : table.prefix(), e.spec.key);
      auto get = e.get;
      auto set = e.set;
      entry.get = [field, get](const T& o) { return get(o.*field); };
      entry.set = [field, set](T* o, const OptionValue& v) { set(&(o->*field), v); };
      entries_.push_back(std::move(entry));
    }
    return *this;
  }

  const std::string& prefix() const { return prefix_; }
  // Entries with keys relative to prefix().
  const std::vector<Entry>& entries() const { return entries_; }

  // Full specs (prefix + key) with defaults taken from `defaults`.
  std::vector<OptionSpec> Specs(const T& defaults = T()) const {
    std::vector<OptionSpec> specs;
    for (const auto& e : entries_) {
      OptionSpec s = e.spec;
      s.key = Join(prefix_, e.spec.key);
      s.default_value = e.get(defaults);
      specs.push_back(std::move(s));
    }
    return specs;
  }

  // Full key -> current value of each field.
  std::vector<std::pair<std::string, OptionValue>> Values(const T& options) const {
    std::vector<std::pair<std::string, OptionValue>> values;
    for (const auto& e : entries_) values.emplace_back(Join(prefix_, e.spec.key), e.get(options));
    return values;
  }

  // Sets the field with the given full key. The value must already be checked against the spec.
  bool SetValue(T* options, const std::string& full_key, const OptionValue& value) const {
    for (const auto& e : entries_) {
      if (Join(prefix_, e.spec.key) == full_key) {
        e.set(options, value);
        return true;
      }
    }
    return false;
  }

 private:
  static std::string Join(const std::string& a, const std::string& b) {
    return a.empty() ? b : a + "." + b;
  }
  OptionTable& Add(const std::string& key, OptionType type, const std::string& unit, double min,
                   double max, double step, const std::vector<std::string>& choices,
                   const std::string& description, std::function<OptionValue(const T&)> get,
                   std::function<void(T*, const OptionValue&)> set) {
    Entry e;
    e.spec.key = key;
    e.spec.type = type;
    e.spec.unit = unit;
    e.spec.min = min;
    e.spec.max = max;
    e.spec.step = step;
    e.spec.choices = choices;
    e.spec.description = description;
    e.get = std::move(get);
    e.set = std::move(set);
    entries_.push_back(std::move(e));
    return *this;
  }

  std::string prefix_;
  std::vector<Entry> entries_;
};

}  // namespace sightline
