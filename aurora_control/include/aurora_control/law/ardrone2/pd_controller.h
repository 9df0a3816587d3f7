// PD law with saturation used in the delay study (docs/controllers.md,
// "PD law with saturation", eq. 3.1 of the thesis):
//   a = xdd_d + Kd tanh(xd_dot - xc_dot) + Kp tanh(xd - xc),  U = [-a_y, -a_x, a_z, 0].
// The law does not clamp U; callers that feed a real drone clamp to [-1, 1].
#pragma once

#include <cmath>
#include <limits>

#include "aurora_common/host_device.h"
#include "aurora_control/law/law_gain_rows.h"

namespace aurora_control {

// The gains' accepted range, one for both (every entry point: the
// controller file, the live settings, the sweep, replay's --kp/--kd).
constexpr double kPdGainMin = 0.0, kPdGainMax = 10.0;

template <typename T>
struct PdGains {
  T kp;  // proportional gain on tanh(position error) [1/s^2 per m, dimensionless command]
  T kd;  // derivative gain on tanh(velocity error)
};

// Computes the command from the desired position/velocity/acceleration and
// the (possibly delayed) position and velocity the controller received.
// Writes the position error it used to `pos_err` (metrics use it).
template <typename T>
AURORA_HD inline void pdSaturatedLaw(const PdGains<T>& g, const T desired_pos[3],
                                     const T desired_vel[3], const T desired_acc[3],
                                     const T pos[3], const T vel[3], T U[4], T pos_err[3]) {
  using std::tanh;
  T a[3];
  for (int i = 0; i < 3; ++i) {
    pos_err[i] = desired_pos[i] - pos[i];
    const T vel_err = desired_vel[i] - vel[i];
    a[i] = desired_acc[i] + g.kd * tanh(vel_err) + g.kp * tanh(pos_err[i]);
  }
  U[0] = -a[1];
  U[1] = -a[0];
  U[2] = a[2];
  U[3] = T(0);
}

// The gains a sweep may vary (law_gain_rows.h): kp and kd, in the
// controller node's range, without a preset (a sweep of the PD law names
// both: the thesis's grid).
struct PdGainRows {
  static constexpr int kGainCount = 2;
  static GainRow gainRow(int i) {
    return {i == 0 ? "kp" : "kd", std::numeric_limits<double>::quiet_NaN(), kPdGainMin, kPdGainMax, false,
            "the controller node's PD gain range",
            i == 0 ? "gain on the tanh-saturated position error (eq. 3.1)" : "gain on the tanh-saturated velocity error"};
  }
  template <typename T>
  AURORA_HD static void giveGains(PdGains<T>& g, const double* v) {
    giveGain(g.kp, v[0]);
    giveGain(g.kd, v[1]);
  }
  static double& gainAt(PdGains<double>& g, int i) { return i == 0 ? g.kp : g.kd; }
};

}  // namespace aurora_control
