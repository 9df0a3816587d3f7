// Which parameters one simulation of a sweep uses, computed from its index
// alone (ROS-free, host and device): a CUDA thread, a SIMD lane and the
// scalar loop all decode the same index to the same combination, so no
// table of every combination is ever built.
#pragma once

#include <type_traits>

#include "aurora_common/host_device.h"
#include "aurora_common/named_list.h"
#include "aurora_control/law/other_laws.h"

namespace aurora_sweep {

// Every parameter a sweep can vary (names and accepted ranges: parameters.h).
// The PD law's gains, the delay, the underactuated law's 12 gains in the
// order of underactuatedGainName (k1_x, k2_x, ..., k2_psi), factors of
// the simulated drone's model parameters (1 = the vehicle file's value), the
// link's values (aurora_control::LinkValue order: uplink_jitter, ...,
// downlink_burst; the delay is the uplink's base delay), the repeat: which
// of a combination's `repeats` link seeds a run draws with (not a name a
// sweep file gives; `repeats: N` makes it vary). A formation sweep's own
// parameters follow, where its shape's ShapeLayout puts them.
enum ParamId : int {
  kParamKp = 0,
  kParamKd = 1,
  kParamDelay = 2,
  kParamFirstUnderactuatedGain = 3,  // 12 of them
  kParamFirstModelFactor = 15,       // m, Ixx, Iyy, Izz, Cf, Ct, Km, Jm
  kParamFirstLinkValue = 23,         // 7 of them
  kParamRepeat = 30,
  kParamFirstRobotParam = 31,        // a formation's: ShapeLayout
};
constexpr int kUnderactuatedGainCount = 12;
constexpr int kModelFactorCount = 8;
constexpr int kLinkParamCount = 7;

// Where a formation sweep's parameters sit, for a shape of `robots` robots
// and `variables` formation variables: each robot's uplink delay (delay_1
// ... delay_N), the formation layer's gains (K1 of each variable, then
// K2), each robot's own link values (uplink_jitter_1 ... downlink_burst_N:
// robot r's value i at linkValue(r, i)); docs/formation.md, "Formation
// sweeps". The line of two puts them where they always were (31, 33, 45;
// 59 in all), so its records and definition hashes stay.
struct ShapeLayout {
  int robots, variables;
  AURORA_HD constexpr int delay(int robot) const { return kParamFirstRobotParam + robot; }
  AURORA_HD constexpr int k1(int i) const { return delay(robots) + i; }
  AURORA_HD constexpr int k2(int i) const { return k1(variables) + i; }
  AURORA_HD constexpr int linkValue(int robot, int i) const { return k2(variables) + robot * kLinkParamCount + i; }
  AURORA_HD constexpr int count() const { return linkValue(robots, 0); }
};
template <class Shape>
AURORA_HD constexpr ShapeLayout layoutOf() {
  return ShapeLayout{Shape::kDrones, Shape::kVariables};
}

// The room of the formation parameters: the largest shape a sweep flies
// (three robots, nine variables: AuRoRA's triangle); a shape that needs more
// is refused where it is laid out (static_assert in shapeLayout).
constexpr ShapeLayout kLargestShape{3, 9};
constexpr int kParamFirstLawGain = kLargestShape.count();
template <class Shape>
AURORA_HD constexpr ShapeLayout shapeLayout() {
  static_assert(layoutOf<Shape>().count() <= kParamFirstLawGain, "a shape whose parameters exceed its room");
  return layoutOf<Shape>();
}

// The laws' own gains (each law's kGainCount rows, law_gain_rows.h), in
// the order of the laws' list (aurora_control/law/other_laws.h), fill the
// record's rooms for them, each block within one room: the first law's
// (the PD law's kp, kd) before the delay, the second's (the underactuated
// law's 12) after it, kLawGainRoom after the formation parameters (the
// Bebop 2 compensator's 10, the Pioneer's dynamic law's 6, its kinematic
// law's 2). A law appended to the list takes its block after the robots'
// gains, so no parameter moves (records, hashes stay).
constexpr int kLawGainRoom = 18;
enum LawGainId : int {
  // A triangle sweep's law (its index: N, PSO, SPO, OSP, S-PO;
  // aurora_control::TriangleLaw), after the laws' gains: older records and
  // hashes keep theirs.
  kParamFormationLaw = kParamFirstLawGain + kLawGainRoom,
  // Each formation robot's own law's gains (robot_gains.h names them by
  // the robot's law): a block of kRobotGainRoom per robot, the most any law
  // has (the underactuated law's 12), for the largest shape's robots; after
  // everything older (its records and hashes keep theirs).
  kParamFirstRobotGain,
};
constexpr int kRobotGainRoom = 12;
constexpr int kRobotGainRobots = kLargestShape.robots;
AURORA_HD constexpr int robotGainParam(int robot, int i) { return kParamFirstRobotGain + robot * kRobotGainRoom + i; }
constexpr int kParamRobotGainEnd = robotGainParam(kRobotGainRobots, 0);

// The rooms, as the record lays them out.
struct GainRoom {
  int first, size;
};
constexpr int kLawGainRooms = 3;
constexpr GainRoom lawGainRoom(int r) {
  return r == 0 ? GainRoom{kParamKp, kParamDelay - kParamKp}
                : r == 1 ? GainRoom{kParamFirstUnderactuatedGain, kParamFirstModelFactor - kParamFirstUnderactuatedGain}
                         : GainRoom{kParamFirstLawGain, kLawGainRoom};
}

// Where the block of the law at `place` (1-based) of the list starts, the
// laws filling the rooms in order; place 0: the end of the blocks past the
// rooms (kParamRobotGainEnd when every block is in a room).
template <class... L>
constexpr int lawGainPlace(aurora_common::TypeList<L...>, int place) {
  const int counts[] = {0, L::kGainCount...};
  int room = 0, used = 0, beyond = kParamRobotGainEnd;
  for (int i = 1; i <= int(sizeof...(L)); ++i) {
    while (room < kLawGainRooms && used + counts[i] > lawGainRoom(room).size) ++room, used = 0;
    const int first = room < kLawGainRooms ? lawGainRoom(room).first + used : beyond;
    if (room < kLawGainRooms) used += counts[i];
    else beyond += counts[i];
    if (i == place) return first;
  }
  return beyond;
}
// Where Law's block starts among `list`'s (-1: not in it).
template <class Law, class... L>
constexpr int lawGainFirst(aurora_common::TypeList<L...> list) {
  const bool is[] = {false, std::is_same<Law, L>::value...};
  for (int i = 1; i <= int(sizeof...(L)); ++i) {
    if (is[i]) return lawGainPlace(list, i);
  }
  return -1;
}

// Law's block of sweep parameters: kFirst .. kFirst + kCount.
template <class Law>
struct LawGainBlock {
  static constexpr int kCount = Law::kGainCount;
  static constexpr int kFirst = lawGainFirst<Law>(aurora_control::KnownLaws());
  static_assert(kFirst >= 0, "a law of the laws' list (other_laws.h)");
};
// Their definitions (C++14: a test's EXPECT_EQ takes them by reference).
template <class Law>
constexpr int LawGainBlock<Law>::kCount;
template <class Law>
constexpr int LawGainBlock<Law>::kFirst;

constexpr int kParamCount = lawGainPlace(aurora_control::KnownLaws(), 0);

// The line of two drones (the shape a sweep file flies today).
constexpr ShapeLayout kLineLayout{2, 6};
// The parameters of the sweeps before links, and before per-drone link
// values (definition hashes keep them).
constexpr int kParamCountBeforeLinks = kParamFirstLinkValue;
constexpr int kParamCountBeforeDroneLinks = kLineLayout.linkValue(0, 0);
static_assert(kLineLayout.delay(0) == 31 && kLineLayout.k1(0) == 33 && kLineLayout.linkValue(0, 0) == 45 &&
                  kLineLayout.count() == 59,
              "the line's parameters where its records and hashes have them");

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
// The most parameters one sweep varies (axes or points columns): the
// view is a CUDA kernel's argument, which stays within the 4 KB older
// CUDA versions allow.
constexpr int kMaxVaried = 32;

struct GridView {
  int n_axes;
  int param[kMaxVaried];           // ParamId of each axis
  long count[kMaxVaried];          // values on each axis
  const double* values[kMaxVaried];
  double fixed[kParamCount];       // value of each parameter not varied
  const double* points;
  long n_points;                   // rows of the whole design (size())
  long points_first;               // the design row points[0] holds: a device copy holds one chunk's rows
  int point_cols;
  int point_param[kMaxVaried];
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
