// The project's lists of named entries (docs/architecture.md, "Vehicles",
// "Shapes"): the vehicles (forEachVehicle), the laws (forEachLaw) and the
// formation shapes (forEachShape) are each one function calling f(Entry())
// for every entry, each Entry giving a static name(). What every list is
// asked by name is written once here, for any of them: `each` is the list
// as a callable, e.g. [](auto&& f) { forEachShape(f); }. Host only.
#pragma once

#include <string>

namespace aurora_common {

// The entries' names, comma separated, each between `quote`s when given.
template <class Each>
std::string entryNames(Each&& each, const std::string& quote = "") {
  std::string names;
  each([&](auto e) { names += (names.empty() ? "" : ", ") + quote + e.name() + quote; });
  return names;
}

// Calls f(Entry()) for the first entry named `name`; false when none is.
template <class Each, class F>
bool withEntryNamed(Each&& each, const std::string& name, F&& f) {
  bool found = false;
  each([&](auto e) {
    if (!found && name == e.name()) found = true, f(e);
  });
  return found;
}

template <class Each>
bool isEntryName(Each&& each, const std::string& name) {
  return withEntryNamed(each, name, [](auto) {});
}

}  // namespace aurora_common
