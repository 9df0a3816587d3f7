// A test-only vehicle and law (issue 32, "proof that the seams hold"): a
// point mass pushed by a force in x, y, z (6 states, 3 inputs) and a PD law
// on it. Defined here only, they fly through every backend's generic code:
// the offline runner, the sweep's scalar loop, its SIMD engine and the CUDA
// kernel's per-thread entry.
#pragma once

#include "aurora_control/loop/closed_loop.h"
#include "aurora_common/host_device.h"
#include "aurora_common/scalar_math.h"
#include "aurora_sweep/robot_gains.h"
#include "aurora_sweep/simulation.h"

namespace point_mass {

template <typename T>
struct Params {
  T Ts;  // [s]
  T m;   // [kg]
  template <typename U>
  AURORA_HD Params<U> cast() const {
    return Params<U>{U(Ts), U(m)};
  }
};

template <typename T>
struct State {
  T X[6];  // x y z [m], vx vy vz [m/s], world frame
  AURORA_HD void reset() {
    for (int i = 0; i < 6; ++i) X[i] = T(0);
  }
};

struct PointMass {
  template <typename T>
  using Params = point_mass::Params<T>;
  template <typename T>
  using State = point_mass::State<T>;
  static constexpr int kStates = 6, kInputs = 3, kPosition = 0, kFactors = 1;
  static constexpr bool kOnGround = false;
  static const char* name() { return "point_mass"; }
  static const char* stateName(int i) {
    static const char* const names[kStates] = {"x", "y", "z", "dx", "dy", "dz"};
    return names[i];
  }
  template <typename T>
  AURORA_HD static void start(const Params<T>&, State<T>& s) {
    s.reset();
  }

  // Semi-implicit Euler: v += F / m Ts, then x += v Ts.
  template <typename T>
  AURORA_HD static void step(const Params<T>& p, State<T>& s, const T U[kInputs]) {
    for (int i = 0; i < 3; ++i) s.X[3 + i] = s.X[3 + i] + U[i] / p.m * p.Ts;
    for (int i = 0; i < 3; ++i) s.X[i] = s.X[i] + s.X[3 + i] * p.Ts;
  }
  template <typename T>
  AURORA_HD static T limitInput(const Params<T>&, int, const T& u) {
    return aurora_common::clampUnit(u);  // [N]
  }
  AURORA_HD static Params<double> scaled(Params<double> p, const double* factor) {
    p.m *= factor[0];
    return p;
  }
};

template <typename T>
struct Gains {
  T kp, kd;  // [1/s^2], [1/s]
};

// Its gains in another precision (a formation sweep casts each robot's;
// found by argument-dependent lookup).
template <typename T, typename U>
void castGains(const Gains<U>& from, Gains<T>& to) {
  to.kp = T(from.kp), to.kd = T(from.kd);
}

template <typename T>
struct Memory {
  AURORA_HD void reset() {}
};

// F = m (kp e + kd (v_ref - v)): a PD on the position the law received.
struct PointPd {
  using Vehicle = PointMass;
  using Data = PointPd;
  template <typename T>
  using Gains = point_mass::Gains<T>;
  template <typename T>
  using Memory = point_mass::Memory<T>;
  struct Input {
    static constexpr int kWidth = 6;
    AURORA_HD static constexpr int state(int j) { return j; }
  };
  static const char* name() { return "point_pd"; }
  // Its gains a sweep varies (law_gain_rows.h): kp, kd.
  static constexpr int kGainCount = 2;
  static aurora_control::GainRow gainRow(int i) { return {i == 0 ? "kp" : "kd", 0.0, 0.0, 100.0, false}; }
  template <typename T>
  AURORA_HD static void giveGains(Gains<T>& g, const double* v) {
    aurora_control::giveGain(g.kp, v[0]);
    aurora_control::giveGain(g.kd, v[1]);
  }

  template <typename T>
  AURORA_HD static void command(const Params<T>& model, const Gains<T>& g, Memory<T>&,
                                const aurora_control::Reference<T>& ref, const T X[6], T U[3], T err[3]) {
    for (int i = 0; i < 3; ++i) {
      err[i] = ref.pos[i] - X[i];
      U[i] = model.m * (g.kp * err[i] + g.kd * (ref.vel[i] - X[3 + i]));
    }
  }
};

}  // namespace point_mass

namespace aurora_sweep {

// The point mass's law reads the sweep's kp and kd.
template <>
struct SweepGains<point_mass::PointPd> {
  template <typename T>
  AURORA_HD static point_mass::Gains<T> from(const Combination& c) {
    return point_mass::Gains<T>{T(c.v[kParamKp]), T(c.v[kParamKd])};
  }
};

// As a formation robot it takes the generic RobotGains (robot_gains.h):
// its declaration's kp, kd.

}  // namespace aurora_sweep
