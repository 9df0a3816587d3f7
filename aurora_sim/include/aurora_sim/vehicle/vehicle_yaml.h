// Reads a vehicle file (config/vehicles/*.yaml) with yaml-cpp, strictly:
// its `type:` names the vehicle it describes, and every key of that
// vehicle's file (Vehicle::fileKeys) must be present and in range. For
// ROS-free callers (the flight tool, the sweep, Python, tests); the nodes
// read the same keys from the parameter server (ros/params.h).
#pragma once

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <sstream>
#include <string>
#include <vector>

#include "aurora_common/refusal_text.h"
#include "aurora_sim/vehicle/vehicle_type.h"
#include "aurora_common/yaml_file.h"

namespace aurora_sim {

// The value under a '/'-separated key of a vehicle file (a flag: true 1,
// false 0).
inline double vehicleFileNumber(const YAML::Node& root, const std::string& path, const std::string& name,
                                const std::string& unit, bool flag = false) {
  std::stringstream parts(name);
  std::string part;
  YAML::Node node = YAML::Clone(root);
  while (std::getline(parts, part, '/')) {
    if (!node.IsMap() || !node[part]) {
      throw aurora_common::ConfigError("vehicle file '" + path + "' lacks the key '" + name + "' (" + unit + ")");
    }
    node = node[part];
  }
  try {
    return flag ? (node.as<bool>() ? 1.0 : 0.0) : node.as<double>();
  } catch (const YAML::Exception&) {
    throw aurora_common::ConfigError("vehicle file '" + path + "': '" + name + "' is not " +
                                     (flag ? "true or false" : "a number"));
  }
}

// The '/'-separated paths of the leaves under `node` (a mapping's), e.g.
// "dynamics/theta1".
inline void vehicleFileLeaves(const YAML::Node& node, const std::string& at, std::vector<std::string>& leaves) {
  for (const auto& kv : node) {
    const std::string key = at + kv.first.as<std::string>();
    if (kv.second.IsMap()) vehicleFileLeaves(kv.second, key + "/", leaves);
    else leaves.push_back(key);
  }
}

// A key a `Vehicle` file does not have (a typo, another vehicle's key) is
// refused naming it and the accepted ones: it would be silently ignored.
// Every file may say how rviz draws the vehicle (rviz_body: the
// simulator's drone_marker reads it; no model does).
template <class Vehicle>
void refuseUnknownVehicleKeys(const YAML::Node& root, const std::string& path) {
  std::vector<std::string> leaves, accepted{"type"};
  vehicleFileLeaves(root, "", leaves);
  for (const auto& key : Vehicle::fileKeys()) accepted.push_back(key.name);
  accepted.insert(accepted.end(), {"rviz_body/form", "rviz_body/size"});  // drone_marker's, not the model's
  for (const std::string& leaf : leaves) {
    if (std::find(accepted.begin(), accepted.end(), leaf) != accepted.end()) continue;
    std::string names;
    for (const std::string& a : accepted) names += (names.empty() ? "" : ", ") + a;
    throw aurora_common::ConfigError("vehicle file '" + path + "': '" + leaf + "' is not a key of a " +
                                     Vehicle::name() + " file: accepted " + names);
  }
}

// The parameters of a vehicle of type `Vehicle` from the file at `path`,
// which `flown_by` (e.g. "the controller 'pd_saturated'") flies.
template <class Vehicle>
typename Vehicle::template Params<double> loadVehicleFile(const std::string& path,
                                                          const std::string& flown_by = "this loop") {
  const YAML::Node root = aurora_common::loadYamlFile("vehicle file", path);
  std::string type;
  try {
    type = root.IsMap() && root["type"] ? root["type"].as<std::string>() : "";
  } catch (const YAML::Exception&) {
  }
  const auto params = vehicleFromKeys<Vehicle>("vehicle file '" + path + "': ", type, flown_by, path + ": ",
                                               [&](const auto& key) {
                                                 return vehicleFileNumber(root, path, key.name, key.unit, key.flag);
                                               });
  refuseUnknownVehicleKeys<Vehicle>(root, path);
  return params;
}

}  // namespace aurora_sim
