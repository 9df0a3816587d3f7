// The triangle's standard desired formation, AuRoRA's "Carrossel"
// (docs/formation.md, "The triangle's reference", eq. T6): an equilateral
// triangle of 1.6 m sides at 1.6 m whose centroid circles with radius
// 0.25 m and period 20 s in the warped time tp = (3 s^2 - 2 s^3) Tf,
// s = t / Tf, Tf = 40 s (not clamped: past 40 s tp decreases again), while
// its heading turns from -0.1 by -pi + 0.1 per 20 s of tp (unwrapped).
// Host and device.
#pragma once

#include <cmath>

#include "aurora_common/host_device.h"
#include "aurora_common/scalar_math.h"

namespace aurora_control {

template <typename T>
AURORA_HD inline void carrouselReference(const T& t, T Qd[9]) {
  const T pi = T(aurora_common::kPi);
  const T Tf = T(40), w = T(2) * pi / T(20);
  const T s = t / Tf;
  const T tp = (T(3) * s * s - T(2) * s * s * s) * Tf;
  using aurora_common::sinCos;  // or a SIMD batch's own, by argument-dependent lookup
  T sw, cw;
  sinCos(w * tp, sw, cw);
  Qd[0] = T(-0.25) + T(0.25) * cw;
  Qd[1] = T(0.25) * sw;
  Qd[2] = T(1.6);
  Qd[3] = T(1.6), Qd[4] = T(1.6), Qd[5] = pi / T(3);
  Qd[6] = T(0), Qd[7] = T(0);
  Qd[8] = T(-0.1) + (-pi + T(0.1)) * tp / T(20);
}

}  // namespace aurora_control
