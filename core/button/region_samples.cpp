#include "core/button/region_samples.h"

#include "core/button/region_classifier.h"

namespace sightline {

TapOutcome JudgeTap(const PanelLabel& tapped, cv::Point2d tap, const StatusOr<ButtonModel>& region,
                    const std::vector<const PanelLabel*>& photo_labels) {
  const bool found = region.ok();
  const cv::Point2d c = found ? region->center : cv::Point2d(-1, -1);
  const PanelLabel* holder = nullptr;  // Another labelled box holding the centroid.
  for (const PanelLabel* o : photo_labels) {
    if (o != &tapped && o->kind != PanelLabel::Kind::kBlank && o->box.contains(c)) holder = o;
  }
  if (tapped.kind == PanelLabel::Kind::kLabel) {
    const bool allowed = !found || (holder && holder->kind == PanelLabel::Kind::kButton &&
                                    holder->box.contains(tap));
    return allowed ? TapOutcome::kLabelOk : TapOutcome::kLabelSelected;
  }
  if (!found) return TapOutcome::kNone;
  if (tapped.box.contains(c) && !holder) return TapOutcome::kRight;
  if (holder && holder->kind == PanelLabel::Kind::kButton) return TapOutcome::kNeighbour;
  if (holder) return TapOutcome::kLabel;
  return TapOutcome::kElsewhere;
}

std::vector<RegionSample> SampleRegions(const ButtonDetectorOptions& options, const cv::Mat& photo,
                                        const std::vector<const PanelLabel*>& labels, bool jitter) {
  ButtonDetectorOptions plain = options;
  plain.min_button_probability = 0;
  const ButtonDetector detector(plain);
  const cv::Mat grey = ToGrey(photo);
  std::vector<RegionSample> out;
  for (const PanelLabel* l : labels) {
    if (l->kind == PanelLabel::Kind::kBlank) continue;
    std::vector<cv::Point2d> taps = {l->tap};
    if (jitter) {
      const double dx = 0.125 * l->box.width, dy = 0.125 * l->box.height;
      for (const cv::Point2d d :
           {cv::Point2d(dx, 0), cv::Point2d(-dx, 0), cv::Point2d(0, dy), cv::Point2d(0, -dy)}) {
        taps.push_back(l->tap + d);
      }
    }
    for (const cv::Point2d& tap : taps) {
      const StatusOr<ButtonModel> region = detector.FindRegion(grey, tap);
      if (!region.ok()) continue;
      const TapOutcome outcome = JudgeTap(*l, tap, region, labels);
      if (outcome != TapOutcome::kRight && outcome != TapOutcome::kLabelSelected) continue;
      out.push_back({RegionFeatures(grey, region->box), outcome == TapOutcome::kRight ? 1 : 0});
    }
  }
  return out;
}

}  // namespace sightline
