// The typed description of one tunable option: key, type, unit, range, step and meaning.
#pragma once

#include <cstdint>
#include <string>
#include <variant>
#include <vector>

#include "core/common/status.h"

namespace sightline {

enum class OptionType { kBool, kInt, kDouble, kString, kChoice };
const char* OptionTypeName(OptionType type);  // "bool", "int", "double", "string", "choice".

// The value of an option. kInt holds int64_t, kChoice and kString hold std::string.
using OptionValue = std::variant<bool, int64_t, double, std::string>;

// One row of a Describe() table. The GUI turns it into a spin box, check box or combo box;
// the CLI into a `--set key=value` key; YAML profiles into a nested key.
struct OptionSpec {
  std::string key;  // Dotted, e.g. "mapping.ransac.max_iterations".
  OptionType type = OptionType::kDouble;
  std::string unit;                  // "m", "deg", "px", "ms", "" for counts and ratios.
  double min = 0;                    // Inclusive lower bound (kInt, kDouble).
  double max = 0;                    // Inclusive upper bound (kInt, kDouble).
  double step = 1;                   // Spin-box step (kInt, kDouble).
  std::vector<std::string> choices;  // Allowed values (kChoice).
  std::string description;           // One sentence: what it does, and why one would change it.
  OptionValue default_value;
};

// "0.035", "250", "true", "ransac".
std::string FormatOptionValue(const OptionValue& value);
// Parses text as the spec's type. Errors name the key.
StatusOr<OptionValue> ParseOptionValue(const OptionSpec& spec, const std::string& text);
// Checks that value has the spec's type and lies in range / among the choices.
Status CheckOptionValue(const OptionSpec& spec, const OptionValue& value);

}  // namespace sightline
