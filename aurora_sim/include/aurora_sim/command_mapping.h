// Mapping between the driver convention of cmd_vel (ardrone_autonomy /
// bebop_autonomy: linear.x forward tilt, linear.y left tilt, linear.z climb
// rate, angular.z counter-clockwise yaw rate, fractions in [-1, 1]) and the
// model command U = [u_phi u_theta u_zdot u_psidot] (docs/model.md, "State, command, frames").
// Negation is exact, so the mapping never changes a value's bits.
#pragma once

#include <cmath>

#include "aurora_common/scalar_math.h"
#include "aurora_sim/state_index.h"

namespace aurora_sim {

struct TwistCommand {
  double linear_x, linear_y, linear_z, angular_z;  // driver fractions
};

inline void modelCommandFromTwist(const TwistCommand& t, double U[4]) {
  U[kURoll] = -t.linear_y;
  U[kUPitch] = -t.linear_x;
  U[kUClimb] = t.linear_z;
  U[kUYawRate] = -t.angular_z;
}

inline TwistCommand twistFromModelCommand(const double U[4]) {
  return TwistCommand{-U[kUPitch], -U[kURoll], U[kUClimb], -U[kUYawRate]};
}

inline bool allFinite(const double* v, int n) {
  for (int i = 0; i < n; ++i) {
    if (!std::isfinite(v[i])) return false;
  }
  return true;
}

}  // namespace aurora_sim
