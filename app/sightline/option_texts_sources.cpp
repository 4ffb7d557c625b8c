#include <set>

#include "app/sightline/option_texts.h"
#include "app/sightline/view_options.h"
#include "core/options/option_set.h"
#include "core/pipeline/pipeline_registry.h"

namespace sightline {

std::vector<std::string> OptionTextsToMark() {
  std::set<std::string> texts;
  for (const OptionSpec& spec : ViewOptions::Describe().Specs()) texts.insert(spec.description);
  const PipelineRegistry registry = BuiltinPipelines();
  for (const PipelineInfo& pipeline : registry.pipelines()) {
    if (!pipeline.declare_options) continue;
    OptionSet options;  // One set per pipeline: pipelines may share keys.
    if (!pipeline.declare_options(&options).ok()) continue;  // Tests report declaration errors.
    for (const OptionSpec& spec : options.specs()) texts.insert(spec.description);
  }
  texts.erase(std::string());
  return {texts.begin(), texts.end()};
}

}  // namespace sightline
