// AuRoRA's 3-D triangular formation of three robots (docs/formation.md,
// "The triangle"; its TriangularFormation3D): formation variables
// Q = (xF, yF, zF, p, q, beta, phi, theta, psi) of the robots' positions
// X = (p1, p2, p3), the inverse transform, the error with its wraps, and
// the five priority laws' robot velocities. A shape as line_formation.h is
// (the formation layer is written against the same interface). ROS-free,
// host and device, without branches on the state: the pseudo-inverses are
// closed forms (triangle_pinv.h), so SIMD lanes and CUDA threads run them.
#pragma once

#include <cmath>

#include "aurora_common/host_device.h"
#include "aurora_common/scalar_math.h"
#include "aurora_control/formation/triangle/triangle_pinv.h"
#include "aurora_control/formation/triangle/triangle_reference.h"

namespace aurora_control {

// The priority laws by their AuRoRA names (docs/formation.md, "Triangle
// laws"): N (all tasks at once), PSO, SPO, OSP, S-PO (P: position, S: shape,
// O: orientation, the first the highest). PSO, SPO and S-PO are one law:
// the position rows are orthogonal to the others (eq. T5).
enum class TriangleLaw : int { kN = 0, kPSO, kSPO, kOSP, kSdashPO };

// A triangle sweep's law: its formation_law value, the law's index (a
// sweep's formationCombination finds this by its law's type; a shape whose
// law no sweep varies has none and flies its file's).
AURORA_HD inline void setSweptLaw(TriangleLaw& law, double v) { law = static_cast<TriangleLaw>(static_cast<int>(v)); }

template <typename T>
struct TriangleFormation {
  using Law = TriangleLaw;
  static constexpr Law kDefaultLaw = TriangleLaw::kN;  // AuRoRA's standard runs
  static constexpr int kDrones = 3;
  static constexpr int kVariables = 9;

  // Variable i's name (the flight tool's Q_ and Qd_ columns) and its gain's
  // (a sweep's formation_k1_NAME). Host only.
  static const char* variableName(int i) {
    static const char* const names[kVariables] = {"xF", "yF", "zF", "p", "q", "beta", "phi", "theta", "psi"};
    return names[i];
  }
  // Its own moving reference (formation_reference.h, FormationPath::kOwn):
  // the carrousel (eq. T6).
  template <typename V>
  AURORA_HD static void ownReference(const V& t, V Qd[kVariables]) {
    carrouselReference(t, Qd);
  }
  static const char* gainName(int i) {
    static const char* const names[kVariables] = {"x", "y", "z", "p", "q", "beta", "phi", "theta", "psi"};
    return names[i];
  }

  // AuRoRA's class gains: K1 = 3 I, K2 = I (its kinematic runs; flying
  // AR.Drones need K1 = 0.1 I, docs/formation.md).
  AURORA_HD static void defaultGains(T k1[9], T k2[9]) {
    for (int i = 0; i < 9; ++i) k1[i] = T(3), k2[i] = T(1);
  }

  // Q of positions X (eq. T1), evaluated as the original writes it: beta
  // the unsigned angle at robot 1, the orientation of the median
  // m = 2 p1 - p2 - p3 with atan (not atan2) for phi and theta.
  AURORA_HD static void variables(const T X[9], T Q[9]) {
    using std::acos;
    using std::atan;
    using std::atan2;
    for (int i = 0; i < 3; ++i) Q[i] = (X[i] + X[3 + i] + X[6 + i]) / T(3);
    const T p = triangle_detail::distance(X, X + 3), q = triangle_detail::distance(X, X + 6);
    const T r = triangle_detail::distance(X + 3, X + 6);
    Q[3] = p, Q[4] = q;
    // The cosine law's quotient within [-1, 1]: in float a narrow angle
    // rounds it past 1 and acos gives NaN (double, in range, is unchanged).
    Q[5] = acos(aurora_common::clampUnit((p * p + q * q - r * r) / (T(2) * p * q)));
    T m[3];
    triangle_detail::median(X, m);
    Q[6] = atan(m[2] / m[1]);
    Q[7] = -atan(m[2] / m[0]);
    Q[8] = atan2(m[1], m[0]);
  }

  AURORA_HD static void formationPosition(const T X[9], T c[3]) {
    for (int i = 0; i < 3; ++i) c[i] = (X[i] + X[3 + i] + X[6 + i]) / T(3);
  }

  // The positions of Q (eq. T2): the medians' lengths and the angles at
  // the centroid place the robots in the plane of e1 (the median's
  // direction, R = Rz(psi) Ry(theta) Rx(phi)) and e2, robot 2 on the +e2 side.
  AURORA_HD static void positions(const T Q[9], T X[9]) {
    using std::acos;
    using std::cos;
    using std::sin;
    using std::sqrt;
    using aurora_common::sinCos;  // or a SIMD batch's own, by argument-dependent lookup
    const T p = Q[3], q = Q[4];
    const T r = sqrt(p * p + q * q - T(2) * p * q * cos(Q[5]));
    const T h1 = sqrt((p * p + q * q) / T(2) - r * r / T(4));
    const T h2 = sqrt((r * r + p * p) / T(2) - q * q / T(4));
    const T h3 = sqrt((q * q + r * r) / T(2) - p * p / T(4));
    const T a1 = acos((T(4) * (h1 * h1 + h2 * h2) - T(9) * p * p) / (T(8) * h1 * h2));
    const T a2 = acos((T(4) * (h1 * h1 + h3 * h3) - T(9) * q * q) / (T(8) * h1 * h3));
    T sf, cf, st, ct, sp, cp;
    sinCos(Q[6], sf, cf);
    sinCos(Q[7], st, ct);
    sinCos(Q[8], sp, cp);
    const T e1[3] = {ct * cp, ct * sp, -st};
    const T e2[3] = {sf * st * cp - cf * sp, sf * st * sp + cf * cp, sf * ct};
    const T s1 = sin(a1), c1 = cos(a1), s2 = sin(a2), c2 = cos(a2);
    for (int i = 0; i < 3; ++i) {
      X[i] = Q[i] + T(2) / T(3) * h1 * e1[i];
      X[3 + i] = Q[i] + T(2) / T(3) * h2 * (c1 * e1[i] + s1 * e2[i]);
      X[6 + i] = Q[i] + T(2) / T(3) * h3 * (c2 * e1[i] - s2 * e2[i]);
    }
  }

  // The shape error the formation checks judge (formation_checks.h) [m]:
  // how far the triangle's sides are from the desired ones (p, q and the
  // third side r: its shape variables, as the line's judge its rho, alpha,
  // beta). Q cannot tell a triangle from its mirror image (beta is
  // unsigned), and its orientation (phi, theta, psi) is a task of its own
  // that the PSO-family laws let lag by design (docs/formation.md): the
  // sides judge neither.
  AURORA_HD static T shapeError(const T X[9], const T Xd[9]) {
    using std::sqrt;
    using triangle_detail::distance;
    const T e[3] = {distance(X, X + 3) - distance(Xd, Xd + 3), distance(X, X + 6) - distance(Xd, Xd + 6),
                    distance(X + 3, X + 6) - distance(Xd + 3, Xd + 6)};
    return sqrt(e[0] * e[0] + e[1] * e[1] + e[2] * e[2]);
  }

  // Q~ = Qd - Q with the original's wraps (eq. T3): beta once into
  // [-pi, pi], phi and theta modulo pi into [-pi/2, pi/2], psi into
  // [-pi, pi]. A fixed number of passes (branch-free) equals the
  // original's while loops for errors below 3 pi in magnitude. An angle
  // whose row of the Jacobian is singular (its median's denominator is 0)
  // has no error (the spec's decision; eq. T4 zeroes its row).
  AURORA_HD static void error(const T X[9], const T Qd[9], const T Q[9], T e[9]) {
    using aurora_common::select;
    const T pi = T(aurora_common::kPi);
    for (int i = 0; i < 9; ++i) e[i] = Qd[i] - Q[i];
    e[5] = wrapOnce(e[5], pi, T(2) * pi);
    for (int pass = 0; pass < 3; ++pass) {
      for (int i = 6; i < 8; ++i) e[i] = wrapOnce(e[i], pi / T(2), pi);
      e[8] = wrapOnce(e[8], pi, T(2) * pi);
    }
    T m[3], w[3];
    triangle_detail::median(X, m);
    triangle_detail::orientationWeights(m, w);
    for (int i = 0; i < 3; ++i) e[6 + i] = select(w[i] == T(0), T(0), e[6 + i]);
  }

  // The robots' velocities dX for the formation velocity v (eq. T5): v's
  // position part moves all three alike; the shape and orientation parts
  // by their pseudo-inverses in the law's priority.
  AURORA_HD static void velocities(TriangleLaw law, const T X[9], const T v[9], T dX[9]) {
    const triangle_detail::TriangleJacobian<T> J(X);
    T a[9], b[9];
    if (law == TriangleLaw::kN) {
      J.jointPinv(v, dX);  // J+ v: every task at once
      return;
    }
    const bool orientation_first = law == TriangleLaw::kOSP;
    // The higher of shape and orientation by its own pseudo-inverse, the
    // lower projected into the higher's null space.
    if (orientation_first) {
      J.orientationPinv(v + 6, a);
      J.shapePinv(v + 3, b);
      J.removeOrientation(b);
    } else {
      J.shapePinv(v + 3, a);
      J.orientationPinv(v + 6, b);
      J.removeShape(b);
    }
    for (int i = 0; i < 9; ++i) dX[i] = v[i % 3] + a[i] + b[i];
  }

 private:
  // e minus `period` (signed) where |e| > `half`, once.
  AURORA_HD static T wrapOnce(const T& e, const T& half, const T& period) {
    using aurora_common::select;
    return select(e > half, e - period, select(e < -half, e + period, e));
  }
};

}  // namespace aurora_control
