// Which parameters one simulation of a sweep uses, computed from its index
// alone (ROS-free, host and device): a CUDA thread, a SIMD lane and the
// scalar loop all decode the same index to the same combination, so no
// table of every combination is ever built.
#pragma once

#include "aurora_sim/host_device.h"

namespace aurora_sweep {

// Every parameter a sweep can vary (names and accepted ranges: parameters.h).
// The PD law's gains, the delay, the underactuated law's 12 gains in the
// order of underactuatedGainName (k1_x, k2_x, ..., k2_psi), factors of
// the simulated drone's model parameters (1 = the vehicle file's value), the
// link's values (aurora_control::LinkValue order: uplink_jitter, ...,
// downlink_burst; the delay is the uplink's base delay), the repeat: which
// of a combination's `repeats` link seeds a run draws with (not a name a
// sweep file gives; `repeats: N` makes it vary), and a formation sweep's
// own: each drone's delay, the formation layer's gains and each drone's own
// link values (uplink_jitter_1 ... downlink_burst_2: drone d's value i at
// kParamFirstDroneLinkValue + d * kLinkParamCount + i; docs/formation.md,
// "Formation sweeps").
enum ParamId : int {
  kParamKp = 0,
  kParamKd = 1,
  kParamDelay = 2,
  kParamFirstUnderactuatedGain = 3,  // 12 of them
  kParamFirstModelFactor = 15,       // m, Ixx, Iyy, Izz, Cf, Ct, Km, Jm
  kParamFirstLinkValue = 23,         // 7 of them
  kParamRepeat = 30,
  kParamFirstDroneDelay = 31,        // a formation's drones' uplink delays: delay_1, delay_2
  kParamFirstFormationGain = 33,     // the formation layer's K1 (6), then K2 (6)
  kParamFirstDroneLinkValue = 45,    // a formation's drones' own link values, 7 per drone
  kParamCount = 59
};
constexpr int kUnderactuatedGainCount = 12;
constexpr int kModelFactorCount = 8;
constexpr int kLinkParamCount = 7;
constexpr int kFormationDroneCount = 2;   // the line's drones
constexpr int kFormationGainCount = 12;   // K1 and K2 of the line's 6 variables
// The parameters of the sweeps before links, and before per-drone link
// values (definition hashes keep them).
constexpr int kParamCountBeforeLinks = kParamFirstLinkValue;
constexpr int kParamCountBeforeDroneLinks = kParamFirstDroneLinkValue;

struct Combination {
  double v[kParamCount];  // every parameter's value, ParamId order
  long key;               // the combination the link's draws are keyed by (the index without its repeat)
  AURORA_HD long delay() const { return static_cast<long>(v[kParamDelay]); }
  AURORA_HD long repeat() const { return static_cast<long>(v[kParamRepeat]); }
};

// A grid: axes, axis 0 varies fastest (the order of the sweep file's
// `order`). Values of an axis are precomputed per axis on the host
// (from/to/count or an explicit list). Alternatively a list of points
// (n_points > 0, from a CSV file or a sampling design): row i holds the
// values of the `point_cols` parameters point_param[0..point_cols).
// Parameters on no axis and in no column take `fixed`. With `repeats` N > 1
// each combination runs N times, its repeats consecutive: index i is repeat
// i % N of combination i / N.
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
  long repeats;                    // runs of each combination (1: one)

  AURORA_HD long combinations() const {
    if (n_points > 0) return n_points;
    long n = 1;
    for (int a = 0; a < n_axes; ++a) n *= count[a];
    return n;
  }
  AURORA_HD long size() const { return combinations() * repeats; }

  AURORA_HD Combination decode(long index) const {
    Combination c;
    for (int i = 0; i < kParamCount; ++i) c.v[i] = fixed[i];
    c.v[kParamRepeat] = double(index % repeats);
    index /= repeats;
    c.key = index;
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
