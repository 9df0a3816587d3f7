// The line formation of two drones (docs/formation.md, "The line
// formation"): formation variables Q = (xF, yF, zF, rho, alpha, beta) of the
// drones' positions X = (p1, p2), the inverse transform, and the three laws'
// velocities in closed form. A shape is a struct of static functions with
// kDrones and kVariables; the formation layer (formation_layer.h) is
// written against that interface, so another shape (AuRoRA's triangle of
// three drones) is a file like this one. ROS-free, host and device.
#pragma once

#include <cmath>

#include "aurora_common/host_device.h"

namespace aurora_control {

// The formation laws (docs/formation.md, "Formation laws"): v is the
// reference velocity in formation space, v_p its position part (3), v_s its
// shape part.
enum class FormationLaw : int {
  kInverseKinematics = 0,  // J^-1 v: both drones follow v_p, drone 2 also the shape
  kPositionPriority = 1,   // null space, position first (the lab's script): drone 2 only corrects the shape, at half gain
  kShapePriority = 2,      // null space, shape first: the drones share the shape correction
};

template <typename T>
struct LineFormation {
  using Law = FormationLaw;
  static constexpr Law kDefaultLaw = FormationLaw::kPositionPriority;  // the lab's script
  static constexpr int kDrones = 2;
  static constexpr int kVariables = 6;
  // The line is singular where the drones are level (eq. F4 divides by
  // sigma = (z2 - z1) / rho; at rho = 0 beta is undefined too): a formation
  // may not start closer than this to level [m] (docs/formation.md,
  // "Formation files").
  static constexpr double kMinStartHeightGap = 0.05;

  // Variable i's name: in the flight tool's columns (Q_xF, Qd_rho, ...) and
  // in a sweep's gain names (formation_k1_x, ..., formation_k2_beta). Host only.
  static const char* variableName(int i) {
    static const char* const names[kVariables] = {"xF", "yF", "zF", "rho", "alpha", "beta"};
    return names[i];
  }
  static const char* gainName(int i) {
    static const char* const names[kVariables] = {"x", "y", "z", "rho", "alpha", "beta"};
    return names[i];
  }

  // K1 (amplitudes) and K2 (slopes) of the layer's law by default:
  // AuRoRA's (its mInit, and the lab's script).
  AURORA_HD static void defaultGains(T k1[6], T k2[6]) {
    const T a[6] = {T(0.1), T(0.1), T(1.0), T(0.75), T(0.5), T(0.5)};
    const T b[6] = {T(0.5), T(0.5), T(0.5), T(0.5), T(0.25), T(0.25)};
    for (int i = 0; i < 6; ++i) k1[i] = a[i], k2[i] = b[i];
  }

  // Q of positions X = (x1, y1, z1, x2, y2, z2) (eq. F1): the formation's
  // position is drone 1's, rho the distance to drone 2, alpha = asin(dx /
  // rho), beta = asin(dy / rho).
  AURORA_HD static void variables(const T X[6], T Q[6]) {
    using std::asin;
    using std::sqrt;
    const T d[3] = {X[3] - X[0], X[4] - X[1], X[5] - X[2]};
    const T rho = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    for (int i = 0; i < 3; ++i) Q[i] = X[i];
    Q[3] = rho;
    Q[4] = asin(d[0] / rho);
    Q[5] = asin(d[1] / rho);
  }

  // The error Q~ = Qd - Q: no angle wraps (the line's angles stay within
  // [-pi/2, pi/2]).
  AURORA_HD static void error(const T[6], const T Qd[6], const T Q[6], T e[6]) {
    for (int i = 0; i < 6; ++i) e[i] = Qd[i] - Q[i];
  }

  // The formation's position of positions X: drone 1's.
  AURORA_HD static void formationPosition(const T X[6], T p[3]) {
    for (int i = 0; i < 3; ++i) p[i] = X[i];
  }

  // The positions of Q (eq. F2), drone 2 above drone 1: the inverse
  // transform cannot tell above from below. Needs sin^2 alpha + sin^2 beta <= 1.
  AURORA_HD static void positions(const T Q[6], T X[6]) {
    using std::sin;
    using std::sqrt;
    const T sa = sin(Q[4]), sb = sin(Q[5]);
    for (int i = 0; i < 3; ++i) X[i] = Q[i];
    X[3] = Q[0] + Q[3] * sa;
    X[4] = Q[1] + Q[3] * sb;
    X[5] = Q[2] + Q[3] * sqrt(T(1) - sa * sa - sb * sb);
  }

  // The drones' velocities dX (6) for formation velocity v at positions X,
  // by law (eq. F5-F7): with A^-1 = d p2 / d(rho, alpha, beta) at X,
  //   inverse kinematics:  dX1 = v_p,              dX2 = v_p + A^-1 v_s
  //   position priority:   dX1 = v_p,              dX2 = A^-1 v_s / 2
  //   shape priority:      dX1 = (v_p - A^-1 v_s)/2, dX2 = (v_p + A^-1 v_s)/2
  AURORA_HD static void velocities(FormationLaw law, const T X[6], const T v[6], T dX[6]) {
    T shape[3];
    shapeVelocity(X, v + 3, shape);
    for (int i = 0; i < 3; ++i) {
      if (law == FormationLaw::kInverseKinematics) {
        dX[i] = v[i], dX[3 + i] = v[i] + shape[i];
      } else if (law == FormationLaw::kPositionPriority) {
        dX[i] = v[i], dX[3 + i] = shape[i] / T(2);
      } else {
        dX[i] = (v[i] - shape[i]) / T(2), dX[3 + i] = (v[i] + shape[i]) / T(2);
      }
    }
  }

  // A^-1 vs (eq. F4): the velocity of drone 2 relative to drone 1 that
  // changes (rho, alpha, beta) at the rates vs, with sigma = dz / rho signed
  // (drone 2 below drone 1 as well).
  AURORA_HD static void shapeVelocity(const T X[6], const T vs[3], T out[3]) {
    using std::sqrt;
    const T d[3] = {X[3] - X[0], X[4] - X[1], X[5] - X[2]};
    const T rho = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    const T sa = d[0] / rho, sb = d[1] / rho, sigma = d[2] / rho;
    const T ca = sqrt(d[1] * d[1] + d[2] * d[2]) / rho, cb = sqrt(d[0] * d[0] + d[2] * d[2]) / rho;
    out[0] = sa * vs[0] + rho * ca * vs[1];
    out[1] = sb * vs[0] + rho * cb * vs[2];
    out[2] = sigma * vs[0] - rho * sa * ca / sigma * vs[1] - rho * sb * cb / sigma * vs[2];
  }
};

}  // namespace aurora_control
