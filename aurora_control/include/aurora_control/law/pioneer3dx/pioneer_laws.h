// The Pioneer P3-DX's two laws (docs/pioneer3dx.md; AuRoRA's
// cKinematicController and cDynamicController): a kinematic law on the
// control point (eq. P4) and the dynamic compensator on top of it (eq. P5).
// Both run every model step (AuRoRA's Pioneer scripts run them at the
// model's 0.1 s). Templated on the scalar, host and device, branch-free.
#pragma once

#include <cmath>

#include "aurora_common/host_device.h"
#include "aurora_common/scalar_math.h"
#include "aurora_control/law/law_gain_rows.h"
#include "aurora_control/law/law_of.h"
#include "aurora_control/task/task.h"
#include "aurora_sim/vehicle/pioneer3dx/pioneer3dx.h"

namespace aurora_control {

// The largest gain a controller file or a sweep gives the Pioneer's laws
// ([1/m], [m/s] and the compensation's): beyond 10 the tanh laws are steps.
constexpr double kPioneerGainMax = 10.0;

// The kinematic law's reference velocity Ur = K^-1 (dXd + K1 tanh(K2 Xtil))
// on x, y (eq. P4), K^-1 in closed form at heading psi, each saturated.
template <typename T>
AURORA_HD inline void pioneerReferenceVelocity(const T& a, const T k1[2], const T k2[2], const Reference<T>& ref,
                                               const T X[aurora_sim::kPioneerStateSize], double u_limit,
                                               double omega_limit, T Ur[2], T pos_err[3]) {
  using std::tanh;
  T v[2];
  for (int i = 0; i < 2; ++i) {
    pos_err[i] = ref.pos[i] - X[aurora_sim::kX + i];
    v[i] = ref.vel[i] + k1[i] * tanh(k2[i] * pos_err[i]);
  }
  pos_err[2] = T(0);  // a ground robot: its error is in the floor plane
  T s, c;
  aurora_common::sinCos(X[aurora_sim::kYaw], s, c);
  Ur[0] = aurora_common::clampSymmetric(c * v[0] + s * v[1], T(u_limit));  // as the original saturates
  Ur[1] = aurora_common::clampSymmetric((-s * v[0] + c * v[1]) / a, T(omega_limit));
}

template <typename T>
struct PioneerKinematicGains {
  T k1[2], k2[2];  // x, y: amplitude [m/s] and slope [1/m]
  AURORA_HD static PioneerKinematicGains defaults() { return {{T(0.35), T(0.35)}, {T(0.8), T(0.8)}}; }
};

template <typename T>
struct PioneerDynamicGains {
  T kc1[2], kc2[2];  // the kinematic part's
  T kd1[2], kd2[2];  // the compensation's (u, omega)
  // [s] the interval the measured acceleration divides by; 0: the model's
  // Ts. AuRoRA's 2018 fDynamicController divides by 0.1 at any period (the
  // UAV-UGV line runs it at 1/30 s; docs/pioneer3dx.md).
  T accel_interval;
  AURORA_HD static PioneerDynamicGains defaults() {
    return {{T(0.35), T(0.35)}, {T(0.8), T(0.8)}, {T(0.75), T(0.75)}, {T(0.12), T(0.035)}, T(0)};
  }
};

template <typename T, typename U>
AURORA_HD void castGains(const PioneerKinematicGains<U>& from, PioneerKinematicGains<T>& to) {
  for (int i = 0; i < 2; ++i) to.k1[i] = T(from.k1[i]), to.k2[i] = T(from.k2[i]);
}
template <typename T, typename U>
AURORA_HD void castGains(const PioneerDynamicGains<U>& from, PioneerDynamicGains<T>& to) {
  for (int i = 0; i < 2; ++i) {
    to.kc1[i] = T(from.kc1[i]), to.kc2[i] = T(from.kc2[i]), to.kd1[i] = T(from.kd1[i]), to.kd2[i] = T(from.kd2[i]);
  }
  to.accel_interval = T(from.accel_interval);
}

template <typename T>
struct NoPioneerMemory {
  AURORA_HD void reset() {}
};

// The previous measured (u, omega) the compensator differentiates.
template <typename T>
struct PioneerDynamicMemory {
  T Ua[2];
  AURORA_HD void reset() { Ua[0] = Ua[1] = T(0); }
};

// Which of the state the laws read: x, y, yaw (and u, omega).
template <int Width>
struct PioneerInput {
  static constexpr int kWidth = Width;
  AURORA_HD static constexpr int state(int j) {
    return j < 2 ? aurora_sim::kX + j : j == 2 ? aurora_sim::kYaw : aurora_sim::kPioneerU + j - 3;
  }
};

// Why a flight of a Pioneer law has no clamp to leave out (its laws'
// declaration saturatesItself(), other_laws.h).
constexpr const char* kPioneerSaturation =
    "for the Pioneer P3-DX: its laws saturate their commands (u within 0.75 or 1 m/s, omega within 1 rad/s) as "
    "AuRoRA's do, and RosAria clamps nothing";

// cKinematicController: Ud = Ur, u within 0.75 m/s, omega within 1 rad/s.
struct PioneerKinematic
    : LawOf<PioneerKinematic, aurora_sim::Pioneer3dx, PioneerKinematicGains, NoPioneerMemory> {
  using Input = PioneerInput<3>;
  static const char* name() { return "pioneer_kinematic"; }
  static const char* saturatesItself() { return kPioneerSaturation; }

  // The gains a sweep varies (law_gain_rows.h): k1, k2, x and y as one.
  static constexpr int kGainCount = 2;
  static GainRow gainRow(int i) {
    const auto d = PioneerKinematicGains<double>::defaults();
    return GainRow{i == 0 ? "k1" : "k2", i == 0 ? d.k1[0] : d.k2[0], 0.0, kPioneerGainMax, false};
  }
  template <typename T>
  AURORA_HD static void giveGains(Gains<T>& g, const double* v) {
    giveGain(g.k1[0], v[0]), giveGain(g.k1[1], v[0]);
    giveGain(g.k2[0], v[1]), giveGain(g.k2[1], v[1]);
  }

  template <typename T>
  AURORA_HD static void command(const aurora_sim::PioneerParams<T>& model, const Gains<T>& g, Memory<T>&,
                                const Reference<T>& ref, const T X[Vehicle::kStates], T U[Vehicle::kInputs],
                                T pos_err[3]) {
    pioneerReferenceVelocity(model.a, g.k1, g.k2, ref, X, 0.75, 1.0, U, pos_err);
  }
};

// cDynamicController (eq. P5): Ur of the kinematic part within 1, then
// Ud = H nu + C Ur with nu = 0.1 tanh(0.1 dU) + Kd1 tanh(Kd2 (Ur - U)), dU
// the measured acceleration over Ts (or the gains' accel_interval); each of Ud
// within 1.
struct PioneerDynamic : LawOf<PioneerDynamic, aurora_sim::Pioneer3dx, PioneerDynamicGains, PioneerDynamicMemory> {
  using Input = PioneerInput<5>;
  static const char* name() { return "pioneer_dynamic"; }
  static const char* saturatesItself() { return kPioneerSaturation; }

  // The gains a sweep varies (law_gain_rows.h): kc1, kc2 (x and y as one),
  // kd1 and kd2 on u and omega.
  static constexpr int kGainCount = 6;
  static GainRow gainRow(int i) {
    static const char* const names[kGainCount] = {"kc1", "kc2", "kd1_u", "kd1_omega", "kd2_u", "kd2_omega"};
    const auto d = PioneerDynamicGains<double>::defaults();
    const double preset[kGainCount] = {d.kc1[0], d.kc2[0], d.kd1[0], d.kd1[1], d.kd2[0], d.kd2[1]};
    return GainRow{names[i], preset[i], 0.0, kPioneerGainMax, false};
  }
  template <typename T>
  AURORA_HD static void giveGains(Gains<T>& g, const double* v) {
    giveGain(g.kc1[0], v[0]), giveGain(g.kc1[1], v[0]);
    giveGain(g.kc2[0], v[1]), giveGain(g.kc2[1], v[1]);
    giveGain(g.kd1[0], v[2]), giveGain(g.kd1[1], v[3]);
    giveGain(g.kd2[0], v[4]), giveGain(g.kd2[1], v[5]);
  }

  template <typename T>
  AURORA_HD static void command(const aurora_sim::PioneerParams<T>& model, const Gains<T>& g, Memory<T>& m,
                                const Reference<T>& ref, const T X[Vehicle::kStates], T U[Vehicle::kInputs],
                                T pos_err[3]) {
    using std::tanh;
    T Ur[2];
    pioneerReferenceVelocity(model.a, g.kc1, g.kc2, ref, X, 1.0, 1.0, Ur, pos_err);
    const T* th = model.theta;
    const T u = X[aurora_sim::kPioneerU], w = X[aurora_sim::kPioneerOmega];
    const T meas[2] = {u, w};
    T nu[2];
    using aurora_common::select;  // a SIMD batch's own select by argument-dependent lookup
    const T dt = select(g.accel_interval > T(0), g.accel_interval, model.Ts);
    for (int i = 0; i < 2; ++i) {
      const T dU = (meas[i] - m.Ua[i]) / dt;
      nu[i] = T(0.1) * tanh(T(0.1) * dU) + g.kd1[i] * tanh(g.kd2[i] * (Ur[i] - meas[i]));
    }
    U[aurora_sim::kPioneerURef] = aurora_common::clampUnit(th[0] * nu[0] + (th[3] * Ur[0] + -th[2] * w * Ur[1]));
    U[aurora_sim::kPioneerOmegaRef] = aurora_common::clampUnit(th[1] * nu[1] + (th[4] * w * Ur[0] + th[5] * Ur[1]));
    m.Ua[0] = u, m.Ua[1] = w;
  }
};

}  // namespace aurora_control
