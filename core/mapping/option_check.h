// Small helpers for the mapping stages' Options::IsValid(std::string*) checks.
#pragma once

#include <string>

namespace sightline::mapping_internal {

// Stores `message` in *error (when given) and returns false, so checks read
//   if (!(x > 0)) return Invalid(error, "mapping.scan.resolution_deg must be positive");
inline bool Invalid(std::string* error, const std::string& message) {
  if (error != nullptr) *error = message;
  return false;
}

}  // namespace sightline::mapping_internal
