// The vehicles this build knows, by the name a vehicle file's `type:` gives
// (docs/architecture.md, "Vehicles"), and the rule that a loop flies only
// its own vehicle: a file of another type is refused naming both. Host only.
#pragma once

#include <string>
#include <tuple>

#include "aurora_common/named_list.h"
#include "aurora_common/refusal_text.h"
#include "aurora_sim/vehicle/ardrone2/ardrone2_profile.h"
#include "aurora_sim/vehicle/bebop2/bebop2_profile.h"
#include "aurora_sim/vehicle/pioneer3dx/pioneer3dx_profile.h"

// A build may add vehicles of its own after the shipped ones without
// editing this file: AURORA_EXTRA_VEHICLES names a header that defines
// aurora_sim::ExtraVehicles, a TypeList (the registry test's build of the
// nodes, test/registry/extra_vehicles.h; docs/architecture.md, "Vehicles").
// Every file of such a build is compiled with it (one list per program).
#ifdef AURORA_EXTRA_VEHICLES
#include AURORA_EXTRA_VEHICLES
#else
namespace aurora_sim {
using ExtraVehicles = aurora_common::TypeList<>;
}
#endif

namespace aurora_sim {

// The vehicles this build knows: the one list (forEachVehicle,
// VehicleParamsSet and every choice by a vehicle file's type read it),
// each included above with its simulator profile (its folder's
// <name>_profile.h, which includes its model).
using KnownVehicles =
    aurora_common::Joined<aurora_common::TypeList<Ardrone2, Bebop2, Pioneer3dx>, ExtraVehicles>::type;

namespace vehicle_type_detail {
template <class... V>
constexpr int mostStates(aurora_common::TypeList<V...>) {
  return aurora_common::largestOf({V::kStates...});
}
}  // namespace vehicle_type_detail

// The largest state of the list's vehicles (the Pioneer P3-DX's 12 + u,
// omega): what a state sample, the controller node's history and a state
// message's reader hold for any vehicle of this build.
constexpr int kMaxStates = vehicle_type_detail::mostStates(KnownVehicles());

// The vehicle of a file that names none (a sweep file without `vehicle:`;
// a sweep's definition hash adds its constants, and another vehicle's
// only when it flies one): the thesis's AR.Drone.
using DefaultVehicle = Ardrone2;

template <class F>
void forEachVehicle(F&& f) {
  aurora_common::forEachType(KnownVehicles(), f);
}

// One set of parameters of each vehicle of a list, by its type (a sweep
// keeps its vehicle file's in its type's): of<Vehicle>(), and
// withType(name, f), f(its parameters) for the vehicle of that name.
template <class List>
struct VehicleParamsOf;
template <class... V>
struct VehicleParamsOf<aurora_common::TypeList<V...>> {
  std::tuple<typename V::template Params<double>...> params;

  template <class W>
  const typename W::template Params<double>& of() const {
    return std::get<typename W::template Params<double>>(params);
  }
  template <class W>
  typename W::template Params<double>& of() {
    return std::get<typename W::template Params<double>>(params);
  }
  template <class F>
  bool withType(const std::string& type, F&& f) const {
    return aurora_common::withEntryNamed(aurora_common::TypeList<V...>(), type,
                                         [&](auto vehicle) { f(of<decltype(vehicle)>()); });
  }
};
using VehicleParamsSet = VehicleParamsOf<KnownVehicles>;

// The names a vehicle file's `type:` accepts, comma separated.
inline std::string knownVehicleTypes() {
  return aurora_common::entryNames(KnownVehicles());
}

// Calls f(Vehicle()) for the vehicle of `type` (a vehicle file's), else
// f(the list's first), whose loader then refuses the type naming it: the one
// choice of a vehicle by its file, for the simulator, the mocap estimator
// and the fake driver.
template <class F>
void withVehicleOfType(const std::string& type, F&& f) {
  if (!aurora_common::withEntryNamed(KnownVehicles(), type, f)) f(aurora_common::FirstType<KnownVehicles>::type());
}

inline bool isKnownVehicleType(const std::string& type) {
  return aurora_common::isEntryName(KnownVehicles(), type);
}

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

// A vehicle's parameters as every loader reads them (a YAML file, the
// parameter server): `type` checked first (refused as `where` + why), then
// each of its file's keys from number(key), checked against its range
// (named with `prefix`), then the derived values.
template <class Vehicle, class Number>
typename Vehicle::template Params<double> vehicleFromKeys(const std::string& where, const std::string& type,
                                                          const std::string& flown_by, const std::string& prefix,
                                                          Number&& number) {
  const std::string refusal = vehicleTypeRefusal<Vehicle>(type, flown_by);
  if (!refusal.empty()) throw aurora_common::ConfigError(where + refusal);
  typename Vehicle::template Params<double> p{};
  for (const auto& key : Vehicle::fileKeys()) {
    const double value = number(key);
    const std::string problem = checkVehicleValue(prefix, key, value);
    if (!problem.empty()) throw aurora_common::ConfigError(problem);
    Vehicle::setFileValue(p, key, value);
  }
  Vehicle::finishFile(p);
  return p;
}

}  // namespace aurora_sim
