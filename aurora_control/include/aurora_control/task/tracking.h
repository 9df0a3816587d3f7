// The steps of a task and the tracking error of a step, written once for
// the node, replay, the flight tool (and, in Python, report):
// docs/controllers.md, "Steps of a task and its tracking error".
#pragma once

#include <cmath>

#include "aurora_control/task/task.h"
#include "aurora_sim/state_index.h"

namespace aurora_control {

// The steps 0..N of a task, N = round(duration / Ts): N + 1 of them
// (docs/controllers.md, "Steps of a task and its tracking error").
inline long taskStepCount(double duration, double Ts) { return std::lround(duration / Ts) + 1; }

// The tracking error of a step: the reference and the state of the same
// time, |p_d(t_k) - p(x_k)| (docs/controllers.md, same section).
inline double trackingError(const Reference<double>& ref, const double X[aurora_sim::kStateSize]) {
  double e2 = 0.0;
  for (int i = 0; i < 3; ++i) {
    const double e = ref.pos[i] - X[aurora_sim::kX + i];
    e2 += e * e;
  }
  return std::sqrt(e2);
}

}  // namespace aurora_control
