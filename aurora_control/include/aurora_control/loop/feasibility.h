// Metrics and the four feasibility checks of the positioning study
// (docs/delay-and-study.md, "The positioning delay study"). Each check, once failed,
// stays failed. Works for scalars (Mask = bool) and SIMD batches (Mask = the
// batch's mask type).
#pragma once

#include <cmath>

#include "aurora_common/host_device.h"

namespace aurora_control {

template <typename T>
struct FeasibilityCriteria {
  T max_error;      // check 1: e <= max_error [m] (study: 5)
  T max_iae;        // check 2: IAE <= max_iae (study: 30 x 5.3218)
  T max_itae;       // check 3: ITAE <= max_itae (study: 50 x 7.3256)
  T error_growth;   // check 4: e <= error_growth |e0| (study: 2)
  T metric_dt;      // dt of the metric integrals (study: 0.03 s, not Ts)

  AURORA_HD static FeasibilityCriteria study() {
    return FeasibilityCriteria{T(5), T(30) * T(5.3218), T(50) * T(7.3256), T(2), T(0.03)};
  }
  template <typename U>
  AURORA_HD FeasibilityCriteria<U> cast() const {
    return FeasibilityCriteria<U>{U(max_error), U(max_iae), U(max_itae), U(error_growth),
                                  U(metric_dt)};
  }
};

template <typename T>
AURORA_HD inline T norm3(const T v[3]) {
  using std::sqrt;
  return sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
}

// The single-robot checks (docs/delay-and-study.md, criteria), in the order
// check() fills them: 1 the true error, 2 IAE, 3 ITAE, 4 the error's growth.
constexpr int kPositioningChecks = 4;

template <typename T, typename Mask>
struct PositioningMetrics {
  T iae;   // integral of |controller's position error| dt
  T itae;  // integral of t |controller's position error| dt
  T iasc;  // integral of |U| dt
  Mask ok[kPositioningChecks];

  AURORA_HD void reset() {
    iae = T(0); itae = T(0); iasc = T(0);
    for (int i = 0; i < kPositioningChecks; ++i) ok[i] = Mask(true);
  }

  // Step (3) of the loop: accumulate with the controller's (delayed) error.
  // |U| over the vehicle's Inputs commands, summed left to right.
  template <int Inputs>
  AURORA_HD void accumulate(const FeasibilityCriteria<T>& c, const T pos_err[3], const T U[Inputs],
                            const T& t) {
    using std::sqrt;
    const T e = norm3(pos_err);
    T u2 = U[0] * U[0];
    for (int i = 1; i < Inputs; ++i) u2 = u2 + U[i] * U[i];
    const T u = sqrt(u2);
    iae = iae + e * c.metric_dt;
    itae = itae + e * t * c.metric_dt;
    iasc = iasc + u * c.metric_dt;
  }

  // Step (5): the checks on the true error e after the model step.
  AURORA_HD void check(const FeasibilityCriteria<T>& c, const T& true_error,
                       const T& initial_error) {
    ok[0] = ok[0] & (true_error <= c.max_error);
    ok[1] = ok[1] & (iae <= c.max_iae);
    ok[2] = ok[2] & (itae <= c.max_itae);
    ok[3] = ok[3] & (true_error <= c.error_growth * initial_error);
  }

  AURORA_HD Mask feasible() const { return ok[0] & ok[1] & ok[2] & ok[3]; }
};

}  // namespace aurora_control
