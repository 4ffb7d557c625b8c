// The subsampling sweep of `sightline-cli sweep stereo-vo` (the stereo seed's Table 1): the
// stereo-vo pipeline run by the headless loop once per factor k, every k-th frame, each
// estimate's path length compared with the ground truth's.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "core/common/status.h"
#include "core/eval/subsample_sweep.h"
#include "core/options/option_set.h"

namespace sightline {

// Runs stereo-vo over `path` for k = first..last with `options` (the registry's stereo-vo
// option set; stereo.subsample is replaced by k, stereo.gt_tolerance_s pairs the poses) and
// returns one row per k. `starting(k)` is called before each run. Errors: a run failed (the
// message starts "k = K: "), or the dataset has no ground truth.
StatusOr<std::vector<SubsampleRow>> SweepStereoVo(const std::string& path, const OptionSet& options,
                                                  int first, int last,
                                                  const std::function<void(int)>& starting = {});

}  // namespace sightline
