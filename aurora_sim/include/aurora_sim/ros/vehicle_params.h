// A vehicle's parameters from the parameter server (a vehicle file loaded
// under a namespace), strictly: its `type` must be the vehicle's, every key
// of its file is required and range-checked (vehicle_type.h), no made-up
// defaults for vehicle constants.
#pragma once

#include <ros/ros.h>

#include <functional>
#include <string>

#include "aurora_common/ros/params.h"
#include "aurora_sim/vehicle/vehicle_type.h"

namespace aurora_sim {

// Reads a vehicle's parameters under `ns` (e.g. "vehicle", a vehicle file
// loaded there): its `type` must be `Vehicle`'s, every key of its file is
// required and checked against its range.
template <class Vehicle>
typename Vehicle::template Params<double> loadVehicleParams(const ros::NodeHandle& nh, const std::string& ns,
                                                            const std::string& flown_by = "this node") {
  const std::string prefix = aurora_common::fullKey(nh, ns) + "/";
  const std::string load = ": load a vehicle file such as config/vehicles/" + std::string(Vehicle::name()) +
                           ".yaml (launch arg 'vehicle')";
  std::string type;
  if (nh.hasParam(ns + "/type") && !nh.getParam(ns + "/type", type)) {
    throw aurora_common::ConfigError("vehicle parameter '" + prefix + "type' is not a name" + load);
  }
  return vehicleFromKeys<Vehicle>("vehicle parameters '" + prefix + "': ", type, flown_by, prefix, [&](const auto& key) {
    double value = 0.0;
    bool flag = false;
    if (key.flag ? !nh.getParam(ns + "/" + key.name, flag) : !nh.getParam(ns + "/" + key.name, value)) {
      throw aurora_common::ConfigError("missing vehicle parameter '" + prefix + key.name + "'" +
                                       (key.flag ? " (true or false)" : "") + load);
    }
    return key.flag ? (flag ? 1.0 : 0.0) : value;
  });
}

// What a node that estimates a robot's state needs of the vehicle file
// under `ns`, of whichever vehicle its `type` names (the whole file checked
// as that vehicle's): its sample time, its state size, and its state from
// an estimate of its body's 12-state (sim_profile.h's stateFromBody: a
// Pioneer's control point, u and omega).
struct VehicleOfFile {
  double Ts = 0.0;
  int states = kStateSize;
  std::function<void(const double* body, double* X)> state;
};

inline VehicleOfFile loadVehicleOfFile(const ros::NodeHandle& nh, const std::string& ns,
                                       const std::string& flown_by = "this node") {
  std::string type;
  nh.getParam(ns + "/type", type);
  VehicleOfFile v;
  withVehicleOfType(type, [&](auto vehicle) {
    using Vehicle = decltype(vehicle);
    const typename Vehicle::template Params<double> p = loadVehicleParams<Vehicle>(nh, ns, flown_by);
    v.Ts = p.Ts, v.states = Vehicle::kStates;
    v.state = [p](const double* body, double* X) { SimProfile<Vehicle>::stateFromBody(p, body, X); };
  });
  return v;
}

}  // namespace aurora_sim
