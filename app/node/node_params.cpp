#include "app/node/node_params.h"

#include <ros/master.h>
#include <ros/param.h>

#include <algorithm>
#include <charconv>

namespace sightline::node {

std::string ParamNameOfOption(const std::string& key) {
  std::string name = key;
  std::replace(name.begin(), name.end(), '.', '/');
  return name;
}

std::string OptionOfParamName(const std::string& name) {
  std::string key = name;
  std::replace(key.begin(), key.end(), '/', '.');
  return key;
}

namespace {

// A parameter's value as the text `--set key=value` takes; "" for lists and dictionaries.
std::string ParamText(XmlRpc::XmlRpcValue& value) {
  switch (value.getType()) {
    case XmlRpc::XmlRpcValue::TypeBoolean:
      return static_cast<bool>(value) ? "true" : "false";
    case XmlRpc::XmlRpcValue::TypeInt:
      return std::to_string(static_cast<int>(value));
    case XmlRpc::XmlRpcValue::TypeDouble: {
      char text[64];  // The shortest text that reads back as the same double.
      const auto end = std::to_chars(text, text + sizeof(text), static_cast<double>(value)).ptr;
      return std::string(text, end);
    }
    case XmlRpc::XmlRpcValue::TypeString:
      return static_cast<std::string>(value);
    default:
      return "";
  }
}

}  // namespace

ParamOverrides ReadParamOverrides(const OptionSet& options, const ros::NodeHandle& private_nh,
                                  const std::vector<std::string>& reserved) {
  ParamOverrides out;
  std::vector<std::string> names;
  if (!ros::param::getParamNames(names)) {
    out.warnings.push_back("could not list the parameters on the master");
    return out;
  }
  const std::string prefix = private_nh.getNamespace() + "/";
  for (const std::string& full : names) {
    if (full.compare(0, prefix.size(), prefix) != 0) continue;
    const std::string name = full.substr(prefix.size());
    if (std::find(reserved.begin(), reserved.end(), name) != reserved.end()) continue;
    const std::string key = OptionOfParamName(name);
    if (!options.Has(key)) {
      out.warnings.push_back("parameter ~" + name + " names no option (option key " + key + ")");
      continue;
    }
    XmlRpc::XmlRpcValue value;
    if (!ros::param::get(full, value)) continue;
    const std::string text = ParamText(value);
    if (text.empty()) {
      out.warnings.push_back("parameter ~" + name + " is a list or dictionary; " + key +
                             " takes a single value");
      continue;
    }
    out.overrides.push_back(key + "=" + text);
  }
  return out;
}

}  // namespace sightline::node
