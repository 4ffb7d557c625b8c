// Hand-labelled panel photos (tests/data/button_panels/labels.csv): one line per button,
// printed label or blank tap of a photo, "file,kind,x0,y0,x1,y1,name" with kind button|label
// (a box, inclusive pixel corners) or blank (a tap at x0,y0). Lines starting with '#' are
// comments. Read by the real-panel tests and by the region classifier's training.
#pragma once

#include <map>
#include <opencv2/core.hpp>
#include <string>
#include <vector>

#include "core/common/status.h"

namespace sightline {

struct PanelLabel {
  enum class Kind { kButton, kLabel, kBlank };
  std::string file;  // Photo file name, relative to the photos' directory.
  Kind kind = Kind::kButton;
  std::string name;
  cv::Rect2d box;   // Buttons and labels.
  cv::Point2d tap;  // The box centre; the tap itself for blanks.
};

// The labels of `path`; an error names the file and line of the first bad one.
StatusOr<std::vector<PanelLabel>> ReadPanelLabels(const std::string& path);

// The labels grouped by photo file, in file order.
std::map<std::string, std::vector<const PanelLabel*>> ByPhoto(const std::vector<PanelLabel>& all);

}  // namespace sightline
