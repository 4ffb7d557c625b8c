#include "core/io/source.h"

namespace sightline {

const char* SourceKindName(SourceKind kind) {
  switch (kind) {
    case SourceKind::kRgbd:
      return "RGB-D";
    case SourceKind::kStereo:
      return "stereo";
    case SourceKind::kMono:
      return "mono";
    case SourceKind::kCloud:
      return "point cloud";
  }
  return "unknown";
}

}  // namespace sightline
