// A sensor device found by a driver's enumeration.
#pragma once

#include <string>

namespace sightline {

// One attached device, as a driver lists it for a "Sensors" menu.
struct DeviceInfo {
  std::string driver;   // Registry name: "openni2", "aravis", "v4l2".
  std::string uri;      // What OpenSource() opens, e.g. "aravis://Basler-21234567".
  std::string name;     // Vendor and model for people, e.g. "Basler acA1300-60gm".
  std::string serial;   // Serial number, when the driver knows it.
  std::string details;  // Transport facts, e.g. "GigEVision 192.168.1.20".
};

}  // namespace sightline
