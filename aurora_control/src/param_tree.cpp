#include "param_tree.h"

#include <algorithm>
#include <cstdio>
#include <set>

#include "aurora_control/params/yaml_reader.h"
#include "aurora_common/ros/params.h"
#include "aurora_common/yaml_file.h"

namespace aurora_control {

YAML::Node yamlFromXmlRpc(XmlRpc::XmlRpcValue& v) {
  switch (v.getType()) {
    case XmlRpc::XmlRpcValue::TypeStruct: {
      YAML::Node map(YAML::NodeType::Map);
      for (auto& kv : v) map[kv.first] = yamlFromXmlRpc(kv.second);
      return map;
    }
    case XmlRpc::XmlRpcValue::TypeArray: {
      YAML::Node seq(YAML::NodeType::Sequence);
      for (int i = 0; i < v.size(); ++i) seq.push_back(yamlFromXmlRpc(v[i]));
      return seq;
    }
    case XmlRpc::XmlRpcValue::TypeDouble:
      return YAML::Node(aurora_common::roundTripText(static_cast<double>(v)));
    case XmlRpc::XmlRpcValue::TypeInt:
      return YAML::Node(static_cast<int>(v));
    case XmlRpc::XmlRpcValue::TypeBoolean:
      return YAML::Node(static_cast<bool>(v) ? "true" : "false");
    case XmlRpc::XmlRpcValue::TypeString: {
      // Tagged as a quoted scalar: a string stays a string even if it reads as a number.
      YAML::Node text(static_cast<std::string>(v));
      text.SetTag("!");
      return text;
    }
    default:
      return YAML::Node();
  }
}

YAML::Node paramAsYaml(const ros::NodeHandle& nh, const std::string& key) {
  XmlRpc::XmlRpcValue v;
  if (!nh.getParam(key, v)) return YAML::Node();
  return yamlFromXmlRpc(v);
}

void refuseUnknownParams(const ros::NodeHandle& nh, const std::string& group,
                         const std::vector<std::string>& accepted, const std::string& hint) {
  std::vector<std::string> names;
  ros::param::getParamNames(names);
  const std::string prefix = (group.empty() ? nh.getNamespace() : aurora_common::fullKey(nh, group)) + "/";
  std::set<std::string> seen;
  for (const std::string& name : names) {
    if (name.compare(0, prefix.size(), prefix) != 0) continue;
    const std::string rest = name.substr(prefix.size());
    const std::string first = rest.substr(0, rest.find('/'));
    if (!seen.insert(first).second) continue;
    if (std::find(accepted.begin(), accepted.end(), first) == accepted.end()) {
      throw aurora_common::ConfigError("parameter '" + prefix + first + "' is not a known key: accepted " +
                                       joinKeys(accepted) + (hint.empty() ? "" : " (" + hint + ")"));
    }
  }
}

void refuseDuplicatedKeysInLoadedFiles(const ros::NodeHandle& pnh) {
  if (!pnh.hasParam("yaml_files")) return;
  std::vector<std::string> files;
  if (!pnh.getParam("yaml_files", files)) {
    throw aurora_common::ConfigError("parameter '" + pnh.resolveName("yaml_files") +
                                  "' is invalid: accepted a list of YAML file paths");
  }
  for (const std::string& f : files) aurora_common::loadYamlFile("file", f);
}

}  // namespace aurora_control
