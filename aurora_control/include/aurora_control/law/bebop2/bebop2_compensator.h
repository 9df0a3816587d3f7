// The Bebop 2's dynamic compensator (docs/bebop2.md, "The compensator",
// eq. B2; AuRoRA's cInverseDynamicController_Compensador_LoadLeo): a
// kinematic law gives the desired world velocity, the inverse of the
// identified model (its nominal Ku, Kv) the command. Runs every
// `period_steps` model steps (30 Hz / period_steps) and holds its command
// in between, as bebop_autonomy holds the last cmd_vel. Templated on the
// scalar, host and device.
#pragma once

#include <cmath>

#include "aurora_common/host_device.h"
#include "aurora_common/scalar_math.h"
#include "aurora_control/law/law_gain_rows.h"
#include "aurora_control/law/law_of.h"
#include "aurora_control/task/task.h"
#include "aurora_sim/vehicle/bebop2/bebop2.h"

namespace aurora_control {

// The largest gain a controller file or a sweep gives the compensator.
constexpr double kCompensatorGainMax = 100.0;

// The 16 gains in the order of x, y, z, yaw within each group (kd is
// AuRoRA's fourth group, which its law never reads), and the law's period.
// Gains and memory are structs of T only (the SIMD engine sets them lane
// by lane).
template <typename T>
struct CompensatorGains {
  T ksp[aurora_sim::kBebopAxes];  // amplitude of the kinematic law [m/s, rad/s]
  T ksd[aurora_sim::kBebopAxes];  // velocity-error gain [1/s]
  T kp[aurora_sim::kBebopAxes];   // slope of the kinematic law [1/m, 1/rad]
  T kd[aurora_sim::kBebopAxes];   // not used (AuRoRA's)
  T period_steps;                 // whole: the law runs every period_steps model steps (1: 30 Hz, 6: 5 Hz)

  // AuRoRA's defaults at 30 Hz.
  AURORA_HD static CompensatorGains defaults() {
    return CompensatorGains{{T(2), T(2), T(3), T(1.5)}, {T(2), T(2), T(1.8), T(5)}, {T(1), T(1), T(1), T(1.5)},
                            {T(1), T(1), T(1), T(1)}, T(1)};
  }
};

template <typename T, typename U>
AURORA_HD void castGains(const CompensatorGains<U>& from, CompensatorGains<T>& to) {
  for (int i = 0; i < aurora_sim::kBebopAxes; ++i) {
    to.ksp[i] = T(from.ksp[i]), to.ksd[i] = T(from.ksd[i]), to.kp[i] = T(from.kp[i]), to.kd[i] = T(from.kd[i]);
  }
  to.period_steps = T(from.period_steps);
}

// What the law keeps between calls: its previous desired velocity Ur, the
// command it holds, and the model steps until it runs again (0: now).
template <typename T>
struct CompensatorMemory {
  T Ur[aurora_sim::kBebopAxes];
  T held[aurora_sim::kBebopAxes];
  T wait;
  AURORA_HD void reset() {
    for (int i = 0; i < aurora_sim::kBebopAxes; ++i) Ur[i] = held[i] = T(0);
    wait = T(0);
  }
};

// One run of eq. B2 with period dt on x y z yaw (X4), their rates (V4),
// the desired ones (Xd4, dXd4): writes the command U and updates Ur.
template <typename T>
AURORA_HD inline void compensatorCommand(const aurora_sim::Bebop2Params<T>& model, const CompensatorGains<T>& g,
                                         const T& dt, const T X4[4], const T V4[4], const T Xd4[4], const T dXd4[4],
                                         T Ur[4], T U[4]) {
  using std::tanh;
  T w[4];
  for (int i = 0; i < 4; ++i) {
    T e = Xd4[i] - X4[i];
    if (i == aurora_sim::kBebopYaw) e = aurora_common::wrapAngleOnce(e);  // one wrap, as the original
    const T Ucw = dXd4[i] + g.ksp[i] * tanh(g.kp[i] * e);
    const T dUcw = (Ucw - Ur[i]) / dt;
    Ur[i] = Ucw;
    w[i] = dUcw + g.ksd[i] * (Ucw - V4[i]) + model.Kv[i] * V4[i];
  }
  T s, c;
  aurora_common::sinCos(X4[aurora_sim::kBebopYaw], s, c);
  U[aurora_sim::kBebopX] = (c * w[0] + s * w[1]) / model.Ku[aurora_sim::kBebopX];
  U[aurora_sim::kBebopY] = (-s * w[0] + c * w[1]) / model.Ku[aurora_sim::kBebopY];
  U[aurora_sim::kBebopZ] = w[2] / model.Ku[aurora_sim::kBebopZ];
  U[aurora_sim::kBebopYaw] = w[3] / model.Ku[aurora_sim::kBebopYaw];
}

// The compensator as a law type (control_law.h's concept).
struct Bebop2Compensator : LawOf<Bebop2Compensator, aurora_sim::Bebop2, CompensatorGains, CompensatorMemory> {
  // x y z yaw and their rates.
  struct Input {
    static constexpr int kWidth = 8;
    AURORA_HD static constexpr int state(int j) {
      return j < 3 ? aurora_sim::kX + j : j == 3 ? aurora_sim::kYaw : j < 7 ? aurora_sim::kVx + j - 4 : aurora_sim::kYawRate;
    }
  };
  static const char* name() { return "bebop2_compensator"; }
  // It runs at a rate of its own (its file's `rate`, flight's --rate): a
  // whole number of model steps (other_laws.h, lawHasRate).
  static constexpr bool kHasRate = true;

  // The gains a sweep varies (law_gain_rows.h): ksp, ksd, kp on xy, z,
  // yaw (x and y as one, as AuRoRA's are equal), then period_steps (1:
  // 30 Hz, 6: 5 Hz). Its unread kd group keeps AuRoRA's values.
  static constexpr int kGainCount = 10;
  static GainRow gainRow(int i) {
    static const char* const names[kGainCount] = {"ksp_xy", "ksp_z", "ksp_yaw", "ksd_xy", "ksd_z",
                                                  "ksd_yaw", "kp_xy", "kp_z", "kp_yaw", "period_steps"};
    const auto d = CompensatorGains<double>::defaults();
    const double* group[3] = {d.ksp, d.ksd, d.kp};
    if (i == 9) return GainRow{names[i], d.period_steps, 1.0, 30.0, true};
    return GainRow{names[i], group[i / 3][i % 3 == 0 ? 0 : i % 3 + 1], 0.0, kCompensatorGainMax, false};
  }
  template <typename T>
  AURORA_HD static void giveGains(Gains<T>& g, const double* v) {
    T* group[3] = {g.ksp, g.ksd, g.kp};
    for (int j = 0; j < 3; ++j) {
      for (int axis = 0; axis < 4; ++axis) giveGain(group[j][axis], v[3 * j + (axis < 2 ? 0 : axis - 1)]);
    }
    giveGain(g.period_steps, v[9]);
  }

  // Every period_steps calls it runs on the state X it received towards
  // ref, with dt = period_steps Ts; in between it gives the held command.
  // Branch-free (lanes): the law is computed every call, kept when due.
  template <typename T>
  AURORA_HD static void command(const aurora_sim::Bebop2Params<T>& model, const Gains<T>& g, Memory<T>& m,
                                const Reference<T>& ref, const T X[Vehicle::kStates], T U[Vehicle::kInputs],
                                T pos_err[3]) {
    using aurora_common::select;
    for (int i = 0; i < 3; ++i) pos_err[i] = ref.pos[i] - X[aurora_sim::kX + i];
    const T X4[4] = {X[aurora_sim::kX], X[aurora_sim::kY], X[aurora_sim::kZ], X[aurora_sim::kYaw]};
    const T V4[4] = {X[aurora_sim::kVx], X[aurora_sim::kVy], X[aurora_sim::kVz], X[aurora_sim::kYawRate]};
    const T Xd4[4] = {ref.pos[0], ref.pos[1], ref.pos[2], ref.yaw};
    const T dXd4[4] = {ref.vel[0], ref.vel[1], ref.vel[2], ref.yaw_rate};
    T Ur[4] = {m.Ur[0], m.Ur[1], m.Ur[2], m.Ur[3]}, Unew[4];
    compensatorCommand(model, g, g.period_steps * model.Ts, X4, V4, Xd4, dXd4, Ur, Unew);
    const auto due = m.wait < T(0.5);
    for (int i = 0; i < 4; ++i) m.Ur[i] = select(due, Ur[i], m.Ur[i]), m.held[i] = select(due, Unew[i], m.held[i]);
    m.wait = select(due, g.period_steps - T(1), m.wait - T(1));
    for (int i = 0; i < Vehicle::kInputs; ++i) U[i] = m.held[i];
  }
};

}  // namespace aurora_control
