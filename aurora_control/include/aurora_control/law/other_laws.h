// The laws of the vehicles other than the AR.Drone (the AR.Drone's two are
// control_law.h's, chosen with withLaw), the one list of them: a flight
// (flight_setup.h's withFlight), a controller file's vehicle and a sweep
// (the sweep file's controller names, its parameter table, withSweepLaw)
// read it. Host only.
#pragma once

#include <string>

#include "aurora_common/named_list.h"

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

// Calls f(Law()) for the law of the list named `name`; false when none is
// (an AR.Drone law's name, or one its reader refuses): the one choice of a
// law by name, for a flight, the controller node and replay.
template <class F>
bool withOtherLaw(const std::string& name, F&& f) {
  return aurora_common::withEntryNamed([](auto&& g) { forEachOtherLaw(g); }, name, f);
}

// Calls f(Law()) for every law, the AR.Drone's two first: the one list the
// help texts and refusals that name the laws read (knownLawNames,
// lawVehicleNames).
template <class F>
void forEachLaw(F&& f) {
  f(ArdroneLaw<LawType::kPdSaturated>());
  f(ArdroneLaw<LawType::kUnderactuated>());
  forEachOtherLaw(f);
}

// Every law's name, comma separated ("pd_saturated, underactuated, ..."),
// each between `quote`s when given ("'pd_saturated', ...").
inline std::string knownLawNames(const std::string& quote = "") {
  return aurora_common::entryNames([](auto&& f) { forEachLaw(f); }, quote);
}

inline bool isKnownLawName(const std::string& name) {
  return aurora_common::isEntryName([](auto&& f) { forEachLaw(f); }, name);
}

// Each vehicle with the laws that fly it ("ardrone2 for pd_saturated,
// underactuated; bebop2 for bebop2_compensator; ...").
inline std::string lawVehicleNames() {
  std::string text, vehicle;
  forEachLaw([&](auto law) {
    const std::string v = decltype(law)::Vehicle::name();
    text += v == vehicle ? ", " : (text.empty() ? "" : "; ") + v + " for ";
    text += law.name();
    vehicle = v;
  });
  return text;
}

// The vehicle law `name` flies, by name (the AR.Drone's for a name not in
// the list: its two laws, or a name the law's reader refuses).
inline std::string vehicleOfLaw(const std::string& name) {
  std::string vehicle = LawVehicle::name();
  withOtherLaw(name, [&](auto law) { vehicle = decltype(law)::Vehicle::name(); });
  return vehicle;
}

}  // namespace aurora_control
