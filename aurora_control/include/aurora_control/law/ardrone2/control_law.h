// The two control laws behind one call (docs/controllers.md): the delay
// study's PD law with saturation (eq. 3.1) and the underactuated 12-gain law.
// Written once for every loop that runs a law on a (delayed) state: the
// controller node's core (DelayedController), the study runner, the sweep's
// SIMD engine and the CUDA kernel. Templated on the scalar (double, float,
// a SIMD batch), host and device.
#pragma once

#include <string>

#include <type_traits>

#include "aurora_control/law/ardrone2/pd_controller.h"
#include "aurora_control/task/trajectory_task.h"
#include "aurora_control/law/ardrone2/underactuated_law.h"
#include "aurora_sim/vehicle/ardrone2/ardrone_params.h"
#include "aurora_common/host_device.h"
#include "aurora_sim/state_index.h"
#include "aurora_sim/vehicle/ardrone2/ardrone2.h"

namespace aurora_control {

enum class LawType : int { kPdSaturated = 0, kUnderactuated = 1 };

// A law's name in controller files, sweep files and messages, and the law
// of a name (false for a name no law has). Host only.
inline const char* lawName(LawType law) {
  return law == LawType::kUnderactuated ? "underactuated" : "pd_saturated";
}
inline bool lawFromName(const std::string& name, LawType& law) {
  if (name == "pd_saturated") law = LawType::kPdSaturated;
  else if (name == "underactuated") law = LawType::kUnderactuated;
  else return false;
  return true;
}

// The gains of both laws; a law reads only its own.
template <typename T>
struct LawGains {
  PdGains<T> pd;
  UnderactuatedGains<T> underactuated;

  // Before a sweep's blocks (aurora_sweep/sweep_gains.h): the PD gains 0
  // (a sweep of the PD law names both), the underactuated law's defaults.
  AURORA_HD static LawGains defaults() { return LawGains{PdGains<T>{T(0), T(0)}, UnderactuatedGains<T>::defaults()}; }
};

// Each AR.Drone law's own part of the gains, by its gain rows' type.
template <typename T>
AURORA_HD PdGains<T>& gainsOf(LawGains<T>& g, const PdGainRows*) {
  return g.pd;
}
template <typename T>
AURORA_HD UnderactuatedGains<T>& gainsOf(LawGains<T>& g, const UnderactuatedGainRows*) {
  return g.underactuated;
}

// The gains in precision T (a formation sweep casts each robot's; every
// law's data gives its castGains, found by argument-dependent lookup).
template <typename T, typename U>
void castGains(const LawGains<U>& from, LawGains<T>& to) {
  to.pd.kp = T(from.pd.kp), to.pd.kd = T(from.pd.kd);
  for (int i = 0; i < kAxes; ++i) {
    to.underactuated.k1[i] = T(from.underactuated.k1[i]);
    to.underactuated.k2[i] = T(from.underactuated.k2[i]);
  }
}

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

// What the AR.Drone's two laws share (a law's Data): the vehicle they fly,
// the gains of both (each reads its own) and the underactuated law's memory.
// Loop parameters and states are typed by a law's Data, so that a loop that
// picks its law at run time keeps one type of state.
struct ArdroneLawData {
  using Data = ArdroneLawData;
  // The CUDA backend builds predicting kernels for these laws
  // (cuda_backend.cu, GpuPredicts): the thesis's predictor studies.
  static constexpr bool kGpuPredictor = true;
  using Vehicle = aurora_sim::Ardrone2;
  template <typename T>
  using Gains = LawGains<T>;
  template <typename T>
  using Memory = UnderactuatedMemory<T>;
};

// The vehicle the laws of the node, replay, flight and formations fly
// (both AR.Drone laws share their data, so a law chosen at run time by
// withLaw flies it): the one place those entry points choose a vehicle.
using LawVehicle = ArdroneLawData::Vehicle;
using LawVehicleParams = LawVehicle::Params<double>;

// A law as a type (docs/architecture.md, "Laws"), what every generic loop
// is instantiated on: its Data (the vehicle it flies, its gains and its own
// memory: structs of T only), what of the state it reads (Input), and one
// call on the state it received: the command U (Vehicle::kInputs, not
// clamped) and the position error ref - X the metrics use. `value` names the
// AR.Drone's two laws for the code that picks one at run time (withLaw).
template <LawType L>
struct ArdroneLaw : ArdroneLawData {
  using Data = ArdroneLawData;
  static constexpr LawType value = L;
  using Input = LawInput<L>;
  static const char* name() { return lawName(L); }

  // The gains a sweep may vary (law_gain_rows.h): its own of the two laws'
  // gains (PdGainRows, UnderactuatedGainRows beside each law).
  using GainRows = typename std::conditional<L == LawType::kPdSaturated, PdGainRows, UnderactuatedGainRows>::type;
  static constexpr int kGainCount = GainRows::kGainCount;
  static GainRow gainRow(int i) { return GainRows::gainRow(i); }
  template <typename T>
  AURORA_HD static void giveGains(LawGains<T>& g, const double* v) {
    GainRows::giveGains(gainsOf(g, static_cast<const GainRows*>(nullptr)), v);
  }
  // Every gain of the law is one of its rows (law_gain_rows.h, gainAt):
  // row i's gain in g.
  static double& gainAt(LawGains<double>& g, int i) {
    return GainRows::gainAt(gainsOf(g, static_cast<const GainRows*>(nullptr)), i);
  }

  template <typename T>
  AURORA_HD static void command(const aurora_sim::ArdroneParams<T>& model, const Gains<T>& g, Memory<T>& memory,
                                const Reference<T>& ref, const T X[Vehicle::kStates], T U[Vehicle::kInputs],
                                T pos_err[3]) {
    lawCommand<L>(model, g, memory, ref, X, U, pos_err);
  }
};

template <LawType L>
constexpr LawType ArdroneLaw<L>::value;
template <LawType L>
constexpr int ArdroneLaw<L>::kGainCount;

// Calls f(ArdroneLaw<law>()): a loop instantiated per law, chosen once at
// run time (decltype(f's argument) is the law's type, ::value its LawType).
template <class F>
void withLaw(LawType law, F&& f) {
  if (law == LawType::kPdSaturated) return f(ArdroneLaw<LawType::kPdSaturated>());
  return f(ArdroneLaw<LawType::kUnderactuated>());
}

}  // namespace aurora_control
