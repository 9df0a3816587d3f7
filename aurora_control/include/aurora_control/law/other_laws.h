// The laws this build knows, the one list of them (docs/architecture.md,
// "Vehicles"): a flight (flight_setup.h's withFlight), the controller node
// and replay, a controller file's vehicle and a sweep (the sweep file's
// controller names, its parameter table, withSweepLaw) read it. Host only.
#pragma once

#include <string>
#include <type_traits>

#include "aurora_common/named_list.h"
#include "aurora_common/refusal_text.h"

// Each vehicle's laws (and, at the end of this file, the controller-file
// readers of those whose file is not their gain rows).
#include "aurora_control/law/bebop2/bebop2_compensator.h"
#include "aurora_control/law/ardrone2/control_law.h"
#include "aurora_control/law/pioneer3dx/pioneer_laws.h"

// A build may add laws of its own after the shipped ones without editing
// this file: AURORA_EXTRA_LAWS names a header that defines
// aurora_control::ExtraLaws, a TypeList (the registry test's build of the
// nodes, test/registry/extra_laws.h). Every file of such a build is
// compiled with it (one list per program).
#ifdef AURORA_EXTRA_LAWS
#include AURORA_EXTRA_LAWS
#else
namespace aurora_control {
using ExtraLaws = aurora_common::TypeList<>;
}
#endif

namespace aurora_control {

// Every law, the AR.Drone's two first: the one list.
using KnownLaws = aurora_common::Joined<
    aurora_common::TypeList<ArdroneLaw<LawType::kPdSaturated>, ArdroneLaw<LawType::kUnderactuated>, Bebop2Compensator,
                            PioneerDynamic, PioneerKinematic>,
    ExtraLaws>::type;

// The laws of the formations' crews (formation/): a shape names these two
// roles, never a vehicle. Its drones fly FormationDroneLaw (a shape that
// takes its drones' law from its file, the line, any law of that law's
// family), its ground robots FormationGroundLaw: AuRoRA's formations' AR.Drones
// on the underactuated law and Pioneer on its dynamic law.
using FormationDroneLaw = ArdroneLaw<LawType::kUnderactuated>;
using FormationGroundLaw = PioneerDynamic;

template <class F>
void forEachLaw(F&& f) {
  aurora_common::forEachType(KnownLaws(), f);
}

// Calls f(Law()) for the law of the list named `name`; false when none is:
// the one choice of a law by name, for a flight, the controller node and
// replay.
template <class F>
bool withLawNamed(const std::string& name, F&& f) {
  return aurora_common::withEntryNamed(KnownLaws(), name, f);
}

// A law's family: the laws of the list that share its Data (the AR.Drone's
// two, whose loop state and gains are one type; any other law alone). One
// loop of a Data (a node, a replay, a formation's robot) flies any law of
// its family, chosen at run time by its index among them (LawSettings.law).
namespace law_list_detail {
template <class F, class Law>
void callIf(std::true_type, F& f, Law law) { f(law); }
template <class F, class Law>
void callIf(std::false_type, F&, Law) {}

template <class Data, class... L>
constexpr int countOf(aurora_common::TypeList<L...>) {
  int n = 0;
  const bool is[] = {false, std::is_same<typename L::Data, Data>::value...};
  for (bool b : is) n += b;
  return n;
}
template <class Data, class Law, class... L>
constexpr int indexOf(aurora_common::TypeList<L...>) {
  int n = 0, found = -1;
  const bool data[] = {false, std::is_same<typename L::Data, Data>::value...};
  const bool is[] = {false, std::is_same<L, Law>::value...};
  for (int i = 1; i <= int(sizeof...(L)); ++i) found = found < 0 && is[i] ? n : found, n += data[i];
  return found;
}
}  // namespace law_list_detail

// How many laws of the list fly on Data (0: a Data no listed law has, such
// as a mixed crew's EitherLaw, which is its own one law).
template <class Data>
constexpr int lawCountOf() {
  return law_list_detail::countOf<Data>(KnownLaws());
}

// Law's index in its family (-1: not listed).
template <class Law>
constexpr int familyIndex() {
  return law_list_detail::indexOf<typename Law::Data, Law>(KnownLaws());
}

// Calls f(Law()) for each law of the list whose Data is Data, in the list's
// order (f is not instantiated for the others).
template <class Data, class F>
void forEachLawOf(F&& f) {
  forEachLaw([&](auto law) { law_list_detail::callIf(std::is_same<typename decltype(law)::Data, Data>(), f, law); });
}

namespace law_list_detail {
template <class Data, class F>
void withIndex(std::true_type /*listed*/, int index, F& f) {
  int i = 0;
  forEachLawOf<Data>([&](auto law) {
    if (i++ == index) f(law);
  });
}
template <class Data, class F>
void withIndex(std::false_type, int, F& f) {
  f(Data());
}
}  // namespace law_list_detail

// Calls f(Law()) for law `index` of Data's family (a Data no listed law has:
// itself).
template <class Data, class F>
void withLawOf(int index, F&& f) {
  law_list_detail::withIndex<Data>(std::integral_constant<bool, (lawCountOf<Data>() > 0)>(), index, f);
}

// The index of law `name` in Data's family; -1 when it has none of that
// name (or is no listed law's).
template <class Data>
int lawIndexOf(const std::string& name) {
  int i = 0, found = -1;
  forEachLawOf<Data>([&](auto law) {
    if (found < 0 && name == law.name()) found = i;
    ++i;
  });
  return found;
}

// Calls f(Law()) for the law of Data's family named `name`; refused
// (naming the family's laws) when it has none of that name.
template <class Data, class F>
void withLawOfNamed(const std::string& name, F&& f) {
  const auto family = [](auto&& each) { forEachLawOf<Data>(each); };
  if (!aurora_common::withEntryNamed(family, name, f)) {
    throw aurora_common::ConfigError("'" + name + "' is no law of these robots: accepted " +
                                     aurora_common::entryNames(family));
  }
}

// The AR.Drone's two laws are its family in LawType's order (the line
// formation's and the sweep's code that picks one by LawType).
static_assert(familyIndex<ArdroneLaw<LawType::kPdSaturated>>() == int(LawType::kPdSaturated) &&
                  familyIndex<ArdroneLaw<LawType::kUnderactuated>>() == int(LawType::kUnderactuated),
              "the AR.Drone's laws listed in LawType's order");

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

// The vehicle law `name` flies, by name (the list's first law's for a name
// not in the list, which the law's reader then refuses).
inline std::string vehicleOfLaw(const std::string& name) {
  std::string vehicle = aurora_common::FirstType<KnownLaws>::type::Vehicle::name();
  withLawNamed(name, [&](auto law) { vehicle = decltype(law)::Vehicle::name(); });
  return vehicle;
}

}  // namespace aurora_control

// The controller-file readers of the laws whose file is not their gain rows
// (law_yaml.h finds each by its gains' type), one include each. Here, after
// the list, not among the laws above: with them first GCC inlines the SIMD
// engine's lane step differently and the thesis grid's double sweep runs
// about 5 % slower (bench/compare_builds.sh, 21 rounds each way).
#include "aurora_control/law/bebop2/compensator_yaml.h"
#include "aurora_control/law/pioneer3dx/pioneer_yaml.h"
