// Training and evaluation samples of the region classifier (region_classifier.h) from labelled
// panel photos (panel_labels.h): the region the detector selects for taps on each button and
// each printed label.
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "core/button/button_detector.h"
#include "core/button/panel_labels.h"

namespace sightline {

struct RegionSample {
  Eigen::VectorXd features;
  int is_button = 0;  // 1: the tapped button's own region; 0: a region selected at a label.
};

// Taps at each button's and label's box centre and, with `jitter`, at four more points a
// quarter of the box's half-size off it. A button tap gives a button sample when the selected
// region's centroid lies in that button's box and in no other labelled box; a label tap gives a
// non-button sample when it selects a region that is not a button holding the tap. Regions are
// found with `options` (its classifier switched off).
std::vector<RegionSample> SampleRegions(const ButtonDetectorOptions& options, const cv::Mat& photo,
                                        const std::vector<const PanelLabel*>& labels, bool jitter);

// What a tap at `tap` on a button or label (`tapped`, one of `photo_labels`) gives, by the
// real-panel rules: right when the region's centroid lies in that button's box and in no other
// labelled box; a neighbour or a label when another box holds it; for a label, allowed when
// nothing is selected or a button whose box holds the tap.
enum class TapOutcome { kRight, kNeighbour, kLabel, kElsewhere, kNone, kLabelSelected, kLabelOk };

TapOutcome JudgeTap(const PanelLabel& tapped, cv::Point2d tap, const StatusOr<ButtonModel>& region,
                    const std::vector<const PanelLabel*>& photo_labels);

}  // namespace sightline
