// The Pioneer P3-DX's profile in the simulator node (sim_profile.h).
#pragma once

#include <algorithm>
#include <cmath>

#include "aurora_sim/vehicle/sim_profile.h"
#include "aurora_sim/vehicle/pioneer3dx/pioneer3dx.h"

namespace aurora_sim {

// The Pioneer P3-DX: on the floor, driving from the first state; RosAria's
// `pose` topic; its body (the centre between the wheels) a behind the
// control point the state and the laws use.
template <>
struct SimProfile<Pioneer3dx> {
  static constexpr int kClimbInput = -1;
  static constexpr bool kFlies = false;
  static const char* odomTopic() { return "pose"; }

  // The safety layer's limits on what is sent (0: none): |u_ref| <= max_speed
  // [m/s], |omega_ref| <= max_turn_rate [rad/s].
  static void limitSpeed(double U[Pioneer3dx::kInputs], double max_speed, double max_turn_rate) {
    if (max_speed > 0.0) U[kPioneerURef] = std::max(-max_speed, std::min(max_speed, U[kPioneerURef]));
    if (max_turn_rate > 0.0) U[kPioneerOmegaRef] = std::max(-max_turn_rate, std::min(max_turn_rate, U[kPioneerOmegaRef]));
  }

  // The state the laws read from a motion-capture estimate of the body
  // (`body`: its 12-state, the centre's position and velocity, attitude and
  // Euler rates): the control point a ahead (eq. P3's velocity), on the
  // floor, then u and omega (the forward speed of the centre, the yaw rate).
  static void stateFromBody(const Pioneer3dx::Params<double>& p, const double body[kStateSize],
                            double X[Pioneer3dx::kStates]) {
    for (int i = 0; i < Pioneer3dx::kStates; ++i) X[i] = 0.0;
    const double psi = body[kYaw], c = std::cos(psi), s = std::sin(psi), w = body[kYawRate];
    X[kX] = body[kX] + p.a * c, X[kY] = body[kY] + p.a * s, X[kYaw] = psi;
    X[kVx] = body[kVx] - p.a * s * w, X[kVy] = body[kVy] + p.a * c * w, X[kYawRate] = w;
    X[kPioneerU] = body[kVx] * c + body[kVy] * s;
    X[kPioneerOmega] = w;
  }

  // At rest with its centre at (x, y) (at[2] must be 0), heading 0.
  static void place(const Pioneer3dx::Params<double>& p, Pioneer3dx::State<double>& s, const double at[3]) {
    s.reset();
    pioneerSetPose(p, s, at[0], at[1], at[2], 0.0);
  }
  static void bodyPosition(const Pioneer3dx::Params<double>& p, const double* X, double out[3]) {
    out[0] = X[kX] - p.a * std::cos(X[kYaw]);
    out[1] = X[kY] - p.a * std::sin(X[kYaw]);
    out[2] = X[kZ];
  }
  // RosAria's twist: forward speed and yaw rate of the body.
  static void bodyTwist(const Pioneer3dx::Params<double>&, const double* X, double linear[3], double angular[3]) {
    linear[0] = X[kPioneerU], linear[1] = linear[2] = 0.0;
    angular[0] = angular[1] = 0.0, angular[2] = X[kPioneerOmega];
  }
};

}  // namespace aurora_sim
