// The Bebop 2's profile in the simulator node (sim_profile.h): a drone that
// climbs with its vertical input (linear.z).
#pragma once

#include "aurora_sim/vehicle/sim_profile.h"
#include "aurora_sim/vehicle/bebop2/bebop2.h"

namespace aurora_sim {

template <>
struct SimProfile<Bebop2> : DroneSimProfile<Bebop2, kBebopZ> {};

}  // namespace aurora_sim
