// The Pioneer P3-DX differential-drive robot (docs/pioneer3dx.md): the
// velocity-based dynamic model of Martins et al. (eq. P1) and the
// kinematic model (eq. P2) of its control point, a distance a ahead of the
// wheel axle. One step of Ts. Templated on the scalar (double, float, SIMD
// batches, CUDA), host and device, branch-free in the state.
#pragma once

#include "aurora_common/host_device.h"
#include "aurora_common/scalar_math.h"
#include "aurora_sim/state_index.h"

namespace aurora_sim {

// The robot's state: the control point's 12-state (x, y, yaw and their
// rates; the rest 0), then its forward speed u [m/s] and yaw rate omega
// [rad/s] (the dynamic model's states; the kinematic model's commands).
enum PioneerIndex : int { kPioneerU = kStateSize, kPioneerOmega, kPioneerStateSize };
// Its commands: u_ref [m/s], omega_ref [rad/s] (RosAria's cmd_vel).
enum PioneerInput : int { kPioneerURef = 0, kPioneerOmegaRef, kPioneerInputs };

// A struct of T only (the SIMD engine sets it lane by lane).
template <typename T>
struct PioneerParams {
  T Ts;                   // model step [s]
  T a;                    // control point ahead of the axle [m]
  T theta[6];             // identified dynamic parameters (s, s, s m/rad^2, 1, s/m, 1)
  T kinematic;            // 1: the kinematic model (eq. P2); 0: the dynamic model (eq. P1)
  T omega_gain_bug;       // 1: the published model's input gain theta2 on omega_ref (eq. P1'); 0: 1/theta2

  template <typename U>
  AURORA_HD PioneerParams<U> cast() const {
    PioneerParams<U> p;
    p.Ts = U(Ts), p.a = U(a), p.kinematic = U(kinematic), p.omega_gain_bug = U(omega_gain_bug);
    for (int i = 0; i < 6; ++i) p.theta[i] = U(theta[i]);
    return p;
  }
};

// The identified values (Martins & Brandao 2018, AuRoRA's iParameters);
// the tools read config/vehicles/pioneer3dx.yaml, a test checks both agree.
inline PioneerParams<double> referencePioneerParams() {
  return PioneerParams<double>{0.1, 0.15, {0.5338, 0.2168, -0.0134, 0.9560, -0.0843, 1.0590}, 0.0, 0.0};
}

template <typename T>
struct PioneerState {
  T X[kPioneerStateSize];

  // At rest with its centre at the origin, heading 0: the control point at
  // (a, 0) once setPose places it (the study's reset: all 0).
  AURORA_HD void reset() {
    for (int i = 0; i < kPioneerStateSize; ++i) X[i] = T(0);
  }
};

// Puts the robot's centre at (x, y, z) with heading psi: the control point
// a ahead along the heading (docs/pioneer3dx.md, "State, command, frames": AuRoRA
// turns by the old heading; the same for a new robot at heading 0).
template <typename T>
AURORA_HD inline void pioneerSetPose(const PioneerParams<T>& p, PioneerState<T>& s, const T& x, const T& y,
                                     const T& z, const T& psi) {
  T sp, cp;
  aurora_common::sinCos(psi, sp, cp);
  s.X[kX] = x + p.a * cp, s.X[kY] = y + p.a * sp, s.X[kZ] = z, s.X[kYaw] = psi;
}

// The control point's world velocity of (u, omega) at heading psi:
// K(psi) [u; omega] (eq. P3).
template <typename T>
AURORA_HD inline void pioneerPointVelocity(const T& a, const T& psi, const T& u, const T& omega, T v[3]) {
  T s, c;
  aurora_common::sinCos(psi, s, c);
  v[0] = c * u + -a * s * omega;
  v[1] = s * u + a * c * omega;
  v[2] = omega;
}

// The dynamic model's (u, omega) rates (eq. P1), in the original's order of
// operations; g52 the omega_ref gain (1/theta2, or theta2: eq. P1').
template <typename T>
AURORA_HD inline void pioneerAcceleration(const PioneerParams<T>& p, const T& u, const T& w,
                                          const T U[kPioneerInputs], T& du, T& dw) {
  using aurora_common::select;
  const T* th = p.theta;
  const T g52 = select(p.omega_gain_bug != T(0), th[1], T(1) / th[1]);
  du = th[2] / th[0] * (w * w) - th[3] / th[0] * u + T(1) / th[0] * U[kPioneerURef];
  dw = -th[4] / th[1] * u * w - th[5] / th[1] * w + g52 * U[kPioneerOmegaRef];
}

// One step of Ts with U = [u_ref, omega_ref] (docs/pioneer3dx.md, "One
// step"): the new (u, omega) (the dynamic model's Euler step, or the
// command itself in the kinematic model), the control point's velocity
// K(psi) [u; omega] at the heading before the step stored, the pose
// advanced by it, the angles wrapped once.
template <typename T>
AURORA_HD inline void pioneerStep(const PioneerParams<T>& p, PioneerState<T>& s, const T U[kPioneerInputs]) {
  using aurora_common::select;
  T* X = s.X;
  T du, dw;
  pioneerAcceleration(p, X[kPioneerU], X[kPioneerOmega], U, du, dw);
  const auto kinematic = p.kinematic != T(0);
  X[kPioneerU] = select(kinematic, U[kPioneerURef], X[kPioneerU] + du * p.Ts);
  X[kPioneerOmega] = select(kinematic, U[kPioneerOmegaRef], X[kPioneerOmega] + dw * p.Ts);
  T v[3];
  pioneerPointVelocity(p.a, X[kYaw], X[kPioneerU], X[kPioneerOmega], v);
  const int at[3] = {kX, kY, kYaw}, rate[3] = {kVx, kVy, kYawRate};
  for (int i = 0; i < 3; ++i) X[rate[i]] = v[i], X[at[i]] = X[at[i]] + v[i] * p.Ts;
  for (int i = kRoll; i <= kYaw; ++i) X[i] = aurora_common::wrapAngleOnce(X[i]);
}

}  // namespace aurora_sim
