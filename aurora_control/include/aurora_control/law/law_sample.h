// The part of a state a law reads, one delay-history entry (docs/
// architecture.md, "Laws"): a law's Input names kWidth components of its
// vehicle's state, in a fixed order, so that a history keeps only those (the
// AR.Drone's PD law: position and velocity, 6 of 12; its gathers halve).
// Generic in the law; host and device.
#pragma once

#include "aurora_common/host_device.h"

namespace aurora_control {

template <typename T, class Law>
struct LawSample {
  static constexpr int kStates = Law::Vehicle::kStates;
  static constexpr int kWidth = Law::Input::kWidth;
  T v[kWidth];

  AURORA_HD static LawSample fromState(const T X[kStates]) {
    LawSample s;
    for (int j = 0; j < kWidth; ++j) s.v[j] = X[Law::Input::state(j)];
    return s;
  }
  // Back into a whole state (components the law does not read are 0).
  AURORA_HD void toState(T X[kStates]) const {
    for (int i = 0; i < kStates; ++i) X[i] = T(0);
    for (int j = 0; j < kWidth; ++j) X[Law::Input::state(j)] = v[j];
  }
};

}  // namespace aurora_control
