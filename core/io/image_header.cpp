#include "core/io/image_header.h"

#include <array>
#include <cctype>
#include <cstdint>
#include <fstream>

#include "core/common/input_limits.h"

namespace sightline {
namespace {

using Bytes = std::array<unsigned char, 32>;

uint32_t BigEndian32(const unsigned char* p) {
  return (uint32_t{p[0]} << 24) | (uint32_t{p[1]} << 16) | (uint32_t{p[2]} << 8) | p[3];
}
uint16_t BigEndian16(const unsigned char* p) { return static_cast<uint16_t>((p[0] << 8) | p[1]); }
int32_t LittleEndian32(const unsigned char* p) {
  return static_cast<int32_t>(uint32_t{p[0]} | (uint32_t{p[1]} << 8) | (uint32_t{p[2]} << 16) |
                              (uint32_t{p[3]} << 24));
}

Status Truncated(const std::string& path, const char* format) {
  return ParseError(path + ": truncated " + format + " header");
}

// Walks the JPEG markers to the first start-of-frame (SOF0..SOF15 except DHT, JPG, DAC).
StatusOr<std::optional<cv::Size>> JpegSize(std::ifstream& in, const std::string& path) {
  in.seekg(2);
  constexpr std::streamoff kMaxScan = std::streamoff{16} << 20;
  while (in && in.tellg() < kMaxScan) {
    unsigned char marker[2];
    if (!in.read(reinterpret_cast<char*>(marker), 2)) break;
    if (marker[0] != 0xFF) return ParseError(path + ": corrupt JPEG header (no marker)");
    if (marker[1] == 0xFF) {  // Fill byte.
      in.seekg(-1, std::ios::cur);
      continue;
    }
    if (marker[1] == 0xD8 || (marker[1] >= 0xD0 && marker[1] <= 0xD7) || marker[1] == 0x01) {
      continue;  // Markers without a length.
    }
    unsigned char length_bytes[2];
    if (!in.read(reinterpret_cast<char*>(length_bytes), 2)) break;
    const uint16_t length = BigEndian16(length_bytes);
    if (length < 2) return ParseError(path + ": corrupt JPEG header (segment length < 2)");
    const bool sof = marker[1] >= 0xC0 && marker[1] <= 0xCF && marker[1] != 0xC4 &&
                     marker[1] != 0xC8 && marker[1] != 0xCC;
    if (sof) {
      unsigned char frame[5];
      if (!in.read(reinterpret_cast<char*>(frame), 5)) return Truncated(path, "JPEG");
      return std::optional<cv::Size>(cv::Size(BigEndian16(frame + 3), BigEndian16(frame + 1)));
    }
    if (marker[1] == 0xDA || marker[1] == 0xD9) break;  // Scan data or end before a frame.
    in.seekg(length - 2, std::ios::cur);
  }
  if (in.eof()) return Truncated(path, "JPEG");
  return std::optional<cv::Size>();
}

// "P5"/"P6"/"P2"/"P3" then width and height, with comments.
StatusOr<std::optional<cv::Size>> NetpbmSize(std::ifstream& in, const std::string& path) {
  in.seekg(2);
  long long values[2] = {0, 0};
  for (long long& value : values) {
    int c = in.get();
    while (c != EOF && (std::isspace(c) || c == '#')) {
      if (c == '#') {
        while (c != EOF && c != '\n') c = in.get();
      }
      c = in.get();
    }
    if (c == EOF || !std::isdigit(c)) return Truncated(path, "PGM/PPM");
    value = 0;
    for (int digits = 0; c != EOF && std::isdigit(c); c = in.get(), ++digits) {
      if (digits > 10) return ParseError(path + ": PGM/PPM size has too many digits");
      value = value * 10 + (c - '0');
    }
  }
  return std::optional<cv::Size>(
      cv::Size(static_cast<int>(std::min<long long>(values[0], 1LL << 30)),
               static_cast<int>(std::min<long long>(values[1], 1LL << 30))));
}

}  // namespace

StatusOr<std::optional<cv::Size>> ReadImageHeaderSize(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return Unavailable(path + ": cannot be read");
  Bytes head{};
  in.read(reinterpret_cast<char*>(head.data()), head.size());
  const std::streamsize got = in.gcount();
  in.clear();
  StatusOr<std::optional<cv::Size>> size = std::optional<cv::Size>();
  if (got >= 8 && head[0] == 0x89 && head[1] == 'P' && head[2] == 'N' && head[3] == 'G') {
    if (got < 24) return Truncated(path, "PNG");
    const uint32_t w = BigEndian32(&head[16]), h = BigEndian32(&head[20]);
    size = std::optional<cv::Size>(cv::Size(static_cast<int>(std::min<uint32_t>(w, 1u << 30)),
                                            static_cast<int>(std::min<uint32_t>(h, 1u << 30))));
  } else if (got >= 2 && head[0] == 0xFF && head[1] == 0xD8) {
    size = JpegSize(in, path);
  } else if (got >= 2 && head[0] == 'P' && head[1] >= '2' && head[1] <= '6' && head[1] != '4') {
    size = NetpbmSize(in, path);
  } else if (got >= 2 && head[0] == 'B' && head[1] == 'M') {
    if (got < 26) return Truncated(path, "BMP");
    const int64_t w = LittleEndian32(&head[18]), h = LittleEndian32(&head[22]);
    const int64_t abs_h = h < 0 ? -h : h;
    size = std::optional<cv::Size>(cv::Size(static_cast<int>(std::min<int64_t>(w, 1 << 30)),
                                            static_cast<int>(std::min<int64_t>(abs_h, 1 << 30))));
  }
  if (!size.ok()) return size.status();
  if (*size && ((*size)->width <= 0 || (*size)->height <= 0)) {
    return ParseError(path + ": the image header declares a size of " +
                      std::to_string((*size)->width) + " x " + std::to_string((*size)->height));
  }
  return size;
}

Status CheckImageHeaderSize(const std::string& path) {
  StatusOr<std::optional<cv::Size>> size = ReadImageHeaderSize(path);
  if (!size.ok()) return size.status();
  if (!*size) return Status::Ok();
  const cv::Size s = **size;
  const double pixels = static_cast<double>(s.width) * s.height;
  if (s.width > kMaxImageSidePx || s.height > kMaxImageSidePx || pixels > kMaxImagePixels) {
    return InvalidArgument(path + ": the image header declares " + std::to_string(s.width) + " x " +
                           std::to_string(s.height) + " pixels; at most " +
                           std::to_string(kMaxImageSidePx) + " per side and " +
                           std::to_string(static_cast<long long>(kMaxImagePixels)) +
                           " in all are accepted");
  }
  return Status::Ok();
}

}  // namespace sightline
