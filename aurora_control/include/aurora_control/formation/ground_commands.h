// A robot's commands as a ground robot's forward speed and turn rate: what
// a real ground robot's safety layer limits (config/safety/real_ground.yaml)
// and the formation's check 5 judges (docs/formation.md, "Formation
// checks"). A vehicle with kOnGround names them (kSpeedInput,
// kTurnRateInput: the Pioneer's u_ref and omega_ref, RosAria's cmd_vel); a
// drone has none; a robot of a mixed crew (EitherVehicle) has its chosen
// vehicle's. Host and device, scalars and SIMD batches.
#pragma once

#include <type_traits>

#include "aurora_common/host_device.h"
#include "aurora_sim/vehicle/either_vehicle.h"

namespace aurora_control {

// A drone: no ground commands.
template <class Vehicle, class = void>
struct GroundCommands {
  template <typename P, typename T>
  AURORA_HD static bool of(const P&, const T*, T&, T&) {
    return false;
  }
};

// A ground robot: true, with its speed and turn rate commands of U.
template <class Vehicle>
struct GroundCommands<Vehicle, typename std::enable_if<Vehicle::kOnGround>::type> {
  template <typename P, typename T>
  AURORA_HD static bool of(const P&, const T* U, T& speed, T& turn_rate) {
    speed = U[Vehicle::kSpeedInput];
    turn_rate = U[Vehicle::kTurnRateInput];
    return true;
  }
};

// A robot of a mixed crew: its chosen vehicle's (U's first entries).
template <class First, class Second>
struct GroundCommands<aurora_sim::EitherVehicle<First, Second>> {
  template <typename P, typename T>
  AURORA_HD static bool of(const P& p, const T* U, T& speed, T& turn_rate) {
    if (p.is_second) return GroundCommands<Second>::of(p.second, U, speed, turn_rate);
    return GroundCommands<First>::of(p.first, U, speed, turn_rate);
  }
};

}  // namespace aurora_control
