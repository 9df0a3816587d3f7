// What a vehicle gives unless it says otherwise (the members every vehicle
// gives: ardrone2.h's comment), written once: a vehicle derives from
// VehicleDefaults and writes only what differs (the Pioneer its start, its
// state's names and its unclamped commands).
#pragma once

#include "aurora_common/host_device.h"
#include "aurora_common/scalar_math.h"
#include "aurora_sim/state_index.h"

namespace aurora_sim {

struct VehicleDefaults {
  // The 12-state's names (state_index.h order).
  static const char* stateName(int i) { return stateName12(i); }

  // A new vehicle at rest: its State's own reset().
  template <class Params, class State>
  AURORA_HD static void start(const Params&, State& s) {
    s.reset();
  }

  // Each command component clamped to [-1, 1], as the drones' drivers
  // (ardrone_autonomy, bebop_autonomy) clamp cmd_vel.
  template <class Params, typename T>
  AURORA_HD static T limitInput(const Params&, int, const T& u) {
    return aurora_common::clampUnit(u);
  }

  // Whether the simulated vehicle clamps what it receives even in a flight
  // asked to clamp nowhere (flight --no-clamp): no; such a flight clamps
  // neither the law's commands nor the vehicle's (AuRoRA's simulation).
  static constexpr bool kAlwaysClamps = false;
};

}  // namespace aurora_sim
