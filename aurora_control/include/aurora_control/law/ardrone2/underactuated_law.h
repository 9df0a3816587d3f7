// Underactuated nonlinear controller with 12 gains (Brandão, Sarcinelli-Filho
// & Carelli 2013), steps 1-11 of the underactuated controller in
// docs/controllers.md. Like ardroneStep: templated on the
// scalar (double, float, a SIMD batch), host and CUDA device, no allocation,
// no exceptions, no Eigen; data-dependent branches are selects.
//
// The pseudo-inverse without an SVD. A = [R At; Ar] (6x4). R is orthonormal,
// so A'A = At'At + Ar'Ar does not depend on the attitude. Its eigenvectors
// are the four motor-mixing vectors v0 = [1 1 1 1], v_roll = [1 1 -1 -1],
// v_pitch = [-1 1 1 -1], v_yaw = [1 -1 1 -1] (|v|^2 = 4), with eigenvalues
// 4, 4 k1^2, 4 k1^2, 4 k2^2. Hence, for w = [w_t; w4; w5; w6],
//   pinv(A) w = (A'A)^-1 A' w
//             = ( (n . w_t) v0 + (w4 / k1) v_roll + (w5 / k1) v_pitch + (w6 / k2) v_yaw ) / 4,
// n = R(:, 3) the thrust axis. Exact for every attitude and every k1, k2 (k2 =
// Ct/Cf varies in robustness studies); agrees with an SVD pinv to rounding.
#pragma once

#include <cmath>

#include "aurora_sim/vehicle/ardrone2/ardrone_model.h"
#include "aurora_common/host_device.h"
#include "aurora_common/rotation.h"
#include "aurora_common/scalar_math.h"
#include "aurora_control/law/law_gain_rows.h"
#include "aurora_sim/state_index.h"

namespace aurora_control {

// Gains (k1, k2) per axis, axes in the order x, y, z, phi, theta, psi.
enum UnderactuatedAxis : int { kAxisX = 0, kAxisY, kAxisZ, kAxisPhi, kAxisTheta, kAxisPsi, kAxes };

// Every gain's accepted range (positive: the law divides by none, but a zero
// gain leaves its axis unregulated).
constexpr double kUnderactuatedGainMin = 0.001, kUnderactuatedGainMax = 100.0;

template <typename T>
struct UnderactuatedGains {
  T k1[kAxes];
  T k2[kAxes];
  // The spec's defaults: x .5 2, y .5 2, z 5 2, phi 1 20, theta 1 20, psi 1 2.5.
  AURORA_HD static UnderactuatedGains defaults() {
    UnderactuatedGains g;
    const double k1[kAxes] = {0.5, 0.5, 5.0, 1.0, 1.0, 1.0};
    const double k2[kAxes] = {2.0, 2.0, 2.0, 20.0, 20.0, 2.5};
    for (int i = 0; i < kAxes; ++i) g.k1[i] = T(k1[i]), g.k2[i] = T(k2[i]);
    return g;
  }
};

// The law's own memory: desired rotor speeds, its reference on the four
// on-board channels (roll, pitch, climb rate, yaw rate) and the desired roll
// and pitch of the previous call.
template <typename T>
struct UnderactuatedMemory {
  T Wd[4];
  T Xr[4];
  T roll_d, pitch_d;
  AURORA_HD void reset() {
    for (int i = 0; i < 4; ++i) Wd[i] = T(0), Xr[i] = T(0);
    roll_d = pitch_d = T(0);
  }
};

namespace underactuated_detail {

// Motor-mixing vectors (the eigenvectors of A'A), one row each.
AURORA_HD constexpr double mix(int row, int motor) {
  return row == 0 ? 1.0
       : row == 1 ? (motor < 2 ? 1.0 : -1.0)
       : row == 2 ? ((motor == 1 || motor == 2) ? 1.0 : -1.0)
                  : ((motor % 2 == 0) ? 1.0 : -1.0);
}

// pinv(A) w for w = [w_t (3); w_r (3)] (see the header comment).
template <typename T>
AURORA_HD inline void pinvTimes(const aurora_sim::ArdroneParams<T>& p, const T n[3],
                                const T w_t[3], const T w_r[3], T out[4]) {
  const T f = n[0] * w_t[0] + n[1] * w_t[1] + n[2] * w_t[2];
  const T c[4] = {f, w_r[0] / p.k1, w_r[1] / p.k1, w_r[2] / p.k2};
  for (int j = 0; j < 4; ++j) {
    T sum = T(0);
    for (int r = 0; r < 4; ++r) sum = sum + T(mix(r, j)) * c[r];
    out[j] = sum / T(4);
  }
}

// pinv(A) [0; w_r]: pinvTimes of torques alone.
template <typename T>
AURORA_HD inline void pinvTorque(const aurora_sim::ArdroneParams<T>& p, const T w_r[3], T out[4]) {
  const T c[3] = {w_r[0] / p.k1, w_r[1] / p.k1, w_r[2] / p.k2};
  for (int j = 0; j < 4; ++j) out[j] = (T(mix(1, j)) * c[0] + T(mix(2, j)) * c[1] + T(mix(3, j)) * c[2]) / T(4);
}

// A Fr: the body force along n and the three torques.
template <typename T>
AURORA_HD inline void actuation(const aurora_sim::ArdroneParams<T>& p, const T n[3], const T F[4],
                                T ftau[6]) {
  T total = T(0), roll = T(0), pitch = T(0), yaw = T(0);
  for (int j = 0; j < 4; ++j) {
    total = total + F[j];
    roll = roll + T(mix(1, j)) * F[j];
    pitch = pitch + T(mix(2, j)) * F[j];
    yaw = yaw + T(mix(3, j)) * F[j];
  }
  for (int i = 0; i < 3; ++i) ftau[i] = n[i] * total;
  ftau[3] = p.k1 * roll;
  ftau[4] = p.k1 * pitch;
  ftau[5] = p.k2 * yaw;
}

// Steps 1-2: wrapped errors and eta_i = dXd_i + k1 tanh(k2 e_i) + k3 tanh(k4 e_i').
template <typename T>
AURORA_HD inline void virtualInputs(const UnderactuatedGains<T>& g, const T e[aurora_sim::kStateSize],
                                    const T acc[6], T eta[6]) {
  using std::sqrt;
  using std::tanh;
  for (int i = 0; i < kAxes; ++i) {
    const T k3 = sqrt(T(4) * g.k1[i]);
    const T k4 = sqrt(T(4) * g.k1[i] * g.k2[i]) / k3;
    eta[i] = acc[i] + g.k1[i] * tanh(g.k2[i] * e[i]) + k3 * tanh(k4 * e[i + 6]);
  }
}

// Steps 5-7: the forces Fr (4) that realise eta on the reduced dynamics.
template <typename T>
AURORA_HD inline void reducedForces(const aurora_sim::ArdroneParams<T>& p, const T R[3][3],
                                    const T Mr[3][3], const T Cr_rates[3], const T eta[6], T Fr[4]) {
  const T n[3] = {R[0][2], R[1][2], R[2][2]};
  // Ma = pinv(A) MM, column by column; Ea = pinv(A) (CC X(7:12) + GG).
  // MM's first three columns are m e_j (forces only): pinv(A) gives
  // (n . m e_j) v0 / 4 = m n_j / 4 on every rotor; the last three (torques
  // only) pinvTorque. Both the values pinvTimes gives, without its zero terms.
  T Ma[6][4];
  for (int j = 0; j < 3; ++j) {
    const T force = n[j] * p.m / T(4);
    for (int r = 0; r < 4; ++r) Ma[j][r] = force;
    const T mr_col[3] = {Mr[0][j], Mr[1][j], Mr[2][j]};
    pinvTorque(p, mr_col, Ma[3 + j]);
  }
  const T gravity[3] = {T(0), T(0), p.m * p.g};
  T Ea[4];
  pinvTimes(p, n, gravity, Cr_rates, Ea);
  // MP = R' m: Mpp = MP(1:2, 1:2), Mpa's only nonzero column MP(1:2, 3),
  // Ep = (R' [0 0 m g])(1:2). y = Mpp^-1 Mpa(:, 1), z = Mpp^-1 Ep.
  const T a = p.m * R[0][0], b = p.m * R[1][0], c = p.m * R[0][1], d = p.m * R[1][1];
  const T det = a * d - b * c;
  const T mpa[2] = {p.m * R[2][0], p.m * R[2][1]};
  const T ep[2] = {R[2][0] * (p.m * p.g), R[2][1] * (p.m * p.g)};
  const T y[2] = {(d * mpa[0] - b * mpa[1]) / det, (a * mpa[1] - c * mpa[0]) / det};
  const T z[2] = {(d * ep[0] - b * ep[1]) / det, (a * ep[1] - c * ep[0]) / det};
  // Fr = (Maa - Map y e1') eta_a + Ea - Map z, eta_a = [eta_z eta_phi eta_theta eta_psi].
  for (int r = 0; r < 4; ++r) {
    const T map_y = Ma[0][r] * y[0] + Ma[1][r] * y[1];
    const T map_z = Ma[0][r] * z[0] + Ma[1][r] * z[1];
    T sum = (Ma[2][r] - map_y) * eta[kAxisZ];
    for (int k = 1; k < 4; ++k) sum = sum + Ma[2 + k][r] * eta[kAxisZ + k];
    Fr[r] = sum + (Ea[r] - map_z);
  }
}

// Steps 9-11: rotor speeds, voltages, inverse on-board PD, commands.
template <typename T>
AURORA_HD inline void commandsFromForces(const aurora_sim::ArdroneParams<T>& p, UnderactuatedMemory<T>& mem,
                                         const T X[aurora_sim::kStateSize], const T Fd[4], T U[4]) {
  using std::sqrt;
  using std::tanh;
  // The motor's constants, once per call (the rotors' loop stores to
  // memory the compiler cannot tell from p's).
  const T inertia = p.Jm * p.Rm / p.Km, damping = p.Bm * p.Rm / p.Km + p.Kb, drag = p.Ct * p.Rm / (p.Km * p.r);
  T Vr[4];
  for (int i = 0; i < 4; ++i) {
    const T Wda = mem.Wd[i];
    mem.Wd[i] = sqrt(Fd[i] / p.Cf);
    Vr[i] = -p.Vo + inertia * (mem.Wd[i] - Wda) / p.Ts + damping * mem.Wd[i] + drag * mem.Wd[i] * mem.Wd[i];
  }
  const T sigma = T(0.25) * p.Ts;
  const T kd[4] = {p.kdp, p.kdt, p.kdz, p.kds};
  const T kp[4] = {p.kpp, p.kpt, p.kpz, p.kps};
  for (int c = 0; c < 4; ++c) {
    // The channel's mixing row: roll v_roll, pitch v_pitch, climb v0, yaw v_yaw.
    const int row = c == 0 ? 1 : (c == 1 ? 2 : (c == 2 ? 0 : 3));
    T mixed = T(0);
    for (int j = 0; j < 4; ++j) mixed = mixed + T(mix(row, j)) * Vr[j];
    const T x = X[aurora_sim::onboardChannel(c)];
    mem.Xr[c] = x + (kd[c] * (mem.Xr[c] - x) + sigma * mixed) / (kd[c] + kp[c] * p.Ts);
  }
  U[0] = tanh(mem.Xr[0] / p.uSat[0]);
  U[1] = tanh(-mem.Xr[1] / p.uSat[1]);
  U[2] = tanh(mem.Xr[2] / p.uSat[2]);
  U[3] = tanh(-mem.Xr[3] / p.uSat[3]);
}

}  // namespace underactuated_detail

// One call of the law. Xd: desired 12-state (position, yaw and rates; its
// roll and pitch are ignored: the law's own from the previous call are
// used), acc: desired accelerations (feed-forward, 6; zero for positioning),
// X: the state the law receives (possibly delayed), U: the command
// [u_phi u_theta u_zdot u_psidot] in [-1, 1].
template <typename T>
AURORA_HD inline void underactuatedCommand(const aurora_sim::ArdroneParams<T>& p,
                                           const UnderactuatedGains<T>& g, UnderactuatedMemory<T>& mem,
                                           const T Xd[aurora_sim::kStateSize], const T acc[6],
                                           const T X[aurora_sim::kStateSize], T U[4]) {
  using std::atan2;
  namespace ud = underactuated_detail;
  using namespace aurora_sim;
  // The branch-free helpers; a SIMD batch brings its own select and sinCos (argument-dependent lookup).
  using aurora_common::rotationMatrix;
  using aurora_common::select;
  using aurora_common::sinCos;
  using aurora_common::wrapErrorAsReference;
  // 1. Errors, angle errors wrapped as the reference does.
  T e[kStateSize];
  for (int i = 0; i < kStateSize; ++i) e[i] = Xd[i] - X[i];
  e[kRoll] = mem.roll_d - X[kRoll];
  e[kPitch] = mem.pitch_d - X[kPitch];
  for (int i = kRoll; i <= kYaw; ++i) e[i] = wrapErrorAsReference(e[i]);
  // 2. Virtual inputs.
  T eta[6];
  ud::virtualInputs(g, e, acc, eta);
  T sphi, cphi, sth, cth, spsi, cpsi;
  sinCos(X[kRoll], sphi, cphi);
  sinCos(X[kPitch], sth, cth);
  sinCos(X[kYaw], spsi, cpsi);
  // 3. Desired roll and pitch, used by the next call.
  mem.roll_d = atan2((eta[kAxisX] * spsi - eta[kAxisY] * cpsi) * cth, eta[kAxisZ] + p.g);
  mem.pitch_d = atan2(eta[kAxisX] * cpsi + eta[kAxisY] * spsi, eta[kAxisZ] + p.g);
  // 4-7. Dynamics matrices and the forces.
  T R[3][3], Mr[3][3], Cr[3][3];
  rotationMatrix(sphi, cphi, sth, cth, spsi, cpsi, R);
  inertiaMatrix(p, sphi, cphi, sth, cth, Mr);
  coriolisMatrix(p, sphi, cphi, sth, cth, X[kRollRate], X[kPitchRate], X[kYawRate], Cr);
  T Cr_rates[3];
  for (int i = 0; i < 3; ++i) {
    Cr_rates[i] = Cr[i][0] * X[kRollRate] + Cr[i][1] * X[kPitchRate] + Cr[i][2] * X[kYawRate];
  }
  T Fr[4], ftau[6];
  ud::reducedForces(p, R, Mr, Cr_rates, eta, Fr);
  const T n[3] = {R[0][2], R[1][2], R[2][2]};
  ud::actuation(p, n, Fr, ftau);
  // 8. Never a negative vertical force; never a negative rotor force.
  ftau[2] = select(ftau[2] < T(0), T(0.3) * p.m * p.g, ftau[2]);
  T Fd[4];
  ud::pinvTimes(p, n, ftau, ftau + 3, Fd);
  for (int i = 0; i < 4; ++i) Fd[i] = select(Fd[i] < T(0), T(0), Fd[i]);
  // 9-11.
  ud::commandsFromForces(p, mem, X, Fd, U);
}

}  // namespace aurora_control

namespace aurora_control {

// Configuration names of the 12 gains, in the order k1, k2 per axis
// (x, y, z, phi, theta, psi): name 2i is k1[i], name 2i+1 is k2[i].
inline const char* underactuatedGainName(int i) {
  static const char* const kNames[2 * kAxes] = {"k1_x",     "k2_x",     "k1_y",   "k2_y",
                                                "k1_z",     "k2_z",     "k1_phi", "k2_phi",
                                                "k1_theta", "k2_theta", "k1_psi", "k2_psi"};
  return kNames[i];
}

// What gain i does (the controller node's parameter reference).
inline const char* underactuatedGainMeaning(int i) {
  static const char* const kMeanings[2 * kAxes] = {"k1 of x",     "k2 of x",     "k1 of y",    "k2 of y",
                                                   "k1 of z",     "k2 of z",     "k1 of roll", "k2 of roll",
                                                   "k1 of pitch", "k2 of pitch", "k1 of yaw",  "k2 of yaw"};
  return kMeanings[i];
}

template <typename T>
AURORA_HD T& underactuatedGain(UnderactuatedGains<T>& g, int i) {
  return i % 2 == 0 ? g.k1[i / 2] : g.k2[i / 2];
}

template <typename T>
AURORA_HD const T& underactuatedGain(const UnderactuatedGains<T>& g, int i) {
  return i % 2 == 0 ? g.k1[i / 2] : g.k2[i / 2];
}

// The gains a sweep may vary (law_gain_rows.h): the 12, in
// underactuatedGainName's order, in the controller node's range.
struct UnderactuatedGainRows {
  static constexpr int kGainCount = 2 * kAxes;
  static GainRow gainRow(int i) {
    return {underactuatedGainName(i), underactuatedGain(UnderactuatedGains<double>::defaults(), i),
            kUnderactuatedGainMin, kUnderactuatedGainMax, false,
            "the controller node's underactuated gain range (positive)", underactuatedGainMeaning(i)};
  }
  template <typename T>
  AURORA_HD static void giveGains(UnderactuatedGains<T>& g, const double* v) {
    for (int i = 0; i < kGainCount; ++i) giveGain(underactuatedGain(g, i), v[i]);
  }
  static double& gainAt(UnderactuatedGains<double>& g, int i) { return underactuatedGain(g, i); }
};

}  // namespace aurora_control
