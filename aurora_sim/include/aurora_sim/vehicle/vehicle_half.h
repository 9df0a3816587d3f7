// The vehicle's half of a step (docs/architecture.md, "One iteration",
// step 5, without the loop's checks and clock): the command it received,
// clamped by the vehicle's own rule where it clamps (clamp_at_drone: an
// AR.Drone's driver; the simulator node's flying vehicle), then one model
// step. Written once for every loop (aurora_control's droneHalf: the
// offline runner, the SIMD lanes, each CUDA thread) and the simulator node.
#pragma once

#include "aurora_common/host_device.h"

namespace aurora_sim {

// `applied` gets the command the model stepped with.
template <class Vehicle, class Params, class State, typename T>
AURORA_HD inline void vehicleHalf(const Params& p, bool clamp, const T* received, State& s, T* applied) {
  for (int i = 0; i < Vehicle::kInputs; ++i) applied[i] = clamp ? Vehicle::limitInput(p, i, received[i]) : received[i];
  Vehicle::step(p, s, applied);
}

}  // namespace aurora_sim
