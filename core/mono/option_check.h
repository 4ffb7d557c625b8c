// A helper for the IsValid(std::string*) checks of the monocular SLAM options.
#pragma once

#include <string>

namespace sightline::mono_internal {

// Sets *error (when given) and returns false, so checks read `if (bad) return Invalid(e, "...")`.
inline bool Invalid(std::string* error, const std::string& message) {
  if (error) *error = message;
  return false;
}

}  // namespace sightline::mono_internal
