// The laws of the vehicles other than the AR.Drone (the AR.Drone's two are
// control_law.h's, chosen with withLaw), the one list of them: a flight
// (flight_setup.h's withFlight), a controller file's vehicle and a sweep
// (the sweep file's controller names, its parameter table, withSweepLaw)
// read it. Host only.
#pragma once

#include <string>

#include "aurora_control/law/bebop2_compensator.h"
#include "aurora_control/law/control_law.h"
#include "aurora_control/law/pioneer_laws.h"

namespace aurora_control {

// Calls f(Law()) for each of them.
template <class F>
void forEachOtherLaw(F&& f) {
  f(Bebop2Compensator());
  f(PioneerDynamic());
  f(PioneerKinematic());
}

// The vehicle law `name` flies, by name (the AR.Drone's for a name not in
// the list: its two laws, or a name the law's reader refuses).
inline std::string vehicleOfLaw(const std::string& name) {
  std::string vehicle = LawVehicle::name();
  forEachOtherLaw([&](auto law) {
    if (name == law.name()) vehicle = decltype(law)::Vehicle::name();
  });
  return vehicle;
}

}  // namespace aurora_control
