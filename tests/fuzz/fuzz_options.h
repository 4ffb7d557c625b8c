// An option set with one option of every type, nested two and three levels deep, as the
// pipelines declare theirs: the profile and `--set` fuzzers parse into it.
#pragma once

#include "core/options/option_set.h"

namespace sightline::fuzz {

inline OptionSet FuzzOptionSet() {
  OptionSet options;
  auto spec = [](std::string key, OptionType type, double min, double max, OptionValue value) {
    OptionSpec s;
    s.key = std::move(key);
    s.type = type;
    s.min = min;
    s.max = max;
    s.default_value = std::move(value);
    return s;
  };
  (void)options.Declare(
      spec("mapping.ransac.max_iterations", OptionType::kInt, 1, 100000, int64_t{250}));
  (void)options.Declare(spec("mapping.floor.epsilon_m", OptionType::kDouble, 0.001, 1.0, 0.035));
  (void)options.Declare(spec("mapping.run.floor_file", OptionType::kString, 0, 0, std::string()));
  (void)options.Declare(spec("stereo.enabled", OptionType::kBool, 0, 0, true));
  OptionSpec choice = spec("stereo.matcher", OptionType::kChoice, 0, 0, std::string("sad"));
  choice.choices = {"sad", "census"};
  (void)options.Declare(choice);
  return options;
}

}  // namespace sightline::fuzz
