// Which parameters one simulation of a sweep uses, computed from its index
// alone (ROS-free, host and device): a CUDA thread, a SIMD lane and the
// scalar loop all decode the same index to the same combination, so no
// table of every combination is ever built.
#pragma once

#include "aurora_sim/host_device.h"

namespace aurora_sweep {

enum ParamId : int { kParamKp = 0, kParamKd = 1, kParamDelay = 2, kParamCount = 3 };

struct Combination {
  double kp;    // proportional gain
  double kd;    // derivative gain
  long delay;   // feedback delay [samples of Ts]
};

// A grid: up to three axes, axis 0 varies fastest (the order of the sweep
// file's `order`). Values of an axis are precomputed per axis on the host
// (from/to/count or an explicit list). Alternatively a list of points
// (n_points > 0): combination i is points[3 i .. 3 i + 2] = (kp, kd, delay).
struct GridView {
  int n_axes;
  int param[kParamCount];          // ParamId of each axis
  long count[kParamCount];         // values on each axis
  const double* values[kParamCount];
  double fixed[kParamCount];       // value of each parameter not on an axis
  const double* points;
  long n_points;

  AURORA_HD long size() const {
    if (n_points > 0) return n_points;
    long n = 1;
    for (int a = 0; a < n_axes; ++a) n *= count[a];
    return n;
  }

  AURORA_HD Combination decode(long index) const {
    double v[kParamCount] = {fixed[0], fixed[1], fixed[2]};
    if (n_points > 0) {
      for (int i = 0; i < kParamCount; ++i) v[i] = points[3 * index + i];
    } else {
      long rest = index;
      for (int a = 0; a < n_axes; ++a) {
        v[param[a]] = values[a][rest % count[a]];
        rest /= count[a];
      }
    }
    return Combination{v[kParamKp], v[kParamKd], static_cast<long>(v[kParamDelay])};
  }
};

}  // namespace aurora_sweep
