// The formation shapes this build knows (docs/architecture.md, "Shapes"):
// the one list every entry point that takes a formation file chooses from
// (flight, the formation node, the sweep, aurora._core). Each entry (its
// reader's header) gives its name, its robots, its file's reader, the keys
// its refusals name, and declares what the entry points that fly it define
// in their own files (fly, crew, flyTable). A file is loaded once
// (formation_document.h) and handed to its shape's reader. Host only.
#pragma once

#include <string>
#include <tuple>
#include <type_traits>

#include "aurora_common/named_list.h"
#include "aurora_common/refusal_text.h"
#include "aurora_control/formation/formation_document.h"
#include "aurora_control/formation/line/line_yaml.h"
#include "aurora_control/formation/triangle/triangle_yaml.h"
#include "aurora_control/formation/uav_ugv/uav_ugv_yaml.h"

// A build may add shapes of its own after the shipped ones without editing
// this file: AURORA_EXTRA_SHAPES names a header that defines
// aurora_control::ExtraShapes, a TypeList (the registry test's build of the
// formation node, test/registry/extra_shapes.h; docs/architecture.md,
// "Shapes"). Every file of such a build is compiled with it (one list per
// program).
#ifdef AURORA_EXTRA_SHAPES
#include AURORA_EXTRA_SHAPES
#else
namespace aurora_control {
using ExtraShapes = aurora_common::TypeList<>;
}
#endif

namespace aurora_control {

// The shapes this build knows: the one list (forEachShape, the sweep's
// SweepShape and its runs read it).
using KnownShapes =
    aurora_common::Joined<aurora_common::TypeList<LineShapeEntry, UavUgvShapeEntry, TriangleShapeEntry>, ExtraShapes>::type;

namespace shapes_detail {
template <class... E>
constexpr int mostRobots(aurora_common::TypeList<E...>) {
  return aurora_common::largestOf({E::kRobots...});
}
}  // namespace shapes_detail

// The most robots of any shape of the list: what the formation node's
// per-robot arrays hold (a crew of any shape fits).
constexpr int kMaxCrew = shapes_detail::mostRobots(KnownShapes());

template <class F>
void forEachShape(F&& f) {
  aurora_common::forEachType(KnownShapes(), f);
}

// Entry's place in the list (0, 1, ...).
template <class Entry>
constexpr int shapeIndex() {
  return aurora_common::typeIndexIn<Entry>(KnownShapes());
}

// One value of Part<Entry> for each shape of a list (a sweep's runs).
template <template <class> class Part, class List>
struct PerShape;
template <template <class> class Part, class... E>
struct PerShape<Part, aurora_common::TypeList<E...>> {
  using type = std::tuple<Part<E>...>;
};

// The shapes' names, comma separated (what a `shape:` accepts).
inline std::string knownShapeNames() { return aurora_common::entryNames(KnownShapes()); }

// A shape's own laws, comma separated ("" for a shape whose law is its
// file's: its lawRefusal() says why --law is refused).
template <class Entry>
std::string ownLawNames(Entry) {
  return Entry::lawRefusal().empty() ? Entry::sweepLawNames() : std::string();
}

// The laws of the shapes that have their own (flight's --law): "triangle:
// N, PD, ...", one shape after another ("; ").
inline std::string shapeLawNames() {
  std::string names;
  forEachShape([&](auto e) {
    const std::string laws = ownLawNames(e);
    if (!laws.empty()) names += (names.empty() ? "" : "; ") + std::string(e.name()) + ": " + laws;
  });
  return names;
}

// Calls f(Vehicle()) with the vehicle of an entry whose file names its
// robots none (kNamesItsVehicles false: its UnnamedVehicle, which the
// flight's, the node's or formation_robot's vehicle file gives); nothing for
// an entry whose file names them.
template <class Entry, class F>
typename std::enable_if<!Entry::kNamesItsVehicles>::type withUnnamedVehicle(Entry, F&& f) {
  f(typename Entry::UnnamedVehicle());
}
template <class Entry, class F>
typename std::enable_if<Entry::kNamesItsVehicles>::type withUnnamedVehicle(Entry, F&&) {}

// That vehicle's type name ("" where the file names its robots').
template <class Entry>
std::string unnamedVehicleName(Entry e) {
  std::string name;
  withUnnamedVehicle(e, [&](auto vehicle) { name = decltype(vehicle)::name(); });
  return name;
}

// Calls f(Entry()) for the shape named `shape`; false when none is.
template <class F>
bool withShapeNamed(const std::string& shape, F&& f) {
  return aurora_common::withEntryNamed(KnownShapes(), shape, f);
}

// withUnnamedVehicle of the shape named `shape` (nothing for an unknown
// shape: its file's reader refuses it): the node's ~vehicle and
// formation_robot's --vehicle are read as that type.
template <class F>
void withUnnamedVehicleOf(const std::string& shape, F&& f) {
  withShapeNamed(shape, [&](auto e) { withUnnamedVehicle(e, f); });
}

// Why `shape` is no shape this build knows ("" when it is one), after
// its key's name: "is missing: accepted ...", "= 'x' is unknown: ...".
inline std::string unknownShapeRefusal(const std::string& shape) {
  if (aurora_common::isEntryName(KnownShapes(), shape)) return "";
  if (shape.empty()) return "is missing: accepted " + knownShapeNames();
  return "= '" + shape + "' is unknown: accepted " + knownShapeNames();
}

// The shape's entry and its file, read once from `d`: f(Entry(), file).
// `law` (flight's --law; "" the file's) goes to the
// reader of a shape with laws of its own (its entry's lawRefusal() is
// empty); another shape refuses it. An unknown or missing shape is refused
// naming the file and the shapes there are.
template <class F>
void withFormationDocument(const FormationDocument& d, const std::string& law, F&& f) {
  const std::string refusal = unknownShapeRefusal(d.shape);
  if (!refusal.empty()) formationReader(d).fail("formation.shape", refusal);
  withShapeNamed(d.shape, [&](auto e) {
    if (!law.empty() && !e.lawRefusal().empty()) {
      throw ConfigError("--law is refused for a formation of shape '" + d.shape + "': " + e.lawRefusal());
    }
    f(e, decltype(e)::read(d, law));
  });
}

template <class F>
void withFormationFile(const std::string& path, const std::string& config_dir, const std::string& law, F&& f) {
  withFormationDocument(loadFormationDocument(path, config_dir), law, f);
}

}  // namespace aurora_control
