// The size an image file declares in its header, read before decoding so that a header that
// lies (a 100000 x 100000 PNG of a few hundred bytes) is refused before the decoder allocates
// gigabytes. PNG, JPEG, PGM/PPM and BMP; other formats are left to the decoder's own limit.
#pragma once

#include <opencv2/core.hpp>
#include <optional>
#include <string>

#include "core/common/status.h"

namespace sightline {

// The width and height `path` declares; nullopt for a format this reader does not know (or a
// JPEG whose frame header lies beyond the first 16 MB of markers). ParseError naming the file
// when a known format's header is truncated or declares a zero or negative size; Unavailable
// when the file cannot be read.
StatusOr<std::optional<cv::Size>> ReadImageHeaderSize(const std::string& path);

// Ok when the declared size of `path` is within kMaxImageSidePx per side and kMaxImagePixels
// (core/common/input_limits.h); else InvalidArgument naming the file, its declared size and the
// limit. Unknown formats pass (the decoder's own limit applies).
Status CheckImageHeaderSize(const std::string& path);

}  // namespace sightline
