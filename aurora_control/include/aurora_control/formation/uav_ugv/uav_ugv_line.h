// AuRoRA's UAV-UGV line formation (docs/formation.md, "The UAV-UGV line";
// its LineFormation3D, "the Pioneer is the reference"): robot 1 a ground
// robot, robot 2 a drone, Q = (xf, yf, zf, rho, alpha, beta) in the
// spherical convention, and its law without integration: every tick the
// robots' references are the desired formation's positions (the inverse of
// Qd) and the law's velocity dXr = Jinv(Q) (dQd + K1 tanh(K2 Q~)), its
// Jacobian taken at the measured Q. ROS-free, host and device.
#pragma once

#include <cmath>

#include "aurora_common/host_device.h"
#include "aurora_common/scalar_math.h"

namespace aurora_control {

template <typename T>
class UavUgvLayer;
template <typename T>
struct UavUgvTrajectory;

template <typename T>
struct UavUgvLine {
  using Law = int;  // one law (eq. L3)
  // Its own layer (formation_runner.h's LayerOf), not the integrating one.
  template <typename V>
  using Layer = UavUgvLayer<V>;
  static constexpr Law kDefaultLaw = 0;
  static constexpr int kDrones = 2;
  static constexpr int kVariables = 6;
  // Its own moving reference (formation_reference.h, FormationPath::kOwn):
  // the trajectory of eq. L4.
  template <typename V>
  AURORA_HD static void ownReference(const V& t, V Qd[kVariables]) {
    UavUgvTrajectory<V>::desired(t, Qd);
  }

  static const char* variableName(int i) {
    static const char* const names[kVariables] = {"xf", "yf", "zf", "rho", "alpha", "beta"};
    return names[i];
  }

  // AuRoRA's mInit: K1 = diag(0.8, 0.8, 0.5, 0.02, 0.015, 0.03),
  // K2 = diag(0.1, 0.1, 0.5, 0.5, 0.5, 0.5).
  AURORA_HD static void defaultGains(T k1[6], T k2[6]) {
    const T a[6] = {T(0.8), T(0.8), T(0.5), T(0.02), T(0.015), T(0.03)};
    const T b[6] = {T(0.1), T(0.1), T(0.5), T(0.5), T(0.5), T(0.5)};
    for (int i = 0; i < 6; ++i) k1[i] = a[i], k2[i] = b[i];
  }

  // Q of X = (p1, p2) (eq. L1): robot 1's position, the distance, the
  // line's azimuth atan2(dy, dx) and elevation atan2(dz, |(dx, dy)|).
  AURORA_HD static void variables(const T X[6], T Q[6]) {
    using std::atan2;
    using std::sqrt;
    const T d[3] = {X[3] - X[0], X[4] - X[1], X[5] - X[2]};
    for (int i = 0; i < 3; ++i) Q[i] = X[i];
    const T horizontal = sqrt(d[0] * d[0] + d[1] * d[1]);
    Q[3] = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    Q[4] = atan2(d[1], d[0]);
    Q[5] = atan2(d[2], horizontal);
  }

  // The formation's position: robot 1's, the reference (xf, yf, zf).
  AURORA_HD static void formationPosition(const T X[6], T c[3]) {
    for (int i = 0; i < 3; ++i) c[i] = X[i];
  }

  // p1 = (xf, yf, zf), p2 = p1 + rho (c_alpha c_beta, s_alpha c_beta, s_beta).
  AURORA_HD static void positions(const T Q[6], T X[6]) {
    T u[3];
    direction(Q, u);
    for (int i = 0; i < 3; ++i) X[i] = Q[i], X[3 + i] = Q[i] + Q[3] * u[i];
  }

  // Q~ = Qd - Q, alpha's and beta's wrapped once into [-pi, pi] (an `if`
  // in the original, not a loop).
  AURORA_HD static void error(const T[6], const T Qd[6], const T Q[6], T e[6]) {
    using aurora_common::select;
    const T pi = T(aurora_common::kPi);
    for (int i = 0; i < 6; ++i) e[i] = Qd[i] - Q[i];
    for (int i = 4; i < 6; ++i) e[i] = select(e[i] > pi, e[i] - T(2) * pi, select(e[i] < -pi, e[i] + T(2) * pi, e[i]));
  }

  // dX = Jinv(Q) dQr (eq. L2): both robots move with the position rate,
  // the drone also with B (the derivative of p2 by rho, alpha, beta) times
  // the shape rate, at the measured Q. Nothing is inverted: no singularity.
  AURORA_HD static void velocities(const T X[6], const T dQr[6], T dX[6]) {
    using aurora_common::sinCos;  // or a SIMD batch's own, by argument-dependent lookup
    T Q[6];
    variables(X, Q);
    T sa, ca, sb, cb;
    sinCos(Q[4], sa, ca);
    sinCos(Q[5], sb, cb);
    const T rho = Q[3];
    const T B[3][3] = {{ca * cb, -rho * sa * cb, -rho * ca * sb},
                       {sa * cb, rho * ca * cb, -rho * sa * sb},
                       {sb, T(0), rho * cb}};
    for (int i = 0; i < 3; ++i) {
      dX[i] = dQr[i];
      dX[3 + i] = dQr[i] + B[i][0] * dQr[3] + B[i][1] * dQr[4] + B[i][2] * dQr[5];
    }
  }

 private:
  AURORA_HD static void direction(const T Q[6], T u[3]) {
    using aurora_common::sinCos;  // or a SIMD batch's own, by argument-dependent lookup
    T sa, ca, sb, cb;
    sinCos(Q[4], sa, ca);
    sinCos(Q[5], sb, cb);
    u[0] = ca * cb, u[1] = sa * cb, u[2] = sb;
  }
};

// The layer of the UAV-UGV line (eq. L3): every tick, no integration and
// no hold. The references are the desired formation's positions, the
// velocities its law's dXr.
template <typename T>
class UavUgvLineLayer {
 public:
  using Shape = UavUgvLine<T>;
  AURORA_HD explicit UavUgvLineLayer(const T k1[6], const T k2[6]) {
    for (int i = 0; i < 6; ++i) k1_[i] = k1[i], k2_[i] = k2[i];
  }

  // One tick on the measured positions X towards Qd with the analytic rate dQd.
  AURORA_HD void update(const T X[6], const T Qd[6], const T dQd[6]) {
    using std::tanh;
    Shape::variables(X, Q_);
    Shape::error(X, Qd, Q_, Qtil_);
    T dQr[6];
    for (int i = 0; i < 6; ++i) dQr[i] = dQd[i] + k1_[i] * tanh(k2_[i] * Qtil_[i]);
    Shape::velocities(X, dQr, dXr_);
    Shape::positions(Qd, Xr_);
  }

  AURORA_HD const T* position(int robot) const { return Xr_ + 3 * robot; }
  AURORA_HD const T* velocity(int robot) const { return dXr_ + 3 * robot; }
  AURORA_HD const T* Q() const { return Q_; }
  AURORA_HD const T* Qtil() const { return Qtil_; }

 private:
  T k1_[6], k2_[6];
  T Q_[6] = {}, Qtil_[6] = {}, Xr_[6] = {}, dXr_[6] = {};
};

// AuRoRA's standard UAV-UGV trajectory (eq. L4): the ground robot on a 1:2
// figure-eight (a = 1.2 m, b = 1 m, w = 0.05 rad/s), the drone 2 m from it
// at azimuth pi/2 and elevation pi/3; the rate analytic. Qd and its rate
// apart: the run's reference needs one, the layer the other.
template <typename T>
struct UavUgvTrajectory {
  AURORA_HD static void desired(const T& t, T Qd[6]) {
    const T pi = T(aurora_common::kPi);
    T s1, c1, s2, c2;
    phases(t, s1, c1, s2, c2);
    const T q[6] = {a() * s1, b() * s2, T(0), T(2), pi / T(2), pi / T(3)};
    for (int i = 0; i < 6; ++i) Qd[i] = q[i];
  }
  AURORA_HD static void rate(const T& t, T dQd[6]) {
    T s1, c1, s2, c2;
    phases(t, s1, c1, s2, c2);
    const T dq[6] = {a() * w() * c1, T(2) * b() * w() * c2, T(0), T(0), T(0), T(0)};
    for (int i = 0; i < 6; ++i) dQd[i] = dq[i];
  }

 private:
  AURORA_HD static T a() { return T(1.2); }   // [m]
  AURORA_HD static T b() { return T(1); }     // [m]
  AURORA_HD static T w() { return T(0.05); }  // [rad/s]
  // sin and cos of w t and of 2 w t.
  AURORA_HD static void phases(const T& t, T& s1, T& c1, T& s2, T& c2) {
    using aurora_common::sinCos;  // or a SIMD batch's own, by argument-dependent lookup
    sinCos(w() * t, s1, c1);
    sinCos(T(2) * w() * t, s2, c2);
  }
};

// The layer as the one formation loop runs a shape's (formation_runner.h,
// LayerOf): every tick (its period the robots' step), towards the
// Qd the run's reference gives (eq. L4, ownReference), with that
// trajectory's analytic rate at the period's time t (the one trajectory a
// UAV-UGV line file flies).
template <typename T>
class UavUgvLayer {
 public:
  using Shape = UavUgvLine<T>;
  static constexpr int kN = 6;
  template <class Gains>
  AURORA_HD UavUgvLayer(int, const Gains& gains, const T&) : layer_(gains.k1, gains.k2) {}

  // Before the first tick: nothing held (the layer runs before every law).
  AURORA_HD void start(const T[6], const T[6]) {}
  AURORA_HD void update(const T X[6], const T Qd[6], const T& t) {
    T dQd[6];
    UavUgvTrajectory<T>::rate(t, dQd);
    layer_.update(X, Qd, dQd);
    for (int i = 0; i < 6; ++i) Qd_[i] = Qd[i];
  }
  AURORA_HD const T* position(int robot) const { return layer_.position(robot); }
  AURORA_HD const T* velocity(int robot) const { return layer_.velocity(robot); }
  AURORA_HD const T* Q() const { return layer_.Q(); }
  AURORA_HD const T* Qd() const { return Qd_; }
  AURORA_HD const T* Qtil() const { return layer_.Qtil(); }

 private:
  UavUgvLineLayer<T> layer_;
  T Qd_[6] = {};
};

}  // namespace aurora_control
