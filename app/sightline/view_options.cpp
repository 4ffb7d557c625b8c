#include "app/sightline/view_options.h"

namespace sightline {

bool ViewOptions::IsValid(std::string* error) const {
  if (cloud_stride < 1) {
    if (error) *error = "view.cloud_stride must be at least 1";
    return false;
  }
  if (!(max_depth_m > 0) || !(depth_range_m > 0)) {
    if (error) *error = "view depth limits must be positive";
    return false;
  }
  return true;
}

OptionTable<ViewOptions> ViewOptions::Describe() {
  return OptionTable<ViewOptions>("view")
      .Int("cloud_stride", &ViewOptions::cloud_stride, "px", 1, 16, 1,
           "Use every n-th depth pixel for the 3D cloud; 1 shows all (slower).")
      .Double("max_depth_m", &ViewOptions::max_depth_m, "m", 0.2, 50, 0.1,
              "Depth beyond this is left out of the 3D cloud.")
      .Double("depth_range_m", &ViewOptions::depth_range_m, "m", 0.5, 50, 0.5,
              "The depth colour map spans zero to this range.");
}

}  // namespace sightline
