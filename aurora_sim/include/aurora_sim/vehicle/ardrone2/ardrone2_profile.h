// The AR.Drone 2.0's profile in the simulator node (sim_profile.h): a drone
// that climbs with its vertical input (u_zdot).
#pragma once

#include "aurora_sim/vehicle/sim_profile.h"
#include "aurora_sim/vehicle/ardrone2/ardrone2.h"

namespace aurora_sim {

template <>
struct SimProfile<Ardrone2> : DroneSimProfile<Ardrone2, kUClimb> {};

}  // namespace aurora_sim
