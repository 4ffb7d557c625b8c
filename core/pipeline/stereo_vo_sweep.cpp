#include "core/pipeline/stereo_vo_sweep.h"

#include <optional>
#include <utility>

#include "core/pipeline/stereo_vo_pipeline.h"

namespace sightline {

StatusOr<std::vector<SubsampleRow>> SweepStereoVo(const std::string& path, const OptionSet& options,
                                                  int first, int last,
                                                  const std::function<void(int)>& starting) {
  std::vector<SubsampleEstimate> estimates;
  std::optional<Trajectory> ground_truth;
  for (int k = first; k <= last; ++k) {
    if (starting) starting(k);
    const std::string context = "k = " + std::to_string(k);
    OptionSet with_k = options;
    SIGHTLINE_RETURN_IF_ERROR(
        with_k.SetFromString("stereo.subsample", std::to_string(k)).WithContext(context));
    StatusOr<StereoVoRun> run = RunStereoOdometry(path, with_k);
    if (!run.ok()) return run.status().WithContext(context);
    if (!run->ground_truth) return FailedPrecondition(path + " has no ground truth");
    ground_truth = std::move(run->ground_truth);
    estimates.push_back({k, std::move(run->estimate)});
  }
  if (!ground_truth) return InvalidArgument("the sweep needs first <= last");
  const StereoVoRunOptions run = options.Extract(StereoVoRunOptions::Describe());
  return EvaluateSubsampleSweep(estimates, *ground_truth, run.gt_tolerance_s);
}

}  // namespace sightline
