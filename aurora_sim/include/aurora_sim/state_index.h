// Named indices of the 12-state X = [x y z phi theta psi xdot ydot zdot
// phidot thetadot psidot] and of the 4-command U = [u_phi u_theta u_zdot
// u_psidot] (docs/model.md, "State, command, frames"; 0-based here).
#pragma once

namespace aurora_sim {

enum StateIndex : int {
  kX = 0, kY = 1, kZ = 2,
  kRoll = 3, kPitch = 4, kYaw = 5,
  kVx = 6, kVy = 7, kVz = 8,
  kRollRate = 9, kPitchRate = 10, kYawRate = 11,
  kStateSize = 12
};

enum CommandIndex : int {
  kURoll = 0, kUPitch = 1, kUClimb = 2, kUYawRate = 3,
  kCommandSize = 4
};

// The 12-state's names in StateIndex order (a flight's CSV header, Python's
// state_names): the spec's x, y, z, phi, theta, psi and their rates.
inline const char* stateName12(int i) {
  static const char* const names[kStateSize] = {"x",  "y",  "z",  "phi",  "theta",  "psi",
                                                "dx", "dy", "dz", "dphi", "dtheta", "dpsi"};
  return names[i];
}

}  // namespace aurora_sim
