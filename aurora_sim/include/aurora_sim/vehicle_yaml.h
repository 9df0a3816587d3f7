// Reads a vehicle file (config/vehicles/*.yaml) with yaml-cpp, strictly:
// every key of vehicle_keys.h must be present and in range. For ROS-free
// callers (the sweep, tests); the nodes read the same keys from the
// parameter server (ros/params.h).
#pragma once

#include <yaml-cpp/yaml.h>

#include <sstream>
#include <stdexcept>
#include <string>

#include "aurora_sim/ardrone_params.h"
#include "aurora_sim/refusal_text.h"
#include "aurora_sim/vehicle_keys.h"
#include "aurora_sim/yaml_file.h"

namespace aurora_sim {

inline ArdroneParams<double> loadVehicleYaml(const std::string& path) {
  const YAML::Node root = loadYamlFile("vehicle file", path);
  ArdroneParams<double> p{};
  for (const VehicleKey& key : vehicleKeys()) {
    std::stringstream parts(key.name);
    std::string part;
    YAML::Node node = YAML::Clone(root);
    while (std::getline(parts, part, '/')) {
      if (!node.IsMap() || !node[part]) {
        throw ConfigError("vehicle file '" + path + "' lacks the key '" + key.name +
                                 "' (" + key.unit + ")");
      }
      node = node[part];
    }
    double value = 0.0;
    try {
      value = node.as<double>();
    } catch (const YAML::Exception&) {
      throw ConfigError("vehicle file '" + path + "': '" + key.name + "' is not a number");
    }
    const std::string problem = checkVehicleValue(path + ": ", key, value);
    if (!problem.empty()) throw ConfigError(problem);
    setVehicleValue(p, key, value);
  }
  p.updateDerived();
  return p;
}

}  // namespace aurora_sim
