#include "app/sightline/builtin_presenters.h"

#include "app/sightline/button_picker_presenter.h"
#include "app/sightline/mapping_presenter.h"
#include "app/sightline/mobility_presenter.h"
#include "app/sightline/mono_slam_presenter.h"
#include "app/sightline/statistics_presenter.h"
#include "app/sightline/stereo_vo_presenter.h"

namespace sightline {

std::vector<PipelinePresenter*> MakeBuiltinPresenters() {
  std::vector<PipelinePresenter*> presenters;
  const PipelineRegistry registry = BuiltinPipelines();
  for (const PipelineInfo& info : registry.pipelines()) {
    if (info.name == "mapping") {
      presenters.push_back(new MappingPresenter());
    } else if (info.name == "stereo-vo") {
      presenters.push_back(new StereoVoPresenter());
    } else if (info.name == "mobility") {
      presenters.push_back(new MobilityPresenter());
    } else if (info.name == "mono-slam") {
      presenters.push_back(new MonoSlamPresenter());
    } else if (info.name == "button") {
      presenters.push_back(new ButtonPickerPresenter());
    } else {
      presenters.push_back(new StatisticsPresenter(info));
    }
  }
  return presenters;
}

}  // namespace sightline
