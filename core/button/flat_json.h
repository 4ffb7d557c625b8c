// A strict reader of one flat JSON object, the shape of every line of the arm protocol
// (PROTOCOL.md): members are strings, numbers, numeric arrays, true, false or null. Used by the
// arm_pose parser (client to server) and the simulated arm's reader of server lines.
#pragma once

#include <cstddef>
#include <map>
#include <string>
#include <vector>

#include "core/common/status.h"

namespace sightline {

// A member's value.
struct FlatJsonValue {
  enum Kind { kString, kNumber, kArray, kBool, kNull } kind = kNull;
  std::string text;
  double number = 0;
  bool flag = false;
  std::vector<double> array;
};

struct FlatJsonRules {
  std::string prefix;     // Starts every error message, e.g. "arm_pose: ".
  size_t max_array = 64;  // Longer numeric arrays are refused.
  bool escapes = true;    // \" \\ \/ \b \f \n \r \t in strings; false: any '\' is refused.
  std::string not_object = "not a JSON object";  // The message when no '{' starts the text.
};

// Reads `text` as one flat object. InvalidArgument (prefixed) naming the member otherwise:
// not an object, a bad string or number (plain decimal only: no hex, inf or nan), a nested
// object, a non-numeric array element, a duplicate member, text after the object.
Status ReadFlatJson(const std::string& text, const FlatJsonRules& rules,
                    std::map<std::string, FlatJsonValue>* members);

}  // namespace sightline
