// A picture of a score function over slope and roughness (the GPR surface of the seed's
// Fig. 3) with Table I's cell centres marked.
#pragma once

#include <opencv2/core.hpp>

#include "core/mobility/mobility_score.h"

namespace sightline {

// BGR image: slope 0-60 deg left to right, roughness 1.0-2.4 bottom to top, coloured by the
// GPR's score (red 0, green 1), grid lines at Table I's band edges, and each cell centre as a
// dot filled with the rule's score (white ring). width x height pixels of plot area plus axes.
cv::Mat RenderScoreSurface(const GprScore& gpr, int width = 360, int height = 280);

}  // namespace sightline
