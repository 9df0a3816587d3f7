// The formation layer (docs/formation.md, "The formation layer"): every
// formation period it compares the formation variables Q of the drones'
// positions with the desired Qd, and gives each drone a reference position
// Xr and velocity dXr, which the drones hold until the next period. Written
// against a shape (line_formation.h); ROS-free, host and device, no clock:
// the caller says when a period is due and passes the positions it sees.
#pragma once

#include <cmath>

#include "aurora_control/formation/line_formation.h"

namespace aurora_control {

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

// Whether the layer runs at tick k: every `period_steps` robot steps from
// tick 0 (T_F = period_steps Ts; docs/formation.md, "One tick"). The
// runner, the SIMD engine and the formation node all ask this.
AURORA_HD inline bool layerDue(long k, long period_steps) { return k % period_steps == 0; }

template <typename T, class Shape>
class FormationLayer {
 public:
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
