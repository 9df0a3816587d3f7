// How a combination's values set the gains of each law a sweep flies
// (docs/delay-and-study.md, "Sweeping any parameter"): SweepGains<Data>
// names the sweep parameters a law family reads (host and device). The
// AR.Drone's laws read kp, kd and the underactuated law's 12 gains; the
// other vehicles' laws read their own block from kParamFirstLawGain
// (combination.h), whose rows (name, default, range) each law gives here
// and the parameter table (parameters.cpp) lists. Their x and y gains are
// one parameter (AuRoRA's are equal on x and y; a controller file may
// still set them apart for a flight).
#pragma once

#include "aurora_common/host_device.h"
#include "aurora_control/law/bebop2_compensator.h"
#include "aurora_control/law/control_law.h"
#include "aurora_control/law/other_laws.h"
#include "aurora_control/law/pioneer_laws.h"
#include "aurora_sweep/combination.h"

namespace aurora_sweep {

template <class Data>
struct SweepGains;

// The AR.Drone's laws: the PD law's kp, kd; the underactuated law's 12
// gains (underactuatedGainName order).
template <>
struct SweepGains<aurora_control::ArdroneLawData> {
  template <typename T>
  AURORA_HD static aurora_control::LawGains<T> from(const Combination& c) {
    aurora_control::LawGains<T> g;
    g.pd.kp = T(c.v[kParamKp]);
    g.pd.kd = T(c.v[kParamKd]);
    for (int i = 0; i < kUnderactuatedGainCount; ++i) {
      aurora_control::underactuatedGain(g.underactuated, i) = T(c.v[kParamFirstUnderactuatedGain + i]);
    }
    return g;
  }
};

// One row of a law's own block: its name, its default (the law's
// defaults()), its accepted range, whole values only.
struct LawGainRow {
  const char* name;
  double preset, min, max;
  bool whole;
};

// A swept value into a gain; NaN (a formation sweep's robot gain it does
// not give, robot_gains.h) keeps the gain's value.
template <typename T>
AURORA_HD inline void giveGain(T& gain, double v) {
  if (v == v) gain = T(v);
}

// The Bebop 2 compensator (docs/bebop2.md): ksp, ksd, kp on xy, z, yaw,
// then period_steps (the law runs every period_steps model steps: 1 is
// 30 Hz, 6 is 5 Hz). Its unread kd group keeps AuRoRA's values.
template <>
struct SweepGains<aurora_control::Bebop2Compensator> {
  static constexpr int kFirst = kParamFirstCompensatorGain, kCount = 10;
  static LawGainRow row(int i) {
    static const char* const names[kCount] = {"ksp_xy", "ksp_z", "ksp_yaw", "ksd_xy", "ksd_z",
                                              "ksd_yaw", "kp_xy", "kp_z", "kp_yaw", "period_steps"};
    const auto d = aurora_control::CompensatorGains<double>::defaults();
    const double* group[3] = {d.ksp, d.ksd, d.kp};
    if (i == 9) return LawGainRow{names[i], d.period_steps, 1.0, 30.0, true};
    return LawGainRow{names[i], group[i / 3][i % 3 == 0 ? 0 : i % 3 + 1], 0.0,
                      aurora_control::kCompensatorGainMax, false};
  }
  // The block v (kCount values, row order) into g.
  template <typename T>
  AURORA_HD static void set(aurora_control::CompensatorGains<T>& g, const double* v) {
    T* group[3] = {g.ksp, g.ksd, g.kp};
    for (int j = 0; j < 3; ++j) {
      for (int axis = 0; axis < 4; ++axis) giveGain(group[j][axis], v[3 * j + (axis < 2 ? 0 : axis - 1)]);
    }
    giveGain(g.period_steps, v[9]);
  }
  template <typename T>
  AURORA_HD static aurora_control::CompensatorGains<T> from(const Combination& c) {
    aurora_control::CompensatorGains<T> g = aurora_control::CompensatorGains<T>::defaults();
    set(g, c.v + kFirst);
    return g;
  }
};

// The Pioneer's dynamic law (docs/pioneer3dx.md, eq. P5): kc1, kc2 on x
// and y, kd1 and kd2 on u and omega.
template <>
struct SweepGains<aurora_control::PioneerDynamic> {
  static constexpr int kFirst = kParamFirstPioneerDynamicGain, kCount = 6;
  static LawGainRow row(int i) {
    static const char* const names[kCount] = {"kc1", "kc2", "kd1_u", "kd1_omega", "kd2_u", "kd2_omega"};
    const auto d = aurora_control::PioneerDynamicGains<double>::defaults();
    const double preset[kCount] = {d.kc1[0], d.kc2[0], d.kd1[0], d.kd1[1], d.kd2[0], d.kd2[1]};
    return LawGainRow{names[i], preset[i], 0.0, aurora_control::kPioneerGainMax, false};
  }
  template <typename T>
  AURORA_HD static void set(aurora_control::PioneerDynamicGains<T>& g, const double* v) {
    giveGain(g.kc1[0], v[0]), giveGain(g.kc1[1], v[0]);
    giveGain(g.kc2[0], v[1]), giveGain(g.kc2[1], v[1]);
    giveGain(g.kd1[0], v[2]), giveGain(g.kd1[1], v[3]);
    giveGain(g.kd2[0], v[4]), giveGain(g.kd2[1], v[5]);
  }
  template <typename T>
  AURORA_HD static aurora_control::PioneerDynamicGains<T> from(const Combination& c) {
    aurora_control::PioneerDynamicGains<T> g = aurora_control::PioneerDynamicGains<T>::defaults();
    set(g, c.v + kFirst);
    g.accel_interval = T(0);  // the model's Ts
    return g;
  }
};

// The Pioneer's kinematic law (eq. P4): k1, k2 on x and y.
template <>
struct SweepGains<aurora_control::PioneerKinematic> {
  static constexpr int kFirst = kParamFirstPioneerKinematicGain, kCount = 2;
  static LawGainRow row(int i) {
    const auto d = aurora_control::PioneerKinematicGains<double>::defaults();
    return LawGainRow{i == 0 ? "k1" : "k2", i == 0 ? d.k1[0] : d.k2[0], 0.0, aurora_control::kPioneerGainMax,
                      false};
  }
  template <typename T>
  AURORA_HD static void set(aurora_control::PioneerKinematicGains<T>& g, const double* v) {
    giveGain(g.k1[0], v[0]), giveGain(g.k1[1], v[0]);
    giveGain(g.k2[0], v[1]), giveGain(g.k2[1], v[1]);
  }
  template <typename T>
  AURORA_HD static aurora_control::PioneerKinematicGains<T> from(const Combination& c) {
    aurora_control::PioneerKinematicGains<T> g = aurora_control::PioneerKinematicGains<T>::defaults();
    set(g, c.v + kFirst);
    return g;
  }
};

// The laws a sweep flies besides the AR.Drone's (law/other_laws.h).
using aurora_control::forEachOtherLaw;

}  // namespace aurora_sweep
