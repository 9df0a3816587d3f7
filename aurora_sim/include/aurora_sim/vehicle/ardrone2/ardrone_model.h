// One step of the AR.Drone 2.0 dynamic model, exactly as docs/model.md
// ("One model step") writes it. ROS-free, allocation-free, no virtual calls;
// templated on the scalar T (double, float, or a SIMD batch) and callable on
// a CUDA device. Time is passed in through the parameters (Ts); nothing here
// reads a clock.
#pragma once

#include <cmath>

#include "aurora_sim/vehicle/ardrone2/ardrone_params.h"
#include "aurora_common/host_device.h"
#include "aurora_common/rotation.h"
#include "aurora_common/scalar_math.h"
#include "aurora_sim/state_index.h"

namespace aurora_sim {

// The four channels the on-board PD controls, as state indices, in command
// order: roll angle, pitch angle, climb rate, yaw rate. Only these entries of
// the reference Xr, its previous value Xra and the previous state Xa are ever
// read, so the model keeps just these four (saves registers on the GPU).
AURORA_HD constexpr int onboardChannel(int c) {
  return c == 0 ? kRoll : (c == 1 ? kPitch : (c == 2 ? kVz : kYawRate));
}

template <typename T>
struct ArdroneState {
  T X[kStateSize];   // [x y z phi theta psi xdot ydot zdot phidot thetadot psidot], world frame
  T Xa[4];           // previous state on the on-board channels
  T Xr[4];           // on-board reference on the on-board channels
  T Xra[4];          // previous on-board reference
  T W[4];            // rotor speeds

  // Initial state of the study: all zero except z = 0.75 m, rotors stopped.
  AURORA_HD void reset(const T& z0 = T(0.75)) {
    for (int i = 0; i < kStateSize; ++i) X[i] = T(0);
    X[kZ] = z0;
    for (int i = 0; i < 4; ++i) { Xa[i] = T(0); Xr[i] = T(0); Xra[i] = T(0); W[i] = T(0); }
  }
};

// External disturbances: force D(1:3) [N] and torque Q [N m] (zero unless a
// scenario sets them). D(4:6) of the reference is not used by the step.
template <typename T>
struct Disturbance {
  T force[3];
  T torque[3];
  AURORA_HD static Disturbance zero() {
    Disturbance d;
    for (int i = 0; i < 3; ++i) { d.force[i] = T(0); d.torque[i] = T(0); }
    return d;
  }
};

// Rotational inertia matrix Mr(eta) (docs/model.md, "Inertia and Coriolis matrices").
template <typename T>
AURORA_HD inline void inertiaMatrix(const ArdroneParams<T>& p, const T& sphi, const T& cphi,
                                    const T& sth, const T& cth, T Mr[3][3]) {
  // Squares as separate factors (x^2 in the reference is x*x, then scaled).
  const T sphi2 = sphi * sphi, cphi2 = cphi * cphi, sth2 = sth * sth, cth2 = cth * cth;
  Mr[0][0] = p.Ixx;
  Mr[0][1] = T(0);
  Mr[0][2] = -p.Ixx * sth;
  Mr[1][0] = T(0);
  Mr[1][1] = p.Iyy * cphi2 + p.Izz * sphi2;
  Mr[1][2] = (p.Iyy - p.Izz) * sphi * cphi * cth;
  Mr[2][0] = -p.Ixx * sth;
  Mr[2][1] = (p.Iyy - p.Izz) * sphi * cphi * cth;
  Mr[2][2] = p.Ixx * sth2 + p.Iyy * sphi2 * cth2 + p.Izz * cphi2 * cth2;
}

// Coriolis matrix Cr(eta, eta_dot) (docs/model.md, "Inertia and Coriolis matrices"),
// including the reference's Cr12 quirk (s_phi c_theta, not s_phi c_phi).
template <typename T>
AURORA_HD inline void coriolisMatrix(const ArdroneParams<T>& p, const T& sphi, const T& cphi,
                                     const T& sth, const T& cth, const T& rate_p,
                                     const T& rate_t, const T& rate_y, T Cr[3][3]) {
  const T Ixx = p.Ixx, Iyy = p.Iyy, Izz = p.Izz;
  const T sphi2 = sphi * sphi, cphi2 = cphi * cphi, cth2 = cth * cth;
  const T h = (-Ixx - Iyy * cphi2 + Iyy * sphi2 + Izz * cphi2 - Izz * sphi2) * cth / T(2);
  const T h2 = (-Ixx + Iyy * cphi2 - Iyy * sphi2 - Izz * cphi2 + Izz * sphi2) * cth / T(2);
  const T s = sphi * cphi;
  const T q = sth * cth;
  Cr[0][0] = T(0);
  Cr[0][1] = rate_t * (Iyy * sphi * cth - Izz * s) + rate_y * h;
  Cr[0][2] = rate_t * h + rate_y * (-Iyy + Izz) * s * cth2;
  Cr[1][0] = rate_t * (-Iyy + Izz) * s - rate_y * h;
  Cr[1][1] = rate_p * (-Iyy + Izz) * s;
  Cr[1][2] = -rate_p * h + rate_y * (-Ixx + Iyy * sphi2 + Izz * cphi2) * q;
  Cr[2][0] = rate_t * h2 + rate_y * (Iyy - Izz) * s * cth2;
  Cr[2][1] = rate_p * h2 + rate_t * (-Iyy + Izz) * s * sth +
             rate_y * (Ixx - Iyy * sphi2 - Izz * cphi2) * q;
  Cr[2][2] = rate_p * (Iyy - Izz) * s * cth2 + rate_t * (Ixx - Iyy * sphi2 - Izz * cphi2) * q;
}

// Solves M x = b for a 3x3 M by the adjugate (branch-free, so it vectorises
// and runs on the GPU without divergence). Mr is symmetric positive definite
// for every attitude with |theta| < pi/2.
template <typename T>
AURORA_HD inline void solve3(const T M[3][3], const T b[3], T x[3]) {
  const T c00 = M[1][1] * M[2][2] - M[1][2] * M[2][1];
  const T c01 = M[1][2] * M[2][0] - M[1][0] * M[2][2];
  const T c02 = M[1][0] * M[2][1] - M[1][1] * M[2][0];
  const T c10 = M[0][2] * M[2][1] - M[0][1] * M[2][2];
  const T c11 = M[0][0] * M[2][2] - M[0][2] * M[2][0];
  const T c12 = M[0][1] * M[2][0] - M[0][0] * M[2][1];
  const T c20 = M[0][1] * M[1][2] - M[0][2] * M[1][1];
  const T c21 = M[0][2] * M[1][0] - M[0][0] * M[1][2];
  const T c22 = M[0][0] * M[1][1] - M[0][1] * M[1][0];
  const T det = M[0][0] * c00 + M[0][1] * c01 + M[0][2] * c02;
  x[0] = (c00 * b[0] + c10 * b[1] + c20 * b[2]) / det;
  x[1] = (c01 * b[0] + c11 * b[1] + c21 * b[2]) / det;
  x[2] = (c02 * b[0] + c12 * b[1] + c22 * b[2]) / det;
}

// Steps 1-5 of docs/model.md, "One model step": the on-board controller's
// reference and PD from command U, the motor voltages, the motor dynamics and
// the rotor thrusts F.
template <typename T>
AURORA_HD inline void rotorThrusts(const ArdroneParams<T>& p, ArdroneState<T>& s, const T U[4], T F[4]) {
  using std::tanh;
  const T* X = s.X;

  // 1. On-board reference from the command (signs as in the model).
  for (int c = 0; c < 4; ++c) s.Xra[c] = s.Xr[c];
  s.Xr[0] = U[0] * p.uSat[0];
  s.Xr[1] = -U[1] * p.uSat[1];
  s.Xr[2] = U[2] * p.uSat[2];
  s.Xr[3] = -U[3] * p.uSat[3];

  // 2. On-board PD on roll, pitch, climb rate, yaw rate.
  const T kd[4] = {p.kdp, p.kdt, p.kdz, p.kds};
  const T kp[4] = {p.kpp, p.kpt, p.kpz, p.kps};
  T u[4];
  for (int c = 0; c < 4; ++c) {
    const T e = s.Xr[c] - X[onboardChannel(c)];
    u[c] = kd[c] * (e - (s.Xra[c] - s.Xa[c])) / p.Ts + kp[c] * e;
  }

  // 3. Motor voltages (no clamping).
  const T a = T(0.15) * tanh(u[0]);
  const T b = T(0.15) * tanh(u[1]);
  const T c = T(0.4) * tanh(u[2]);
  const T d = T(0.3) * tanh(u[3]);
  const T dv = p.Vbat - p.Vo;
  const T V[4] = {p.Vo + dv * (a - b + c + d), p.Vo + dv * (a + b + c - d),
                  p.Vo + dv * (-a + b + c + d), p.Vo + dv * (-a - b + c - d)};

  // 4. Motor dynamics, 4 implicit sub-steps of Tsm.
  const T km_rm = p.Km / p.Rm;
  const T ct_r = p.Ct / p.r;
  const T denom = p.Jm + p.Tsm * (p.Bm + p.Km * p.Kb / p.Rm);
  for (int sub = 0; sub < 4; ++sub) {
    for (int j = 0; j < 4; ++j) {
      s.W[j] = (p.Jm * s.W[j] + p.Tsm * (km_rm * V[j] - ct_r * (s.W[j] * s.W[j]))) / denom;
    }
  }

  // 5. Thrusts.
  for (int j = 0; j < 4; ++j) F[j] = p.Cf * (s.W[j] * s.W[j]);
}

// Advances the model by one robot sample Ts with command U (model order
// [u_phi u_theta u_zdot u_psidot]; not clamped here: the delay study does not
// clamp, the ROS sim clamps before calling). Steps 1-9 of docs/model.md.
template <typename T>
AURORA_HD inline void ardroneStep(const ArdroneParams<T>& p, ArdroneState<T>& s, const T U[4],
                                  const Disturbance<T>& dist) {
  T* X = s.X;
  T F[4];
  rotorThrusts(p, s, U, F);

  // 6. Previous state (on-board channels only; see onboardChannel).
  for (int c = 0; c < 4; ++c) s.Xa[c] = X[onboardChannel(c)];

  T sphi, cphi, sth, cth, spsi, cpsi;
  using aurora_common::sinCos;  // a SIMD batch brings its own (argument-dependent lookup)
  sinCos(X[kRoll], sphi, cphi);
  sinCos(X[kPitch], sth, cth);
  sinCos(X[kYaw], spsi, cpsi);

  // 7. Translation: v += ((R [0 0 sum F]' - D) - [0 0 m g]') / m * Ts.
  // The thrust acts along the body z axis, R's third column.
  const T thrust = F[0] + F[1] + F[2] + F[3];
  T R[3][3];
  aurora_common::rotationMatrix(sphi, cphi, sth, cth, spsi, cpsi, R);
  const T weight[3] = {T(0), T(0), p.m * p.g};
  for (int i = 0; i < 3; ++i) {
    X[kVx + i] = X[kVx + i] + ((R[i][2] * thrust - dist.force[i]) - weight[i]) / p.m * p.Ts;
  }

  // 8. Rotation: eta_dot += Mr^-1 (tau - Q - Cr eta_dot) Ts.
  const T tau[3] = {p.k1 * (F[0] + F[1] - F[2] - F[3]), p.k1 * (-F[0] + F[1] + F[2] - F[3]),
                    p.k2 * (F[0] - F[1] + F[2] - F[3])};
  T Mr[3][3], Cr[3][3];
  inertiaMatrix(p, sphi, cphi, sth, cth, Mr);
  coriolisMatrix(p, sphi, cphi, sth, cth, X[kRollRate], X[kPitchRate], X[kYawRate], Cr);
  T rhs[3];
  for (int i = 0; i < 3; ++i) {
    rhs[i] = (tau[i] - dist.torque[i]) -
             (Cr[i][0] * X[kRollRate] + Cr[i][1] * X[kPitchRate] + Cr[i][2] * X[kYawRate]);
  }
  T accel[3];
  solve3(Mr, rhs, accel);
  for (int i = 0; i < 3; ++i) X[kRollRate + i] = X[kRollRate + i] + accel[i] * p.Ts;

  // 9. Integration with the updated velocities, then angle wrapping.
  for (int i = 0; i < 6; ++i) X[i] = X[i] + X[i + 6] * p.Ts;
  for (int i = kRoll; i <= kYaw; ++i) X[i] = aurora_common::wrapAngleOnce(X[i]);
}

}  // namespace aurora_sim
