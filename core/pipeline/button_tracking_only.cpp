// The figures and notes of a button run without a metric scale (button_scale_mode.h).
#include <algorithm>

#include "core/pipeline/button_pipeline.h"

namespace sightline {

void ButtonPipeline::AddTrackingOnlyFigures(RunResult* result,
                                            std::vector<std::string>* notes) const {
  int64_t tracked = 0, located = 0;
  for (size_t i = 1; i < log_.rows.size(); ++i) {  // rows[0] is the tap frame itself.
    tracked += log_.rows[i].picker.track.found ? 1 : 0;
    located += log_.rows[i].button_in_map.allFinite() ? 1 : 0;
  }
  result->counts.emplace_back("frames_tracked", static_cast<double>(tracked));
  result->counts.emplace_back("frames_located_map_units", static_cast<double>(located));
  result->counts.emplace_back("targets_suppressed_no_scale",
                              static_cast<double>(log_.suppressed_targets));
  // "No target was sent" is what this mode promises, not news.
  notes->erase(std::remove(notes->begin(), notes->end(), "no target was sent"), notes->end());
  notes->insert(
      notes->begin(),
      {std::string(kNoMetricScaleNote) +
           " (tracking only: the button is tracked and located in map units, "
           "button.csv's metre columns are empty, no target is ever sent)",
       !scale_mode_.metric ? scale_mode_.how
       : feed_ == ArmPoseInput::kLiveSource
           ? "tracking only: mono.run.metric_source = auto and the live source gave no arm pose "
             "in " +
                 std::to_string(frames_) + " frame(s) (the first: " + arm_stream_.first_missing +
                 ")"
           : "tracking only: mono.run.metric_source = auto while serving, no "
             "arm_poses.txt beside the images and no arm streamed its pose"});
  if (log_.tap_index < 0) {
    result->nothing_achieved =
        "nothing tracked: no button was tapped in " + std::to_string(frames_) + " frame(s)";
  } else if (tracked == 0) {
    result->nothing_achieved = "nothing tracked: the button tapped at frame " +
                               std::to_string(log_.tap_index) + " was not found again in the " +
                               std::to_string(frames_ - log_.tap_index - 1) + " frame(s) after";
  }
}

}  // namespace sightline
