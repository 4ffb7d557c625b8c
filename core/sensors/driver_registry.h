// The sensor drivers Sightline has, each with an availability probe, device enumeration, its
// options and a factory; and OpenSource(), which opens any sensor URI or dataset path.
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "core/common/status.h"
#include "core/io/source.h"
#include "core/options/option_set.h"
#include "core/sensors/device_info.h"
#include "core/sensors/sensor_options.h"  // DeclareSensorOptions

namespace sightline {

// One sensor driver. Built explicitly by BuiltinDrivers() (no static registration). A driver
// left out of the build is still listed: available() then says so, which lets a GUI show it
// greyed out with the reason.
struct DriverInfo {
  std::string name;         // "openni2", "aravis", "v4l2".
  std::string description;  // One line for menus and `--help`.
  std::string scheme;       // URI prefix, e.g. "openni2://".
  // Ok when the driver can be used here; else kUnavailable with the reason ("not built: ...",
  // "no /dev/video* device", "OpenNI2 failed to initialise: ...").
  std::function<Status()> available;
  // Devices attached now (may block about a second, e.g. GigE discovery). Reads the driver's
  // options from the set (e.g. sensors.aravis.fake_interface); empty when unavailable.
  std::function<std::vector<DeviceInfo>(const OptionSet& options)> enumerate;
  // Declares the driver's options (`sensors.<name>.*`) in a set.
  std::function<Status(OptionSet*)> declare_options;
  // A source for a URI of this driver's scheme (or, for openni2, an .oni path), not yet opened,
  // configured from the options in the set (undeclared keys take their defaults). Fails for
  // invalid options or when the driver is not built.
  std::function<StatusOr<std::unique_ptr<Source>>(const std::string& uri, const OptionSet& options)>
      create;
};

// openni2, aravis, v4l2, replay and rosbag, in that order.
std::vector<DriverInfo> BuiltinDrivers();

// The driver called `name` in `drivers`, or nullptr.
const DriverInfo* FindDriver(const std::vector<DriverInfo>& drivers, const std::string& name);

// True for "openni2://...", "aravis://...", "v4l2://...", "replay://...", "rosbag://..." and
// paths ending in .oni or .bag (files a driver reads rather than dataset folders).
bool IsSensorUri(const std::string& uri);

// Declares the options of the driver that opens `uri` (e.g. io.rosbag.* for a .bag file) that
// `options` lacks, so that a pipeline run on it takes `--set` for them. Nothing for datasets.
Status DeclareSourceOptions(const std::string& uri, OptionSet* options);

// Bytes of an ONI recording's file header ("NI10", version, largest timestamp, largest node id).
inline constexpr size_t kOniHeaderBytes = 24;

// Why `path` cannot be an .oni recording, before OpenNI2 (which only says "could not be opened")
// tries it: NotFound "<path>: no such file"; InvalidArgument when it is a folder or a device;
// Unavailable with the system's reason (permission denied); ParseError "<path> is too short for
// an ONI recording (N bytes; its header alone is 24)" or "<path> is not an ONI recording (it
// does not start with the ONI header 'NI10')". Ok for a file that starts like one.
Status CheckOniFile(const std::string& path);

// Opens anything Sightline can read frames from and returns the open source:
//   "openni2://" (first device), "openni2://DEVICE_URI", "openni2://file.oni" or "file.oni";
//   "aravis://" (first camera), "aravis://DEVICE_ID", "aravis://LEFT_ID,RIGHT_ID" (stereo;
//   "aravis://LEFT_ID,RIGHT_ID?calibration_file=FILE" attaches a stereo calibration);
//   "v4l2://0", "v4l2:///dev/video0";
//   "replay://PATH?fps=30&loop=1" (a recording paced as a live camera, replay_source.h);
//   "file.bag" or "rosbag://file.bag" (a ROS bag, core/ros/bag_source.h; io.rosbag.* options);
//   anything else: a dataset or recording folder through OpenDataset().
// core/io cannot open sensors itself (core/sensors sits above it); front ends call this.
//
//   OptionSet options;
//   DeclareSensorOptions(&options);
//   options.ApplyOverride("sensors.aravis.exposure_us=5000");
//   auto source = OpenSource("aravis://Basler-21234567", options);
//   if (!source.ok()) return source.status();   // e.g. "Aravis camera '...' is not available"
StatusOr<std::unique_ptr<Source>> OpenSource(const std::string& uri,
                                             const OptionSet& options = OptionSet());

}  // namespace sightline
