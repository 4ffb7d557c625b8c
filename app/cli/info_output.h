// What `sightline-cli info` prints for an opened source, in the front binary and the full one.
#pragma once

#include "core/io/source.h"

namespace sightline::cli {

// Prints DescribeSourceText (or DescribeSourceJson when `json`) of `source` to stdout, ending
// in a newline. Returns the exit code, 0.
int PrintSourceInfo(const Source& source, bool json);

}  // namespace sightline::cli
