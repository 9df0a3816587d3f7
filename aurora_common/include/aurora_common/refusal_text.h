// Texts shared by every refusal, ROS-free: the node's parameters
// (ros/params.h), every YAML file (aurora_control/params/yaml_reader.h) and the
// task checks word numbers and booleans the same way.
#pragma once

#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>

namespace aurora_common {

// The one error type of a refused value, parameter or file: its message
// names the key, the value and what is accepted. Every reader throws it (ROS
// parameters, YAML files, sweep files, the tools' options, the runner); every
// entry point catches it and exits 2 with the message.
struct ConfigError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// A number as a user wrote it (%g: 0.2, -5, 1e+09; any NaN reads "nan"), for messages.
inline std::string numberText(double v) {
  if (std::isnan(v)) return "nan";
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

// A number with the digits that read back to it (%.17g): what is passed on
// as text (a launch's parameter, a YAML scalar) must not round.
inline std::string roundTripText(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

// The one boolean rule (a YAML file, a ROS parameter, a sweep file): an
// unquoted true or false; anything else, a quoted "false" included (a
// string, whatever it reads as), is refused with this text.
inline std::string booleanRefusal(const std::string& key, const std::string& value) {
  return "'" + key + "' = '" + value + "' is not a boolean: accepted true or false, unquoted "
         "(a quoted \"false\" is a string)";
}

}  // namespace aurora_common
