// The formation layer (docs/formation.md, "The formation layer"): every
// formation period it compares the formation variables Q of the drones'
// positions with the desired Qd, and gives each drone a reference position
// Xr and velocity dXr, which the drones hold until the next period. Written
// against a shape (line_formation.h); ROS-free, host and device, no clock:
// the caller says when a period is due and passes the positions it sees.
#pragma once

#include <cmath>

#include "aurora_common/host_device.h"

namespace aurora_control {

// The range of every shape's formation gains, K1 and K2 (its file's
// formation.gains, a sweep's formation_k1_* and formation_k2_*): positive,
// as the underactuated law's gains are.
constexpr double kFormationGainMin = 0.001, kFormationGainMax = 100.0;

// K1 (amplitudes) and K2 (slopes) of v = dQd + K1 tanh(K2 (Qd - Q)).
template <typename T, int N>
struct FormationGains {
  T k1[N], k2[N];

  // The shape's own defaults (Shape::defaultGains: the line's are AuRoRA's).
  template <class Shape>
  AURORA_HD static FormationGains of() {
    static_assert(Shape::kVariables == N, "a shape's gains, one of each per variable");
    FormationGains g;
    Shape::defaultGains(g.k1, g.k2);
    return g;
  }
};

// When the layer runs, and the time it reads Qd at (docs/formation.md,
// "One tick"). Robot steps and layer periods fall on a common base tick: a
// period is `period_ticks` of them, a robot step `step_ticks` (at most the
// period: one layer before a step at most). The line's layer runs on the
// robots' clock (every period_ticks steps from step 0, T_F = period_ticks
// Ts, AuRoRA's formation script's t = k Ts); the triangle's on its own
// (TriangularFormation3D's t = n T_F; its AR.Drones' 0.05 s beside 1/30 s
// on a base tick of 1/60 s: period 3, step 2). The runner, the SIMD
// engine, the kernel's threads and the formation node all ask it.
template <typename T>
struct LayerSchedule {
  long period_ticks = 6;   // p [base ticks]
  long step_ticks = 1;     // q [base ticks], q <= p
  bool own_clock = false;  // the layer's own clock (own_period), not the robots' steps
  T own_period = T(0);     // [s] T_F on its own clock

  // The period n whose layer runs before robot step k (-1: none): by its
  // base tick n p the robots took floor(n p / q) steps, so it falls before
  // step k when k q <= n p < (k + 1) q.
  AURORA_HD long periodBefore(long k) const {
    const long n = (k * step_ticks + period_ticks - 1) / period_ticks;
    return n * period_ticks < (k + 1) * step_ticks ? n : -1;
  }
  // T_F [s] for robots of step Ts.
  AURORA_HD T period(const T& Ts) const { return own_clock ? own_period : T(period_ticks) * Ts; }
  // The time of period n [s]: on the robots' clock its step's, k Ts.
  AURORA_HD T time(long n, const T& Ts) const { return own_clock ? T(n) * own_period : T(n * period_ticks) * Ts; }
  template <typename U>
  AURORA_HD LayerSchedule<U> cast() const {
    return LayerSchedule<U>{period_ticks, step_ticks, own_clock, U(own_period)};
  }
};

// A period on the robots' clock in whole robot steps of Ts (the line's, a
// build's own shape's): period / Ts when that is a whole number of at least
// one step (to 1e-9 of it), else 0, which each file's reader refuses.
inline long wholeRobotSteps(double period, double Ts) {
  const double steps = period / Ts;
  const long p = std::lround(steps);
  return p >= 1 && std::fabs(steps - double(p)) <= 1e-9 * steps ? p : 0;
}

template <typename T, class S>
class FormationLayer {
 public:
  using Shape = S;
  static constexpr int kN = Shape::kVariables;  // Q's size; also the drones' stacked positions (3 per drone)
  static_assert(kN == 3 * Shape::kDrones, "a shape of d drones has 3 d variables here");

  AURORA_HD FormationLayer(typename Shape::Law law, const FormationGains<T, kN>& gains, T period)
      : law_(law), gains_(gains), period_(period) {}

  // Before the first period: the references are the drones' start
  // positions X0 at rest, and the previous Qd is Qd(0), so the first
  // feed-forward dQd is 0 (no start-up spike; docs/formation.md).
  AURORA_HD void start(const T X0[kN], const T Qd0[kN]) {
    for (int i = 0; i < kN; ++i) Xr_[i] = X0[i], dXr_[i] = T(0), Qd_prev_[i] = Qd0[i];
  }

  // One period on the positions X the layer sees, towards Qd (eq. F3):
  // Q of X, Q~ = Qd - Q (the shape's error: the line's without angle
  // wrapping, the triangle's with its wraps), dQd the backward difference
  // over the period, v = dQd + K1 tanh(K2 Q~), dXr of v by the law,
  // Xr += dXr T_F.
  AURORA_HD void update(const T X[kN], const T Qd[kN]) {
    using std::tanh;
    Shape::variables(X, Q_);
    Shape::error(X, Qd, Q_, Qtil_);
    T v[kN];
    for (int i = 0; i < kN; ++i) {
      Qd_[i] = Qd[i];
      dQd_[i] = (Qd[i] - Qd_prev_[i]) / period_;
      v[i] = dQd_[i] + gains_.k1[i] * tanh(gains_.k2[i] * Qtil_[i]);
      Qd_prev_[i] = Qd[i];
    }
    Shape::velocities(law_, X, v, dXr_);
    for (int i = 0; i < kN; ++i) Xr_[i] += dXr_[i] * period_;
  }
  // As the one formation loop calls a layer, with its period's time
  // (formation_runner.h; this layer's rate is its backward difference).
  AURORA_HD void update(const T X[kN], const T Qd[kN], const T&) { update(X, Qd); }

  // Drone d's reference (0-based): its position and velocity [m, m/s].
  AURORA_HD const T* position(int d) const { return Xr_ + 3 * d; }
  AURORA_HD const T* velocity(int d) const { return dXr_ + 3 * d; }
  // The last period's variables, desired variables, error and feed-forward.
  AURORA_HD const T* Q() const { return Q_; }
  AURORA_HD const T* Qd() const { return Qd_; }
  AURORA_HD const T* Qtil() const { return Qtil_; }
  AURORA_HD const T* dQd() const { return dQd_; }
  AURORA_HD T period() const { return period_; }

 private:
  typename Shape::Law law_;
  FormationGains<T, kN> gains_;
  T period_;  // [s] T_F
  T Xr_[kN], dXr_[kN], Qd_prev_[kN];
  T Q_[kN] = {}, Qd_[kN] = {}, Qtil_[kN] = {}, dQd_[kN] = {};
};

}  // namespace aurora_control
