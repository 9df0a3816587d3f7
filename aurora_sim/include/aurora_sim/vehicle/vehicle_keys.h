// What a vehicle's file keys are (each vehicle's table of them, its
// meaning and accepted ranges, in its own folder: fileKeys()), used by every
// loader (ROS parameter server in the sim node, yaml-cpp in the sweep), and
// the one range check of a value. A loader must find every key: there is
// no silent fall-back to built-in constants.
#pragma once

#include <cmath>
#include <string>

namespace aurora_sim {

// A key of a vehicle file whose values go to `field` (a vehicle's own enum
// of its parameters), entry `index` of it where it is an array.
template <class Field>
struct FileKey {
  const char* name;
  Field field;
  int index;
  double min, max;   // accepted range, inclusive
  const char* unit;
  bool flag;         // true / false in the file
};

// Empty when `value` is acceptable for `key` (any vehicle's key: name,
// min, max, unit); otherwise a message naming the full key (with `prefix`,
// e.g. "/ardrone1/vehicle/"), the value and the range.
template <class Key>
std::string checkVehicleValue(const std::string& prefix, const Key& key, double value) {
  if (std::isfinite(value) && value >= key.min && value <= key.max) return "";
  return "parameter '" + prefix + key.name + "' = " + std::to_string(value) +
         " is invalid: accepted range [" + std::to_string(key.min) + ", " +
         std::to_string(key.max) + "] " + key.unit;
}

}  // namespace aurora_sim
