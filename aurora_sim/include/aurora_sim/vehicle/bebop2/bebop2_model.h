// The Parrot Bebop 2's identified velocity model (docs/bebop2.md, "The
// model", eq. B1): normalised command in, acceleration out, no attitude.
// One step of Ts, semi-implicit Euler. Templated on the scalar (double,
// float, SIMD batches, CUDA), host and device, branch-free in the state.
#pragma once

#include "aurora_common/host_device.h"
#include "aurora_common/scalar_math.h"
#include "aurora_sim/state_index.h"

namespace aurora_sim {

// The model's channels, in the order of Ku, Kv and the command:
// x, y (world, horizontal), z (up), yaw.
enum Bebop2Axis : int { kBebopX = 0, kBebopY, kBebopZ, kBebopYaw, kBebopAxes };

// A struct of T only (the SIMD engine sets it lane by lane).
template <typename T>
struct Bebop2Params {
  T Ts;               // model step [s]
  T Ku[kBebopAxes];   // input gains: m/s^2 per unit command (x, y, z), rad/s^2 per unit (yaw)
  T Kv[kBebopAxes];   // damping [1/s]
  T rotated_drag;     // 1: the published model's drag turned by the yaw (eq. B1'); 0: the corrected model

  template <typename U>
  AURORA_HD Bebop2Params<U> cast() const {
    Bebop2Params<U> p;
    p.Ts = U(Ts);
    for (int i = 0; i < kBebopAxes; ++i) p.Ku[i] = U(Ku[i]), p.Kv[i] = U(Kv[i]);
    p.rotated_drag = U(rotated_drag);
    return p;
  }
};

// The identified values of docs/bebop2.md, "Parameters" (AuRoRA's
// iParameters, Model = 'Bebop2'). The tools read config/vehicles/bebop2.yaml;
// a test checks that both agree.
inline Bebop2Params<double> referenceBebop2Params() {
  return Bebop2Params<double>{1.0 / 30.0, {0.8417, 0.8354, 3.966, 9.8524}, {0.18227, 0.17095, 4.001, 4.7295}, 0.0};
}

// The 12-state of docs/bebop2.md (the AR.Drone's layout; roll and pitch and
// their rates stay 0).
template <typename T>
struct Bebop2State {
  T X[kStateSize];

  // The study's start: all 0 except z = z0 [m] (airborne, as AuRoRA's class).
  AURORA_HD void reset(const T& z0 = T(0.75)) {
    for (int i = 0; i < kStateSize; ++i) X[i] = T(0);
    X[kZ] = z0;
  }
};

// a = F(psi) Ku U - Kv v (eq. B1), or - F(psi) Kv v with rotated_drag
// (eq. B1'); F(psi) turns x and y by the yaw. In MATLAB's order: (F Ku) U.
template <typename T>
AURORA_HD inline void bebop2Acceleration(const Bebop2Params<T>& p, const T X[kStateSize], const T U[kBebopAxes],
                                         T a[kBebopAxes]) {
  T s, c;
  aurora_common::sinCos(X[kYaw], s, c);
  const T v[kBebopAxes] = {X[kVx], X[kVy], X[kVz], X[kYawRate]};
  using aurora_common::select;  // a SIMD batch's own select by argument-dependent lookup
  const auto rotated = p.rotated_drag != T(0);
  const T drag_x = select(rotated, c * p.Kv[kBebopX] * v[0] - s * p.Kv[kBebopY] * v[1], p.Kv[kBebopX] * v[0]);
  const T drag_y = select(rotated, s * p.Kv[kBebopX] * v[0] + c * p.Kv[kBebopY] * v[1], p.Kv[kBebopY] * v[1]);
  a[kBebopX] = c * p.Ku[kBebopX] * U[kBebopX] - s * p.Ku[kBebopY] * U[kBebopY] - drag_x;
  a[kBebopY] = s * p.Ku[kBebopX] * U[kBebopX] + c * p.Ku[kBebopY] * U[kBebopY] - drag_y;
  a[kBebopZ] = p.Ku[kBebopZ] * U[kBebopZ] - p.Kv[kBebopZ] * v[2];
  a[kBebopYaw] = p.Ku[kBebopYaw] * U[kBebopYaw] - p.Kv[kBebopYaw] * v[3];
}

// One step of Ts with command U = [u_x u_y u_z u_yaw] (bebop_autonomy's
// cmd_vel fractions, no sign change): velocities first, then positions
// and angles with the new velocities, each angle wrapped once into
// [-pi, pi] (docs/bebop2.md, "One step").
template <typename T>
AURORA_HD inline void bebop2Step(const Bebop2Params<T>& p, Bebop2State<T>& s, const T U[kBebopAxes]) {
  T a[kBebopAxes];
  bebop2Acceleration(p, s.X, U, a);
  s.X[kVx] = s.X[kVx] + a[kBebopX] * p.Ts;
  s.X[kVy] = s.X[kVy] + a[kBebopY] * p.Ts;
  s.X[kVz] = s.X[kVz] + a[kBebopZ] * p.Ts;
  s.X[kYawRate] = s.X[kYawRate] + a[kBebopYaw] * p.Ts;
  for (int i = 0; i < 6; ++i) s.X[i] = s.X[i + 6] * p.Ts + s.X[i];
  for (int i = kRoll; i <= kYaw; ++i) s.X[i] = aurora_common::wrapAngleOnce(s.X[i]);
}

}  // namespace aurora_sim
