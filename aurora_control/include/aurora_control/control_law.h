// The two control laws behind one call (docs/controllers.md): the delay
// study's PD law with saturation (eq. 3.1) and the underactuated 12-gain law.
// Written once for every loop that runs a law on a (delayed) state: the
// controller node's core (DelayedController), the study runner, the sweep's
// SIMD engine and the CUDA kernel. Templated on the scalar (double, float,
// a SIMD batch), host and device.
#pragma once

#include <type_traits>

#include "aurora_control/pd_controller.h"
#include "aurora_control/trajectory_task.h"
#include "aurora_control/underactuated_law.h"
#include "aurora_sim/ardrone_params.h"
#include "aurora_sim/host_device.h"
#include "aurora_sim/state_index.h"

namespace aurora_control {

enum class LawType : int { kPdSaturated = 0, kUnderactuated = 1 };

// Calls f(std::integral_constant<LawType, law>()): a loop instantiated per
// law, chosen once at run time.
template <class F>
void withLaw(LawType law, F&& f) {
  if (law == LawType::kPdSaturated) return f(std::integral_constant<LawType, LawType::kPdSaturated>());
  return f(std::integral_constant<LawType, LawType::kUnderactuated>());
}

// The gains of both laws; a law reads only its own.
template <typename T>
struct LawGains {
  PdGains<T> pd;
  UnderactuatedGains<T> underactuated;
};

// Which components of the 12-state a law reads, in a fixed order: what a
// delay history must keep (the PD law: position and velocity, 6; the
// underactuated law: all 12). Keeping 6 halves the PD sweep's gathers.
template <LawType Law>
struct LawInput;

template <>
struct LawInput<LawType::kPdSaturated> {
  static constexpr int kWidth = 6;
  AURORA_HD static constexpr int state(int j) { return j < 3 ? aurora_sim::kX + j : aurora_sim::kVx + j - 3; }
};

template <>
struct LawInput<LawType::kUnderactuated> {
  static constexpr int kWidth = aurora_sim::kStateSize;
  AURORA_HD static constexpr int state(int j) { return j; }
};

// The part of a state a law reads (one delay-history entry).
template <typename T, LawType Law>
struct LawSample {
  static constexpr int kWidth = LawInput<Law>::kWidth;
  T v[kWidth];

  AURORA_HD static LawSample fromState(const T X[aurora_sim::kStateSize]) {
    LawSample s;
    for (int j = 0; j < kWidth; ++j) s.v[j] = X[LawInput<Law>::state(j)];
    return s;
  }
  // Back into a 12-state (components the law does not read are 0).
  AURORA_HD void toState(T X[aurora_sim::kStateSize]) const {
    for (int i = 0; i < aurora_sim::kStateSize; ++i) X[i] = T(0);
    for (int j = 0; j < kWidth; ++j) X[LawInput<Law>::state(j)] = v[j];
  }
};

// The underactuated law's desired state and feed-forward from a reference:
// position, velocity, yaw and yaw rate; accelerations and yaw acceleration.
template <typename T>
AURORA_HD inline void underactuatedDesired(const Reference<T>& ref, T Xd[aurora_sim::kStateSize], T acc[6]) {
  for (int i = 0; i < aurora_sim::kStateSize; ++i) Xd[i] = T(0);
  for (int i = 0; i < 3; ++i) {
    Xd[aurora_sim::kX + i] = ref.pos[i];
    Xd[aurora_sim::kVx + i] = ref.vel[i];
    acc[i] = ref.acc[i];
  }
  Xd[aurora_sim::kYaw] = ref.yaw;
  Xd[aurora_sim::kYawRate] = ref.yaw_rate;
  acc[3] = acc[4] = T(0);
  acc[5] = ref.yaw_acc;
}

// One call of law `Law` on the state X the controller received: the command
// U (not clamped) and the position error the metrics use (ref - X). `model`
// is the vehicle the underactuated law inverts (nominal; the simulated drone
// may differ in a robustness study); `memory` is that law's own state.
template <LawType Law, typename T>
AURORA_HD inline void lawCommand(const aurora_sim::ArdroneParams<T>& model, const LawGains<T>& g,
                                 UnderactuatedMemory<T>& memory, const Reference<T>& ref,
                                 const T X[aurora_sim::kStateSize], T U[4], T pos_err[3]) {
  const T pos[3] = {X[aurora_sim::kX], X[aurora_sim::kY], X[aurora_sim::kZ]};
  if (Law == LawType::kPdSaturated) {
    const T vel[3] = {X[aurora_sim::kVx], X[aurora_sim::kVy], X[aurora_sim::kVz]};
    pdSaturatedLaw(g.pd, ref.pos, ref.vel, ref.acc, pos, vel, U, pos_err);
  } else {
    T Xd[aurora_sim::kStateSize], acc[6];
    underactuatedDesired(ref, Xd, acc);
    underactuatedCommand(model, g.underactuated, memory, Xd, acc, X, U);
    for (int i = 0; i < 3; ++i) pos_err[i] = ref.pos[i] - pos[i];
  }
}

}  // namespace aurora_control
