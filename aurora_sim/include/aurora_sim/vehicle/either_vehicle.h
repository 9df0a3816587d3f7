// Two vehicles as one vehicle type (docs/architecture.md, "Mixed crews"):
// the type of a robot that is a First or a Second, which one being its
// parameters' choice. A formation whose robots differ (a ground robot with
// a drone) is a formation of EitherVehicle robots, so the generic loop,
// the SIMD engine and the kernel fly it unchanged; nest it for a third
// kind. Every lane of a SIMD batch and every thread of a launch flies the
// same robots, so the choice is a plain bool, one branch per call, the
// same on all lanes and threads.
#pragma once

#include "aurora_common/host_device.h"

namespace aurora_sim {

// The parameters of a robot that is a First or a Second (vehicle types),
// with the chosen one's sample time as `Ts` (what every loop reads).
template <typename T, class First, class Second>
struct EitherParams {
  bool is_second;
  typename First::template Params<T> first;
  typename Second::template Params<T> second;
  T Ts;  // [s] the chosen vehicle's

  AURORA_HD static EitherParams ofFirst(const typename First::template Params<T>& p) {
    EitherParams e{};
    e.is_second = false, e.first = p, e.Ts = p.Ts;
    return e;
  }
  AURORA_HD static EitherParams ofSecond(const typename Second::template Params<T>& p) {
    EitherParams e{};
    e.is_second = true, e.second = p, e.Ts = p.Ts;
    return e;
  }
  template <typename U>
  AURORA_HD EitherParams<U, First, Second> cast() const {
    EitherParams<U, First, Second> e;
    e.is_second = is_second;
    e.first = first.template cast<U>();
    e.second = second.template cast<U>();
    e.Ts = U(Ts);
    return e;
  }
};

template <int A, int B>
struct Larger {
  static constexpr int value = A > B ? A : B;
};

// The state: X, the chosen vehicle's state in its first entries (the rest
// 0), is what every loop reads and writes; each vehicle's own state keeps
// what its step carries beyond X (the AR.Drone's on-board channels).
template <typename T, class First, class Second>
struct EitherState {
  static constexpr int kStates = Larger<First::kStates, Second::kStates>::value;
  T X[kStates];
  typename First::template State<T> first;
  typename Second::template State<T> second;

  // Both at rest; X as First's reset gives it (a formation then puts every
  // robot at its own start: formation_runner.h, startFormation).
  AURORA_HD void reset() {
    first.reset();
    second.reset();
    for (int i = 0; i < kStates; ++i) X[i] = i < First::kStates ? first.X[i] : T(0);
  }
};

template <class First, class Second>
struct EitherVehicle {
  static_assert(First::kPosition == Second::kPosition, "x y z sit at the same place in both vehicles' states");
  template <typename T>
  using Params = EitherParams<T, First, Second>;
  template <typename T>
  using State = EitherState<T, First, Second>;
  static constexpr int kStates = Larger<First::kStates, Second::kStates>::value;
  static constexpr int kInputs = Larger<First::kInputs, Second::kInputs>::value;
  static constexpr int kPosition = First::kPosition;

  // The chosen vehicle's step on X (read into its own state and back; a
  // smaller vehicle's commands are U's first entries).
  template <typename T>
  AURORA_HD static void step(const Params<T>& p, State<T>& s, const T U[kInputs]) {
    if (p.is_second) stepOne<Second>(p.second, s.second, s.X, U);
    else stepOne<First>(p.first, s.first, s.X, U);
  }

  // Both started; X as the chosen one's start gives it.
  template <typename T>
  AURORA_HD static void start(const Params<T>& p, State<T>& s) {
    s.reset();
    First::start(p.first, s.first);
    Second::start(p.second, s.second);
    if (p.is_second) copyX<Second>(s.second, s.X);
    else copyX<First>(s.first, s.X);
  }

  template <typename T>
  AURORA_HD static T limitInput(const Params<T>& p, int i, const T& u) {
    if (p.is_second) return i < Second::kInputs ? Second::limitInput(p.second, i, u) : T(0);
    return i < First::kInputs ? First::limitInput(p.first, i, u) : T(0);
  }

 private:
  template <class One, class OwnState, typename T>
  AURORA_HD static void copyX(const OwnState& own, T X[kStates]) {
    for (int i = 0; i < kStates; ++i) X[i] = i < One::kStates ? own.X[i] : T(0);
  }

  template <class One, typename T, class OwnState>
  AURORA_HD static void stepOne(const typename One::template Params<T>& p, OwnState& own, T X[kStates],
                                const T U[kInputs]) {
    for (int i = 0; i < One::kStates; ++i) own.X[i] = X[i];
    One::step(p, own, U);
    for (int i = 0; i < One::kStates; ++i) X[i] = own.X[i];
  }
};

}  // namespace aurora_sim
