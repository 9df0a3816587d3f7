// The laws this build knows, the one list of them (docs/architecture.md,
// "Vehicles"): a flight (flight_setup.h's withFlight), the controller node
// and replay, a controller file's vehicle and a sweep (the sweep file's
// controller names, its parameter table, withSweepLaw) read it. Host only.
#pragma once

#include <string>
#include <type_traits>

#include "aurora_common/named_list.h"

#include "aurora_control/law/bebop2_compensator.h"
#include "aurora_control/law/control_law.h"
#include "aurora_control/law/pioneer_laws.h"

namespace aurora_control {

// Every law, the AR.Drone's two first: the one list.
using KnownLaws = aurora_common::TypeList<ArdroneLaw<LawType::kPdSaturated>, ArdroneLaw<LawType::kUnderactuated>,
                                          Bebop2Compensator, PioneerDynamic, PioneerKinematic>;

template <class F>
void forEachLaw(F&& f) {
  aurora_common::forEachType(KnownLaws(), f);
}

// The AR.Drone's laws are chosen among themselves at run time: one
// controller node, flight and sweep loop of ControllerSettings and withLaw
// switch between them (a live change of controller/name). Every other law
// has a node, a flight and a sweep loop of its own type.
template <class Law>
struct ChosenAtRunTime : std::is_base_of<ArdroneLawData, Law> {};

namespace law_list_detail {
template <class F, class Law>
void callFor(std::false_type /*chosen at run time*/, F& f, Law law) { f(law); }
template <class F, class Law>
void callFor(std::true_type, F&, Law) {}
}  // namespace law_list_detail

// Calls f(Law()) for each law of the list not ChosenAtRunTime (f is not
// instantiated for those).
template <class F>
void forEachOtherLaw(F&& f) {
  forEachLaw([&](auto law) { law_list_detail::callFor(ChosenAtRunTime<decltype(law)>(), f, law); });
}

// Calls f(Law()) for the law of forEachOtherLaw named `name`; false when
// none is (an AR.Drone law's name, or one its reader refuses): the one
// choice of a law by name, for a flight, the controller node and replay.
template <class F>
bool withOtherLaw(const std::string& name, F&& f) {
  return aurora_common::withEntryNamed([](auto&& g) { forEachOtherLaw(g); }, name, f);
}

namespace law_list_detail {
template <class Law>
constexpr bool hasRate(decltype(Law::kHasRate)*) {
  return Law::kHasRate;
}
template <class Law>
constexpr bool hasRate(...) {
  return false;
}
}  // namespace law_list_detail

// Whether law `Law` runs at a rate of its own (its declaration's kHasRate;
// without one, every model step).
template <class Law>
constexpr bool lawHasRate() {
  return law_list_detail::hasRate<Law>(nullptr);
}

namespace law_list_detail {
template <class Law>
const char* saturation(decltype(&Law::saturatesItself)) {
  return Law::saturatesItself();
}
template <class Law>
const char* saturation(...) {
  return nullptr;
}
}  // namespace law_list_detail

// Why law `Law` has no clamp to leave out, where it saturates its own
// commands and its driver clamps nothing (its declaration's
// saturatesItself(), e.g. "for the Pioneer P3-DX: ..."); else null.
template <class Law>
const char* lawSaturation() {
  return law_list_detail::saturation<Law>(nullptr);
}

// Calls f(Law()) for each law of the list that saturates its own commands.
template <class F>
void forEachLawThatSaturates(F&& f) {
  forEachLaw([&](auto law) {
    if (lawSaturation<decltype(law)>()) f(law);
  });
}

// Calls f(Law()) for each law of the list that runs at a rate of its own.
template <class F>
void forEachLawWithARate(F&& f) {
  forEachLaw([&](auto law) {
    if (lawHasRate<decltype(law)>()) f(law);
  });
}

// Every law's name, comma separated ("pd_saturated, underactuated, ..."),
// each between `quote`s when given ("'pd_saturated', ...").
inline std::string knownLawNames(const std::string& quote = "") {
  return aurora_common::entryNames(KnownLaws(), quote);
}

inline bool isKnownLawName(const std::string& name) {
  return aurora_common::isEntryName(KnownLaws(), name);
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
