// A formation robot's ROS namespace where its file names none: its
// vehicle's namespace stem and its number in the formation, from 1 (a
// triangle of AR.Drones: ardrone1, ardrone2, ardrone3; the UAV-UGV line:
// pioneer1, ardrone2). Host only.
#pragma once

#include <string>

namespace aurora_control {

// Robot `index` (0-based) of vehicle Vehicle (its namespaceStem()).
template <class Vehicle>
std::string robotNamespace(int index) {
  return std::string(Vehicle::namespaceStem()) + std::to_string(index + 1);
}

}  // namespace aurora_control
