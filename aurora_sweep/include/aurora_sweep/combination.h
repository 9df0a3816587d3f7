// Which parameters one simulation of a sweep uses, computed from its index
// alone (ROS-free, host and device): a CUDA thread, a SIMD lane and the
// scalar loop all decode the same index to the same combination, so no
// table of every combination is ever built.
#pragma once

#include "aurora_sim/host_device.h"

namespace aurora_sweep {

// Every parameter a sweep can vary (names and accepted ranges: parameters.h).
// The PD law's gains, the delay, the underactuated law's 12 gains in the
// order of underactuatedGainName (k1_x, k2_x, ..., k2_psi), and factors of
// the simulated drone's model parameters (1 = the vehicle file's value).
enum ParamId : int {
  kParamKp = 0,
  kParamKd = 1,
  kParamDelay = 2,
  kParamFirstUnderactuatedGain = 3,  // 12 of them
  kParamFirstModelFactor = 15,       // m, Ixx, Iyy, Izz, Cf, Ct, Km, Jm
  kParamCount = 23
};
constexpr int kUnderactuatedGainCount = 12;
constexpr int kModelFactorCount = 8;

struct Combination {
  double v[kParamCount];  // every parameter's value, ParamId order
  AURORA_HD long delay() const { return static_cast<long>(v[kParamDelay]); }
};

// A grid: axes, axis 0 varies fastest (the order of the sweep file's
// `order`). Values of an axis are precomputed per axis on the host
// (from/to/count or an explicit list). Alternatively a list of points
// (n_points > 0, from a CSV file or a sampling design): row i holds the
// values of the `point_cols` parameters point_param[0..point_cols).
// Parameters on no axis and in no column take `fixed`.
struct GridView {
  int n_axes;
  int param[kParamCount];          // ParamId of each axis
  long count[kParamCount];         // values on each axis
  const double* values[kParamCount];
  double fixed[kParamCount];       // value of each parameter not varied
  const double* points;
  long n_points;                   // rows of the whole design (size())
  long points_first;               // the design row points[0] holds: a device copy holds one chunk's rows
  int point_cols;
  int point_param[kParamCount];

  AURORA_HD long size() const {
    if (n_points > 0) return n_points;
    long n = 1;
    for (int a = 0; a < n_axes; ++a) n *= count[a];
    return n;
  }

  AURORA_HD Combination decode(long index) const {
    Combination c;
    for (int i = 0; i < kParamCount; ++i) c.v[i] = fixed[i];
    if (n_points > 0) {
      const long row = index - points_first;
      for (int j = 0; j < point_cols; ++j) c.v[point_param[j]] = points[row * point_cols + j];
    } else {
      long rest = index;
      for (int a = 0; a < n_axes; ++a) {
        c.v[param[a]] = values[a][rest % count[a]];
        rest /= count[a];
      }
    }
    return c;
  }
};

}  // namespace aurora_sweep
