// The vehicles this build knows, by the name a vehicle file's `type:` gives
// (docs/architecture.md, "Vehicles"), and the rule that a loop flies only
// its own vehicle: a file of another type is refused naming both. Host only.
#pragma once

#include <string>

#include "aurora_sim/vehicle/ardrone2.h"

namespace aurora_sim {

// The names a vehicle file's `type:` accepts, comma separated.
inline std::string knownVehicleTypes() { return Ardrone2::name(); }

inline bool isKnownVehicleType(const std::string& type) { return type == Ardrone2::name(); }

// Empty when a vehicle file of type `type` is one `flown_by` (which flies a
// `Vehicle`) can fly; else why not: a missing or unknown type, or another
// vehicle than the one it flies.
template <class Vehicle>
std::string vehicleTypeRefusal(const std::string& type, const std::string& flown_by) {
  const std::string accepted = "accepted: " + knownVehicleTypes();
  if (type.empty()) {
    return "lacks the key 'type' (the vehicle it describes; " + accepted + "): add 'type: " +
           std::string(Vehicle::name()) + "' to a file of " + Vehicle::name() + " parameters";
  }
  if (!isKnownVehicleType(type)) return "type '" + type + "' is not a vehicle this build knows (" + accepted + ")";
  if (type != Vehicle::name()) {
    return "is of type '" + type + "', but " + flown_by + " flies type '" + Vehicle::name() +
           "': give a vehicle file of type '" + Vehicle::name() + "' (config/vehicles/" + Vehicle::name() +
           ".yaml), or a controller for '" + type + "'";
  }
  return "";
}

}  // namespace aurora_sim
