// The options of the sensor drivers (`sensors.<driver>.*`, `io.rosbag.*`) without the drivers:
// a program that runs only recorded datasets declares the same option set as one that opens
// sensors (a run's metrics.json lists them), without linking OpenNI2, Aravis or ROS.
#pragma once

#include "core/common/status.h"
#include "core/options/option_set.h"

namespace sightline {

// Each driver's options, as its DriverInfo::declare_options (driver_registry.h) declares them.
Status DeclareOpenNi2Options(OptionSet* options);
Status DeclareAravisOptions(OptionSet* options);  // Mono and stereo (sensors.aravis.stereo.*).
Status DeclareV4l2Options(OptionSet* options);
Status DeclareReplayOptions(OptionSet* options);
Status DeclareRosBagOptions(OptionSet* options);

// Declares the options of every built-in driver, in BuiltinDrivers()' order: openni2, aravis,
// v4l2, replay, rosbag.
Status DeclareSensorOptions(OptionSet* options);

}  // namespace sightline
