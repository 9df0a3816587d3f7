// The project's lists of named entries (docs/architecture.md, "Vehicles",
// "Shapes"): the vehicles (KnownVehicles), the laws (KnownLaws) and the
// formation shapes (KnownShapes) are each a TypeList of entries, each
// Entry giving a static name(), walked by forEachType (forEachVehicle,
// forEachLaw, forEachShape). What every list is asked by name is written
// once here, for any of them: `each` is the list, a TypeList (KnownShapes())
// or any callable that calls its argument with each entry. Host only.
#pragma once

#include <initializer_list>
#include <string>
#include <type_traits>

namespace aurora_common {

// A list's entries, as types; called with f, it calls f(Entry()) for each
// entry, in its order.
template <class... T>
struct TypeList {
  static constexpr int kCount = sizeof...(T);
  template <class F>
  void operator()(F&& f) const {
    const int each[] = {0, (f(T()), 0)...};
    (void)each;
  }
};

template <class... T, class F>
void forEachType(TypeList<T...> list, F&& f) {
  list(f);
}

// X's place in the list (0, 1, ...; -1 when it is none of its entries).
template <class X, class... T>
constexpr int typeIndexIn(TypeList<T...>) {
  int index = 0, found = -1;
  const bool is[] = {false, std::is_same<X, T>::value...};
  for (bool b : is) found = found < 0 && b ? index - 1 : found, ++index;
  return found;
}

// The largest of `values` (0 for none): what the largest entry of a list
// has, as largestOf({E::kRobots...}) over its entries E.
constexpr int largestOf(std::initializer_list<int> values) {
  int most = 0;
  for (int v : values) most = v > most ? v : most;
  return most;
}

// List A's entries, then B's (a shipped list and a build's own entries).
template <class A, class B>
struct Joined;
template <class... A, class... B>
struct Joined<TypeList<A...>, TypeList<B...>> {
  using type = TypeList<A..., B...>;
};

// A list's first entry.
template <class List>
struct FirstType;
template <class T0, class... T>
struct FirstType<TypeList<T0, T...>> {
  using type = T0;
};

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
