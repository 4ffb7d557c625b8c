// Private ROS parameters mirrored from a pipeline's option tables: option key
// "mapping.ransac.threshold" is the private parameter ~mapping/ransac/threshold (ROS names allow
// no dots; nested like a YAML profile, so `rosparam load profile.yaml ~` works too).
#pragma once

#include <ros/node_handle.h>

#include <string>
#include <vector>

#include "core/options/option_set.h"

namespace sightline::node {

// The parameter name of an option key ("a.b.c" -> "a/b/c") and back.
std::string ParamNameOfOption(const std::string& key);
std::string OptionOfParamName(const std::string& name);

// What the private parameters set: "key=value" overrides for the options `options` declares
// (read once, at start), and a warning for each private parameter that names no option.
struct ParamOverrides {
  std::vector<std::string> overrides;
  std::vector<std::string> warnings;
};
// `private_nh` is the node's "~" handle; `reserved` are the node's own parameters (not options).
ParamOverrides ReadParamOverrides(const OptionSet& options, const ros::NodeHandle& private_nh,
                                  const std::vector<std::string>& reserved = {});

}  // namespace sightline::node
