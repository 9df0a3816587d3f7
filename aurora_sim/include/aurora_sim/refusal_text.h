// The one boolean rule, ROS-free: the node's parameters (ros_params.h) and
// every YAML file (aurora_control/yaml_reader.h) refuse with this text.
#pragma once

#include <string>

namespace aurora_sim {

// The one boolean rule (a YAML file, a ROS parameter, a sweep file): an
// unquoted true or false; anything else, a quoted "false" included (a
// string, whatever it reads as), is refused with this text.
inline std::string booleanRefusal(const std::string& key, const std::string& value) {
  return "'" + key + "' = '" + value + "' is not a boolean: accepted true or false, unquoted "
         "(a quoted \"false\" is a string)";
}

}  // namespace aurora_sim
