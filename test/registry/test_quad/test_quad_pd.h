// The test-only vehicle's law (test_quad.h): each axis's speed command is
// the reference's speed plus k_position times its error, as a fraction of
// the vehicle's top speed (the heading's error wrapped once). Every gain is
// one of its rows, so its controller file is read by them and the
// controller node shows and changes them live. Declared here only; it joins
// the laws' list of a test build of the nodes (extra_laws.h).
#pragma once

#include "aurora_common/scalar_math.h"
#include "aurora_control/law/law_gain_rows.h"
#include "aurora_control/law/law_of.h"
#include "aurora_control/task/task.h"
#include "test_quad.h"

namespace registry {

template <typename T>
struct TestQuadPdGains {
  T k_position;  // [1/s] on x, y, z
  T k_heading;   // [1/s] on yaw
  AURORA_HD static TestQuadPdGains defaults() { return {T(1.5), T(1.0)}; }
};

template <typename T, typename U>
AURORA_HD void castGains(const TestQuadPdGains<U>& from, TestQuadPdGains<T>& to) {
  to.k_position = T(from.k_position), to.k_heading = T(from.k_heading);
}

template <typename T>
struct NoMemory {
  AURORA_HD void reset() {}
};

struct TestQuadPd : aurora_control::LawOf<TestQuadPd, TestQuad, TestQuadPdGains, NoMemory> {
  struct Input {  // it reads x, y, z, yaw
    static constexpr int kWidth = 4;
    AURORA_HD static constexpr int state(int j) { return j < 3 ? aurora_sim::kX + j : aurora_sim::kYaw; }
  };
  static const char* name() { return "test_quad_pd"; }

  static constexpr int kGainCount = 2;
  static aurora_control::GainRow gainRow(int i) {
    const auto d = TestQuadPdGains<double>::defaults();
    return {i == 0 ? "k_position" : "k_heading", i == 0 ? d.k_position : d.k_heading, 0.0, 20.0, false};
  }
  template <typename T>
  AURORA_HD static void giveGains(Gains<T>& g, const double* v) {
    aurora_control::giveGain(g.k_position, v[0]);
    aurora_control::giveGain(g.k_heading, v[1]);
  }
  static double& gainAt(Gains<double>& g, int i) { return i == 0 ? g.k_position : g.k_heading; }

  template <typename T>
  AURORA_HD static void command(const TestQuadParams<T>& model, const Gains<T>& g, Memory<T>&,
                                const aurora_control::Reference<T>& ref, const T X[TestQuad::kStates],
                                T U[TestQuad::kInputs], T pos_err[3]) {
    for (int i = 0; i < 3; ++i) {
      pos_err[i] = ref.pos[i] - X[aurora_sim::kX + i];
      U[i] = (ref.vel[i] + g.k_position * pos_err[i]) / model.speed;
    }
    const T yaw_err = aurora_common::wrapAngleOnce(ref.yaw - X[aurora_sim::kYaw]);
    U[kAxisYaw] = (ref.yaw_rate + g.k_heading * yaw_err) / model.yaw_rate;
  }
};

}  // namespace registry
