// The run loop's sources in the full library: every sensor driver, ROS bags, sim:// and datasets.
#include "core/pipeline/run_sources.h"
#include "core/pipeline/sim_panel_source.h"
#include "core/sensors/driver_registry.h"

namespace sightline {

bool IsRunSourceLive(const std::string& uri) { return IsLiveUri(uri); }

StatusOr<std::unique_ptr<Source>> OpenLiveRunSource(const std::string& uri,
                                                    const OptionSet& options) {
  return OpenRunSource(uri, options);
}

StatusOr<std::unique_ptr<Source>> OpenAnyRunSource(const std::string& uri,
                                                   const OptionSet& options) {
  return OpenSource(uri, options);
}

Status DeclareRunSourceOptions(const std::string& uri, OptionSet* options) {
  return DeclareSourceOptions(uri, options);
}

Status PrepareRunSource(const std::string& uri, const std::string& out_dir, OptionSet* options) {
  return PrepareSimRun(uri, out_dir, options);
}

}  // namespace sightline
