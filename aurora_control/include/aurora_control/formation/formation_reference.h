// The desired formation Qd(t) (docs/formation.md, "References"): the
// formation's position fixed or on a figure-eight with AuRoRA's smoothstep
// time warp, and its shape (the remaining variables) fixed; or the shape's
// own moving reference, where it declares one. Generic over the shape (its
// number of variables N): no shape is named here. ROS-free, host and device.
#pragma once

#include <cmath>
#include <limits>
#include <type_traits>

#include "aurora_common/host_device.h"

namespace aurora_control {

// kOwn: the shape's own moving reference, `template <typename V>
// AURORA_HD static void ownReference(const V& t, V Qd[kVariables])` in the
// shape (the triangle's carrousel, eq. T6; the UAV-UGV line's trajectory,
// eq. L4); its files choose it, and a shape without one never has it.
enum class FormationPath : int { kFixed = 0, kLemniscate = 1, kOwn = 2 };

template <typename T, class Shape>
struct FormationReference {
  static constexpr int N = Shape::kVariables;
  FormationPath path = FormationPath::kFixed;
  T duration = T(90);  // [s] T: the warp's length, and one lap of the figure-eight
  T amplitude[2] = {T(1), T(1)};  // [m] rX, rY of the figure-eight
  T Q[N] = {};  // the fixed values: the formation's position (x, y, z) and its shape; the figure-eight moves x, y

  // Qd at time t (eq. F8): tp = (3 (t/T)^2 - 2 (t/T)^3) T, w = 2 pi / T,
  // xF = x + rX sin(w tp), yF = y + rY sin(2 w tp); the rest fixed.
  AURORA_HD void at(const T& t, T Qd[N]) const {
    using std::sin;
    if (path == FormationPath::kOwn) return own<Shape>(t, Qd, 0);
    for (int i = 0; i < N; ++i) Qd[i] = Q[i];
    if (path != FormationPath::kLemniscate) return;
    const T s = t / duration;
    const T tp = (T(3) * s * s - T(2) * s * s * s) * duration;
    const T w = T(2) * T(3.14159265358979323846) / duration;
    Qd[0] += amplitude[0] * sin(w * tp);
    Qd[1] += amplitude[1] * sin(T(2) * w * tp);
  }

 private:
  template <class S>
  AURORA_HD static auto own(const T& t, T* Qd, int) -> decltype(S::ownReference(t, Qd)) {
    return S::ownReference(t, Qd);
  }
  // A shape without a reference of its own: NaN, which no check passes.
  template <class S>
  AURORA_HD static void own(const T&, T* Qd, long) {
    for (int i = 0; i < N; ++i) Qd[i] = T(kNotThisShape);
  }
  // A constant, not quiet_NaN() (a host function) in device code.
  static constexpr double kNotThisShape = std::numeric_limits<double>::quiet_NaN();
};

}  // namespace aurora_control
