#include "core/options/option_spec.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace sightline {

const char* OptionTypeName(OptionType type) {
  switch (type) {
    case OptionType::kBool:
      return "bool";
    case OptionType::kInt:
      return "int";
    case OptionType::kDouble:
      return "double";
    case OptionType::kString:
      return "string";
    case OptionType::kChoice:
      return "choice";
  }
  return "unknown";
}

std::string FormatOptionValue(const OptionValue& value) {
  if (const bool* b = std::get_if<bool>(&value)) return *b ? "true" : "false";
  if (const int64_t* i = std::get_if<int64_t>(&value)) return std::to_string(*i);
  if (const double* d = std::get_if<double>(&value)) {
    char buffer[32];
    std::snprintf(buffer, sizeof(buffer), "%.10g", *d);
    return buffer;
  }
  return std::get<std::string>(value);
}

namespace {

std::string Range(const OptionSpec& spec) {
  return "[" + FormatOptionValue(spec.min) + ", " + FormatOptionValue(spec.max) + "]" +
         (spec.unit.empty() ? "" : " " + spec.unit);
}

}  // namespace

StatusOr<OptionValue> ParseOptionValue(const OptionSpec& spec, const std::string& text) {
  const std::string where = "option '" + spec.key + "'";
  switch (spec.type) {
    case OptionType::kBool: {
      std::string t = text;
      std::transform(t.begin(), t.end(), t.begin(),
                     [](unsigned char c) { return std::tolower(c); });
      if (t == "true" || t == "1" || t == "yes" || t == "on") return OptionValue(true);
      if (t == "false" || t == "0" || t == "no" || t == "off") return OptionValue(false);
      return InvalidArgument(where + ": '" + text + "' is not a boolean (true/false)");
    }
    case OptionType::kInt: {
      errno = 0;
      char* end = nullptr;
      const long long v = std::strtoll(text.c_str(), &end, 10);
      if (text.empty() || *end != '\0' || errno == ERANGE) {
        return InvalidArgument(where + ": '" + text + "' is not an integer");
      }
      return OptionValue(static_cast<int64_t>(v));
    }
    case OptionType::kDouble: {
      char* end = nullptr;
      const double v = std::strtod(text.c_str(), &end);
      if (text.empty() || *end != '\0') {
        return InvalidArgument(where + ": '" + text + "' is not a number");
      }
      return OptionValue(v);
    }
    case OptionType::kString:
    case OptionType::kChoice:
      return OptionValue(text);
  }
  return Internal(where + ": unknown type");
}

Status CheckOptionValue(const OptionSpec& spec, const OptionValue& value) {
  const std::string where = "option '" + spec.key + "'";
  switch (spec.type) {
    case OptionType::kBool:
      if (!std::holds_alternative<bool>(value))
        return InvalidArgument(where + " expects true or false");
      return Status::Ok();
    case OptionType::kInt: {
      if (!std::holds_alternative<int64_t>(value))
        return InvalidArgument(where + " expects an integer");
      const double v = static_cast<double>(std::get<int64_t>(value));
      if (v < spec.min || v > spec.max) {
        return InvalidArgument(where + ": " + FormatOptionValue(value) + " is outside " +
                               Range(spec));
      }
      return Status::Ok();
    }
    case OptionType::kDouble: {
      if (!std::holds_alternative<double>(value))
        return InvalidArgument(where + " expects a number");
      const double v = std::get<double>(value);
      if (!std::isfinite(v)) return InvalidArgument(where + ": value is not finite");
      if (v < spec.min || v > spec.max) {
        return InvalidArgument(where + ": " + FormatOptionValue(value) + " is outside " +
                               Range(spec));
      }
      return Status::Ok();
    }
    case OptionType::kString:
      if (!std::holds_alternative<std::string>(value))
        return InvalidArgument(where + " expects text");
      return Status::Ok();
    case OptionType::kChoice: {
      if (!std::holds_alternative<std::string>(value))
        return InvalidArgument(where + " expects a choice");
      const std::string& v = std::get<std::string>(value);
      if (std::find(spec.choices.begin(), spec.choices.end(), v) == spec.choices.end()) {
        std::string list;
        for (const auto& c : spec.choices) list += (list.empty() ? "" : ", ") + c;
        return InvalidArgument(where + ": '" + v + "' is not one of: " + list);
      }
      return Status::Ok();
    }
  }
  return Internal(where + ": unknown type");
}

}  // namespace sightline
