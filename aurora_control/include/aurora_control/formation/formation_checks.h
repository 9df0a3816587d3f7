// The formation's metrics and its five checks (docs/formation.md, "Formation
// checks"): how far the formation's position and its shape are from the
// desired ones once the formation has settled, their integrals, how close
// the drones come to each other, and whether a ground robot's commands stay
// within what its real safety layer passes. Written against a shape (its
// variables and inverse transform), for scalars (Mask = bool) and SIMD
// batches, host and device. Each check, once failed, stays failed.
#pragma once

#include <cmath>
#include <type_traits>

#include "aurora_control/formation/ground_commands.h"
#include "aurora_control/loop/feasibility.h"
#include "aurora_common/scalar_math.h"

namespace aurora_control {

template <typename T>
struct FormationCriteria {
  T settle_time;         // [s] the errors are judged from this time on
  T max_position_error;  // check 1 [m]: |p_F - p_Fd| after settle_time
  T max_shape_error;     // check 2 [m]: each drone's offset from drone 1 against the desired one
  T max_iae_position;    // check 3 [m s]: the position error's integral after settle_time ...
  T max_iae_shape;       // ... and the shape error's
  T min_distance;        // check 4 [m]: the drones' centres never closer (a collision)
  T max_ground_speed;      // check 5 [m/s]: a ground robot's |speed command| at most this ...
  T max_ground_turn_rate;  // ... and its |turn rate command| [rad/s], every tick

  // The defaults of docs/formation.md, "Formation checks"; check 5's are
  // config/safety/real_ground.yaml's max_speed and max_turn_rate (a test
  // reads the file and compares).
  AURORA_HD static FormationCriteria study() {
    return FormationCriteria{T(10), T(0.75), T(1.5), T(30), T(120), T(0.6), T(0.5), T(1)};
  }
  template <typename U>
  AURORA_HD FormationCriteria<U> cast() const {
    return FormationCriteria<U>{U(settle_time),   U(max_position_error), U(max_shape_error),
                                U(max_iae_position), U(max_iae_shape),  U(min_distance),
                                U(max_ground_speed), U(max_ground_turn_rate)};
  }
};

// The distance between the drones' offsets from drone 1 in X and in Xd [m].
template <class Shape, typename T>
AURORA_HD inline T offsetError(const T X[Shape::kVariables], const T Xd[Shape::kVariables]) {
  using std::sqrt;
  T sum = T(0);
  for (int d = 1; d < Shape::kDrones; ++d) {
    for (int i = 0; i < 3; ++i) {
      const T e = (X[3 * d + i] - X[i]) - (Xd[3 * d + i] - Xd[i]);
      sum = sum + e * e;
    }
  }
  return sqrt(sum);
}

// A shape with its own shape error (Shape::shapeError: the triangle's
// sides); the others the offsets' (offsetError).
template <class Shape, class = void>
struct HasShapeError : std::false_type {};
template <class Shape>
struct HasShapeError<Shape, decltype(void(&Shape::shapeError))> : std::true_type {};

template <class Shape, typename T>
AURORA_HD inline T shapeErrorOf(const T* X, const T* Xd, std::false_type) {
  return offsetError<Shape>(X, Xd);
}
template <class Shape, typename T>
AURORA_HD inline T shapeErrorOf(const T* X, const T* Xd, std::true_type) {
  return Shape::shapeError(X, Xd);
}

// The two errors of positions X against the desired positions Xd (eq. F9;
// Xd = Shape::positions(Qd), which changes only when the layer runs): the
// formation's position error |p_Fd - p_F| and the shape error, the distance
// between the drones' offsets from drone 1 and the desired offsets (for the
// line: where drone 2 is against where it should be, seen from drone 1;
// the triangle's: its sides against the desired ones) [m].
template <class Shape, typename T>
AURORA_HD inline void formationErrors(const T X[Shape::kVariables], const T Xd[Shape::kVariables], T& position,
                                      T& shape) {
  T p[3], pd[3];
  Shape::formationPosition(X, p);
  Shape::formationPosition(Xd, pd);
  const T ep[3] = {pd[0] - p[0], pd[1] - p[1], pd[2] - p[2]};
  position = norm3(ep);
  shape = shapeErrorOf<Shape>(X, Xd, HasShapeError<Shape>());
}

// The smaller of two distances [m], NaN once either is: a NaN distance (a
// diverged robot's) is kept, not passed over by a later finite one.
template <typename T>
AURORA_HD inline T smallerDistance(const T& closest, const T& r) {
  using aurora_common::select;
  // !(r == r): r is NaN (xsimd's != is ordered on AVX and AVX-512, false for NaN).
  return select((r < closest) | !(r == r), r, closest);
}

// The smallest distance between any two drones of positions X [m]; NaN
// where any drone's position is NaN (whichever drone it is).
template <class Shape, typename T>
AURORA_HD inline T closestPair(const T X[Shape::kVariables]) {
  T closest = T(1e30);
  for (int a = 0; a < Shape::kDrones; ++a) {
    for (int b = a + 1; b < Shape::kDrones; ++b) {
      const T d[3] = {X[3 * b] - X[3 * a], X[3 * b + 1] - X[3 * a + 1], X[3 * b + 2] - X[3 * a + 2]};
      closest = smallerDistance(closest, norm3(d));
    }
  }
  return closest;
}

// The formation's checks: 1-5 of docs/formation.md, "Formation checks".
constexpr int kFormationChecks = 5;

template <typename T, typename Mask, class Shape>
struct FormationMetrics {
  static constexpr int kN = Shape::kVariables;
  static constexpr int kChecks = kFormationChecks;
  T iae_position, iae_shape;      // [m s] after settle_time
  T max_position, max_shape;      // [m] the largest errors after settle_time
  T closest;                      // [m] the smallest distance between drones, whole flight
  T ground_command;               // the largest share of a ground robot's check 5 limits its commands used (0: none)
  Mask ok[kChecks];

  AURORA_HD void reset() {
    iae_position = iae_shape = max_position = max_shape = ground_command = T(0);
    closest = T(1e30);
    for (int i = 0; i < kChecks; ++i) ok[i] = Mask(true);
  }

  // Tick k at time t = k Ts: the drones at X_k against the positions Xd of
  // the layer's held Qd (the errors of "Formation errors"), integrated over
  // one tick dt.
  AURORA_HD void add(const FormationCriteria<T>& c, const T X[kN], const T Xd[kN], const T& t, const T& dt) {
    using aurora_common::select;
    T position, shape;
    formationErrors<Shape>(X, Xd, position, shape);
    const T r = closestPair<Shape>(X);
    const T zero(0);
    // A drone whose position is not finite (a diverged or NaN drone) fails
    // every check from then on, and the figures show the NaN: every error
    // and distance of a NaN position is NaN, and x * 0 == 0 is false for
    // NaN and infinity alike.
    const auto finite = (position + shape + r) * zero == zero;
    closest = select(!finite | (r < closest), r, closest);
    const auto judged = t >= c.settle_time;
    iae_position = iae_position + select(judged, position * dt, zero);
    iae_shape = iae_shape + select(judged, shape * dt, zero);
    max_position = select(judged & (!finite | (position > max_position)), position, max_position);
    max_shape = select(judged & (!finite | (shape > max_shape)), shape, max_shape);
    ok[0] = ok[0] & finite & (!judged | (position <= c.max_position_error));
    ok[1] = ok[1] & finite & (!judged | (shape <= c.max_shape_error));
    ok[2] = ok[2] & finite & (iae_position <= c.max_iae_position) & (iae_shape <= c.max_iae_shape);
    ok[3] = ok[3] & finite & (r >= c.min_distance);
  }

  // Check 5 at a tick: each ground robot's commands U (as it applies them:
  // its law's, over its downlink; Vehicle: the crew's, a robot's params
  // choose for a mixed crew) within the limits. A NaN command fails it and
  // is kept.
  template <class Vehicle, class Params, class Step>
  AURORA_HD void addCommands(const FormationCriteria<T>& c, const Params* params, const Step* steps) {
    using aurora_common::select;
    using std::sqrt;
    for (int d = 0; d < Shape::kDrones; ++d) {
      T speed, turn_rate;
      if (!GroundCommands<Vehicle>::of(params[d].model, steps[d].U, speed, turn_rate)) continue;
      const T s = speed / c.max_ground_speed, w = turn_rate / c.max_ground_turn_rate;
      const T s2 = s * s, w2 = w * w;
      const T share = sqrt(select((s2 > w2) | !(s2 == s2), s2, w2));  // the larger, or the NaN (as smallerDistance)
      ground_command = select(!(share <= ground_command), share, ground_command);
      ok[4] = ok[4] & (s2 <= T(1)) & (w2 <= T(1));
    }
  }

  AURORA_HD Mask feasible() const { return ok[0] & ok[1] & ok[2] & ok[3] & ok[4]; }
};

}  // namespace aurora_control
