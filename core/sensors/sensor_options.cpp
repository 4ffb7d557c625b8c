#include "core/sensors/sensor_options.h"

#include "core/io/rosbag_options.h"
#include "core/sensors/aravis_options.h"
#include "core/sensors/openni2_options.h"
#include "core/sensors/replay_source.h"
#include "core/sensors/v4l2_source.h"

namespace sightline {

Status DeclareOpenNi2Options(OptionSet* options) {
  return options->Declare(OpenNi2Options::Describe());
}

Status DeclareAravisOptions(OptionSet* options) {
  SIGHTLINE_RETURN_IF_ERROR(options->Declare(AravisOptions::Describe()));
  return options->Declare(AravisStereoOptions::Describe());
}

Status DeclareV4l2Options(OptionSet* options) { return options->Declare(V4l2Options::Describe()); }

Status DeclareReplayOptions(OptionSet* options) {
  return options->Declare(ReplayOptions::Describe());
}

Status DeclareRosBagOptions(OptionSet* options) {
  return options->Declare(RosBagOptions::Describe());
}

Status DeclareSensorOptions(OptionSet* options) {
  SIGHTLINE_RETURN_IF_ERROR(DeclareOpenNi2Options(options));
  SIGHTLINE_RETURN_IF_ERROR(DeclareAravisOptions(options));
  SIGHTLINE_RETURN_IF_ERROR(DeclareV4l2Options(options));
  SIGHTLINE_RETURN_IF_ERROR(DeclareReplayOptions(options));
  return DeclareRosBagOptions(options);
}

}  // namespace sightline
