// The GUI's presenters: one per pipeline of the core registry (BuiltinPipelines()), in its
// order, so the Pipeline menu lists exactly what `sightline-cli run` runs.
#pragma once

#include <vector>

#include "app/sightline/pipeline_presenter.h"

namespace sightline {

// A new presenter for each registry pipeline: the pipeline's own views where it has them, the
// statistics table otherwise. The caller (the main window) takes ownership.
std::vector<PipelinePresenter*> MakeBuiltinPresenters();

}  // namespace sightline
