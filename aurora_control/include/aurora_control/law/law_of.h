// What a law type declares (docs/architecture.md, "Laws"), written once: the
// vehicle it flies, its own type as its Data (laws that share their data,
// as the AR.Drone's two, declare it themselves), its gains and its memory.
// A law derives from LawOf and adds its Input, name() and command().
#pragma once

namespace aurora_control {

template <class Law, class FliesVehicle, template <typename> class GainsOf, template <typename> class MemoryOf>
struct LawOf {
  using Vehicle = FliesVehicle;
  using Data = Law;
  template <typename T>
  using Gains = GainsOf<T>;
  template <typename T>
  using Memory = MemoryOf<T>;
};

}  // namespace aurora_control
