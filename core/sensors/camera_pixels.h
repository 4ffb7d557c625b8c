// Converting machine-vision camera buffers (GenICam PFNC pixel formats) to OpenCV images.
// Independent of Aravis so it is testable and reusable by any GenICam driver.
#pragma once

#include <cstddef>
#include <cstdint>
#include <opencv2/core.hpp>
#include <string>

#include "core/common/status.h"

namespace sightline {

// GenICam Pixel Format Naming Convention codes that Sightline converts (values as in Aravis'
// ARV_PIXEL_FORMAT_*).
namespace pfnc {
inline constexpr uint32_t kMono8 = 0x01080001u;
inline constexpr uint32_t kMono10 = 0x01100003u;  // 10 bits in 16-bit containers.
inline constexpr uint32_t kMono12 = 0x01100005u;
inline constexpr uint32_t kMono14 = 0x01100025u;
inline constexpr uint32_t kMono16 = 0x01100007u;
inline constexpr uint32_t kBayerGR8 = 0x01080008u;
inline constexpr uint32_t kBayerRG8 = 0x01080009u;
inline constexpr uint32_t kBayerGB8 = 0x0108000au;
inline constexpr uint32_t kBayerBG8 = 0x0108000bu;
inline constexpr uint32_t kBayerGR16 = 0x0110002eu;
inline constexpr uint32_t kBayerRG16 = 0x0110002fu;
inline constexpr uint32_t kBayerGB16 = 0x01100030u;
inline constexpr uint32_t kBayerBG16 = 0x01100031u;
inline constexpr uint32_t kRgb8 = 0x02180014u;
inline constexpr uint32_t kBgr8 = 0x02180015u;
}  // namespace pfnc

// "Mono8", "BayerRG8", ... or "0x........" for formats Sightline does not know.
std::string PixelFormatName(uint32_t pixel_format);

// Converts one image buffer to a new cv::Mat owning its data:
//  - Mono8 -> CV_8UC1; Mono10/12/14/16 (16-bit containers) -> CV_8UC1 scaled to 8 bits;
//  - Bayer 8/16 -> CV_8UC3 BGR (demosaiced) when `debayer`, else the raw mosaic as CV_8UC1;
//  - RGB8 -> CV_8UC3 BGR; BGR8 -> CV_8UC3.
// `stride` is the row length in bytes (0 = packed). Errors name the format and the sizes.
StatusOr<cv::Mat> ConvertCameraImage(uint32_t pixel_format, int width, int height, const void* data,
                                     size_t size, bool debayer, size_t stride = 0);

}  // namespace sightline
