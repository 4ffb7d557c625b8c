#include "app/cli/program_pipelines.h"

#ifdef SIGHTLINE_HAVE_ROS
#include "core/ros/ros_client.h"
#include "core/ros/ros_live_source.h"
#endif

namespace sightline::cli {

PipelineRegistry ProgramPipelines() { return BuiltinPipelines(); }

SourceOpener ProgramSourceOpener(const std::string& path, const std::atomic<bool>* cancel) {
#ifdef SIGHTLINE_HAVE_ROS
  if (IsRosLiveUri(path)) {
    return [cancel](const std::string& uri) { return OpenRosLiveSourceAsClient(uri, cancel); };
  }
#endif
  return {};
}

}  // namespace sightline::cli
