#include "core/common/frame.h"

namespace sightline {

const FrameStamp& StampOf(const Frame& frame) {
  return std::visit([](const auto& f) -> const FrameStamp& { return f.stamp; }, frame);
}

}  // namespace sightline
