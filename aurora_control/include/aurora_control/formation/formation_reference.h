// The desired formation Qd(t) (docs/formation.md, "References"): the
// formation's position fixed or on a figure-eight with AuRoRA's smoothstep
// time warp, and its shape (the remaining variables) fixed. Generic over
// the number of variables N, so another shape reuses it. ROS-free, host
// and device.
#pragma once

#include <cmath>
#include <limits>
#include <type_traits>

#include "aurora_common/host_device.h"
#include "aurora_control/formation/triangle_reference.h"
#include "aurora_control/formation/uav_ugv_line.h"

namespace aurora_control {

// kCarrousel: the triangle's moving reference (triangle_reference.h, eq. T6;
// nine variables only); kUavUgv: the UAV-UGV line's (uav_ugv_line.h, eq.
// L4; six).
enum class FormationPath : int { kFixed = 0, kLemniscate = 1, kCarrousel = 2, kUavUgv = 3 };

template <typename T, int N>
struct FormationReference {
  FormationPath path = FormationPath::kFixed;
  T duration = T(90);  // [s] T: the warp's length, and one lap of the figure-eight
  T amplitude[2] = {T(1), T(1)};  // [m] rX, rY of the figure-eight
  T Q[N] = {};  // the fixed values: the formation's position (x, y, z) and its shape; the figure-eight moves x, y

  // Qd at time t (eq. F8): tp = (3 (t/T)^2 - 2 (t/T)^3) T, w = 2 pi / T,
  // xF = x + rX sin(w tp), yF = y + rY sin(2 w tp); the rest fixed.
  AURORA_HD void at(const T& t, T Qd[N]) const {
    using std::sin;
    if (path == FormationPath::kCarrousel) return carrousel(t, Qd, std::integral_constant<bool, N == 9>());
    if (path == FormationPath::kUavUgv) return uavUgv(t, Qd, std::integral_constant<bool, N == 6>());
    for (int i = 0; i < N; ++i) Qd[i] = Q[i];
    if (path != FormationPath::kLemniscate) return;
    const T s = t / duration;
    const T tp = (T(3) * s * s - T(2) * s * s * s) * duration;
    const T w = T(2) * T(3.14159265358979323846) / duration;
    Qd[0] += amplitude[0] * sin(w * tp);
    Qd[1] += amplitude[1] * sin(T(2) * w * tp);
  }

 private:
  AURORA_HD static void carrousel(const T& t, T* Qd, std::true_type) { carrouselReference(t, Qd); }
  AURORA_HD static void uavUgv(const T& t, T* Qd, std::true_type) {
    T dQd[6];
    uavUgvReference(t, Qd, dQd);
  }
  // Another shape's Qd is not these shapes': NaN, which no check passes
  // (its files refuse the path).
  AURORA_HD static void carrousel(const T&, T* Qd, std::false_type) { notThisShape(Qd); }
  AURORA_HD static void uavUgv(const T&, T* Qd, std::false_type) { notThisShape(Qd); }
  AURORA_HD static void notThisShape(T* Qd) {
    for (int i = 0; i < N; ++i) Qd[i] = T(kNotThisShape);
  }
  // A constant, not quiet_NaN() (a host function) in device code.
  static constexpr double kNotThisShape = std::numeric_limits<double>::quiet_NaN();
};

}  // namespace aurora_control
