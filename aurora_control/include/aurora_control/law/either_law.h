// Two laws as one law type (docs/architecture.md, "Mixed crews"): a robot
// flies law First (its vehicle) or law Second (its vehicle), as its
// parameters choose (aurora_sim/vehicle/either_vehicle.h). A formation of
// robots of different vehicles, each with its own law, is a formation of
// EitherLaw robots: the runner, the SIMD engine and the kernel fly it with
// no change. Nest it for a third kind of robot.
#pragma once

#include "aurora_control/task/task.h"
#include "aurora_common/host_device.h"
#include "aurora_sim/vehicle/either_vehicle.h"

namespace aurora_control {

// Both laws' gains and memories; a robot's law reads its own.
template <typename T, class First, class Second>
struct EitherGains {
  typename First::template Gains<T> first;
  typename Second::template Gains<T> second;
};

template <typename T, class First, class Second>
struct EitherMemory {
  typename First::template Memory<T> first;
  typename Second::template Memory<T> second;
  AURORA_HD void reset() {
    first.reset();
    second.reset();
  }
};

// Both laws' gains in precision T (each law's castGains).
template <typename T, typename U, class First, class Second>
void castGains(const EitherGains<U, First, Second>& from, EitherGains<T, First, Second>& to) {
  castGains(from.first, to.first);
  castGains(from.second, to.second);
}

template <class First, class Second>
struct EitherLaw {
  using Vehicle = aurora_sim::EitherVehicle<typename First::Vehicle, typename Second::Vehicle>;
  using Data = EitherLaw;
  // No predictor (docs/predictor.md) for a mixed crew: no shape's reader
  // gives one (uav_ugv_yaml.h), and the sweeps build no predicted code for
  // it (formation_simulation.h, withFormationPredictor).
  static constexpr bool kPredicts = false;
  template <typename T>
  using Gains = EitherGains<T, typename First::Data, typename Second::Data>;
  template <typename T>
  using Memory = EitherMemory<T, typename First::Data, typename Second::Data>;
  // The whole state: the two laws read different components.
  struct Input {
    static constexpr int kWidth = Vehicle::kStates;
    AURORA_HD static constexpr int state(int j) { return j; }
  };

  // The chosen law on X (its vehicle's state in X's first entries); the
  // commands a smaller vehicle has not are 0.
  template <typename T>
  AURORA_HD static void command(const typename Vehicle::template Params<T>& model, const Gains<T>& g, Memory<T>& m,
                                const Reference<T>& ref, const T X[Vehicle::kStates], T U[Vehicle::kInputs],
                                T pos_err[3]) {
    for (int i = 0; i < Vehicle::kInputs; ++i) U[i] = T(0);
    if (model.is_second) Second::command(model.second, g.second, m.second, ref, X, U, pos_err);
    else First::command(model.first, g.first, m.first, ref, X, U, pos_err);
  }
};

}  // namespace aurora_control
