// Options of the frame views (not of a pipeline): how the current frame is turned into pictures.
#pragma once

#include <string>

#include "core/options/option_table.h"

namespace sightline {

// How frames are shown in the image and 3D views.
struct ViewOptions {
  int cloud_stride = 2;        // Use every n-th depth pixel for the 3D cloud (1 = all).
  double max_depth_m = 6.0;    // Depth beyond this is left out of the cloud [m].
  double depth_range_m = 5.0;  // Depth colour map spans 0..this [m].

  bool IsValid(std::string* error) const;
  static OptionTable<ViewOptions> Describe();
};

}  // namespace sightline
