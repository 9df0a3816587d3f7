// The formation's checks (formation_checks.h) as an observer of the offline
// formation runner: what the flight tool prints and every sweep backend's
// scalar run records. ROS-free, host and device.
#pragma once

#include "aurora_control/formation/formation_checks.h"
#include "aurora_control/formation/formation_runner.h"

namespace aurora_control {

// The formation's checks as the runner's observer: tick k's positions X_k
// against the positions of the layer's held Qd (computed when the layer
// runs); false (stop) at the first failed check with early_stop.
template <typename T, class Shape, class Data>
struct FormationJudge {
  static constexpr int kN = Shape::kVariables;
  FormationCriteria<T> criteria;
  bool early_stop;
  T Ts;
  FormationMetrics<T, bool, Shape> metrics;
  T Xd[kN];

  AURORA_HD bool operator()(const FormationObservation<T, Shape, Data>& o) {
    T X[kN];
    dronePositions<Shape, typename Data::Vehicle>(o.X_before, X);
    if (o.layer_ran) Shape::positions(o.layer.Qd(), Xd);
    metrics.add(criteria, X, Xd, taskTime(T(o.k), Ts), Ts);
    metrics.template addCommands<typename Data::Vehicle>(criteria, o.params, o.steps);
    return !(early_stop && !metrics.feasible());
  }
};

}  // namespace aurora_control
