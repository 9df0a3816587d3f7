// Branch-free helpers that work for plain scalars and for SIMD batch types.
// The model is written once; a SIMD engine instantiates it on a batch type
// whose comparisons return masks, so data-dependent branches go through
// select() instead of `if`.
#pragma once

#include <cmath>

#include "aurora_common/host_device.h"

namespace aurora_common {

// pi, written once for the whole project (the double nearest to it).
constexpr double kPi = 3.141592653589793;

template <typename T>
AURORA_HD inline T select(bool condition, const T& a, const T& b) {
  return condition ? a : b;
}

// sin and cos of one angle. Scalars use the C library's sin and cos (the
// reference's values); a SIMD batch type provides its own sinCos overload
// (found by argument-dependent lookup) that shares the range reduction.
template <typename T>
AURORA_HD inline void sinCos(const T& x, T& s, T& c) {
  using std::cos;
  using std::sin;
  s = sin(x);
  c = cos(x);
}

// Wraps an angle once into [-pi, pi] as the reference does (step 9 of the
// model): above pi subtract 2 pi, below -pi add 2 pi.
template <typename T>
AURORA_HD inline T wrapAngleOnce(const T& angle) {
  const T pi = T(kPi);
  const T two_pi = T(2.0 * kPi);
  T wrapped = select(angle > pi, angle - two_pi, angle);
  return select(wrapped < -pi, wrapped + two_pi, wrapped);
}

// The underactuated controller's angle-error rule, as the reference writes
// it (docs/controllers.md, underactuated law, step 1): if |e| > pi then e -= 2 pi;
// then if e < -pi, e += 2 pi. Unlike wrapAngleOnce, an error below -pi goes
// down and back up by 2 pi (rounding included), as in the reference.
template <typename T>
AURORA_HD inline T wrapErrorAsReference(const T& e) {
  const T pi = T(kPi);
  const T two_pi = T(2.0 * kPi);
  const T once = select((e > pi) | (e < -pi), e - two_pi, e);
  return select(once < -pi, once + two_pi, once);
}

// Clamps u to [-limit, limit] (|u| > limit becomes limit sign(u)). NaN is
// not a number a driver could send; callers reject it before clamping.
template <typename T>
AURORA_HD inline T clampSymmetric(const T& u, const T& limit) {
  T c = select(u > limit, limit, u);
  return select(c < -limit, -limit, c);
}

// Clamps a command to [-1, 1], as the AR.Drone and Bebop drivers do.
template <typename T>
AURORA_HD inline T clampUnit(const T& u) {
  return clampSymmetric(u, T(1));
}

}  // namespace aurora_common
