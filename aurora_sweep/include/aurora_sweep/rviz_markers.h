// `sweep --rviz`: the feasible set as a latched MarkerArray in (Kp, Kd, delay)
// space. The only part of the sweep program that needs ROS.
#pragma once

#include <vector>

#include "aurora_sweep/simulation.h"
#include "aurora_sweep/sweep_spec.h"

namespace aurora_sweep {

// Publishes /sweep/feasible (x = Kp, y = Kd, z = delay in seconds, frame
// "sweep") and spins until Ctrl-C. Returns the process exit code.
// Initialises ROS and checks the master before any work; false (and a
// message) when none answers.
bool rvizMasterReachable(int argc, char** argv);

// After rvizMasterReachable:
int publishFeasibleMarkers(int argc, char** argv, const SweepSpec& spec,
                           const std::vector<SimResult>& results);

}  // namespace aurora_sweep
