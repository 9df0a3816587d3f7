// One formation of a formation sweep (docs/formation.md, "Formation
// sweeps"), from its combination index: the formation file's run with the
// combination's drone delays, formation gains and link values, flown by the
// offline formation runner and judged by the formation's checks. The
// per-thread body of the CUDA kernel and of the scalar loop (host and
// device, no allocation); the SIMD engine builds each lane's run with the
// same formationCombination().
#pragma once

#include <type_traits>

#include "aurora_control/formation_judge.h"
#include "aurora_control/formation_runner.h"
#include "aurora_sweep/simulation.h"

namespace aurora_sweep {

template <typename T>
using LineRun = aurora_control::FormationRun<T, aurora_control::LineFormation<T>>;

// Everything a formation of the sweep needs besides its combination.
template <typename T>
struct FormationSetup {
  LineRun<T> run;  // the formation file's, in T
  aurora_control::FormationCriteria<T> criteria;
  long iterations;  // ticks (2700 for 90 s)
  bool early_stop;  // stop a run at its first failed check
  bool ideal_link;  // every drone over today's delay rule (SweepSpec::linkIdeal)
};

// The file's run in precision T (its values are loaded in double).
template <typename T>
LineRun<T> castFormationRun(const LineRun<double>& r) {
  LineRun<T> run;
  for (int d = 0; d < kFormationDroneCount; ++d) {
    const auto& from = r.drone[d];
    auto& to = run.drone[d];
    to.plant = from.plant.template cast<T>();
    to.model = from.model.template cast<T>();
    to.gains.pd.kp = T(from.gains.pd.kp), to.gains.pd.kd = T(from.gains.pd.kd);
    for (int i = 0; i < aurora_control::kAxes; ++i) {
      to.gains.underactuated.k1[i] = T(from.gains.underactuated.k1[i]);
      to.gains.underactuated.k2[i] = T(from.gains.underactuated.k2[i]);
    }
    to.delay = from.delay;
    to.link = from.link;
    for (int i = 0; i < 3; ++i) to.start[i] = T(from.start[i]);
  }
  run.law = r.law;
  for (int i = 0; i < 6; ++i) run.gains.k1[i] = T(r.gains.k1[i]), run.gains.k2[i] = T(r.gains.k2[i]);
  run.period_steps = r.period_steps;
  run.reference.path = r.reference.path;
  run.reference.duration = T(r.reference.duration);
  for (int i = 0; i < 2; ++i) run.reference.amplitude[i] = T(r.reference.amplitude[i]);
  for (int i = 0; i < 6; ++i) run.reference.Q[i] = T(r.reference.Q[i]);
  run.clamp = r.clamp;
  return run;
}

// A combination's formation: each drone's delay, the formation's gains, and
// each drone's link with the link values the sweep gives, the drones'
// common ones (combinationLink) then the drone's own (uplink_loss_2); a
// value it does not give keeps the drone's file's.
template <typename T>
AURORA_HD inline LineRun<T> formationCombination(const FormationSetup<T>& s, const Combination& c) {
  LineRun<T> run = s.run;
  for (int d = 0; d < kFormationDroneCount; ++d) {
    run.drone[d].delay = static_cast<long>(c.v[kParamFirstDroneDelay + d]);
    run.drone[d].link = combinationLink(run.drone[d].link, run.drone[d].delay, c);
    applyLinkValues(run.drone[d].link, c.v + kParamFirstDroneLinkValue + d * kLinkParamCount);  // its own last
  }
  for (int i = 0; i < 6; ++i) {
    run.gains.k1[i] = T(c.v[kParamFirstFormationGain + i]);
    run.gains.k2[i] = T(c.v[kParamFirstFormationGain + 6 + i]);
  }
  return run;
}

// Drone d's link draws are keyed by the combination and the drone (the
// flight tool's key is the drone's index: combination 0 draws as it does).
AURORA_HD inline uint64_t formationLinkKey(const Combination& c, int drone) {
  return static_cast<uint64_t>(c.key) * kFormationDroneCount + static_cast<uint64_t>(drone);
}

// The record a formation writes (the sweep's 48 bytes, its columns named by
// result_columns.h's formation list): iae = the position error's integral,
// itae = the shape error's, iasc = the smallest distance, the floats the
// largest position and shape errors and the drones' distance at the end.
template <typename T>
AURORA_HD inline SimResult formationResult(const aurora_control::FormationMetrics<T, bool, aurora_control::LineFormation<T>>& m,
                                           long ticks, T end_distance) {
  SimResult s;
  for (int i = 0; i < 7; ++i) s.zero[i] = 0;
  s.final_pos[0] = static_cast<float>(m.max_position);
  s.final_pos[1] = static_cast<float>(m.max_shape);
  s.final_pos[2] = static_cast<float>(end_distance);
  s.steps = static_cast<int>(ticks);
  s.iae = double(m.iae_position);
  s.itae = double(m.iae_shape);
  s.iasc = double(m.closest);
  s.ok = 0;
  for (int i = 0; i < 4; ++i) s.ok |= static_cast<unsigned char>((m.ok[i] ? 1 : 0) << i);
  s.ok |= static_cast<unsigned char>((m.feasible() ? 1 : 0) << kFeasibleBit);
  return s;
}

// The drones' distance at the end of a run (positions after its last tick).
template <typename T, class Observer>
struct EndDistance {
  Observer& judge;
  T distance = T(0);
  AURORA_HD bool operator()(const aurora_control::FormationObservation<T, aurora_control::LineFormation<T>>& o) {
    T X[6];
    for (int d = 0; d < 2; ++d) {
      for (int i = 0; i < 3; ++i) X[3 * d + i] = o.drones[d].model.X[aurora_sim::kX + i];
    }
    distance = aurora_control::closestPair<aurora_control::LineFormation<T>>(X);
    return judge(o);
  }
};

// Over today's delay rule on every drone.
template <aurora_control::LawType Law, typename T, int Capacity, class Observer>
AURORA_HD inline long flyFormation(const LineRun<T>& run, const Combination&, long iterations, Observer& observe,
                                   std::false_type /*linked*/) {
  aurora_control::IdealLink links[kFormationDroneCount];
  for (int d = 0; d < kFormationDroneCount; ++d) links[d] = aurora_control::IdealLink{run.drone[d].delay};
  return aurora_control::runFormationOver<Law, T, aurora_control::LineFormation<T>, Capacity>(run, iterations, observe,
                                                                                          links);
}

// Over each drone's link model, in this frame (no allocation).
template <aurora_control::LawType Law, typename T, int Capacity, class Observer>
AURORA_HD inline long flyFormation(const LineRun<T>& run, const Combination& c, long iterations, Observer& observe,
                                   std::true_type /*linked*/) {
  using Link = aurora_control::ModelLink<Capacity, T>;
  Link links[kFormationDroneCount] = {
      Link(run.drone[0].link, run.drone[0].delay, formationLinkKey(c, 0), double(run.drone[0].plant.Ts)),
      Link(run.drone[1].link, run.drone[1].delay, formationLinkKey(c, 1), double(run.drone[1].plant.Ts))};
  return aurora_control::runFormationOver<Law, T, aurora_control::LineFormation<T>, Capacity>(run, iterations, observe,
                                                                                          links);
}

// Formation `index` of the sweep (over its drones' links when `Linked`):
// the CUDA thread's and the scalar loop's body.
template <aurora_control::LawType Law, typename T, int Capacity, bool Linked = false>
AURORA_HD inline SimResult simulateFormation(const FormationSetup<T>& setup, const GridView& grid, long index) {
  const Combination c = grid.decode(index);
  const LineRun<T> run = formationCombination(setup, c);
  aurora_control::FormationJudge<T> judge{setup.criteria, setup.early_stop, run.drone[0].plant.Ts, {}, {}};
  judge.metrics.reset();
  EndDistance<T, aurora_control::FormationJudge<T>> observe{judge};
  const long ticks = flyFormation<Law, T, Capacity>(run, c, setup.iterations, observe,
                                                    std::integral_constant<bool, Linked>());
  return formationResult(judge.metrics, ticks, observe.distance);
}

}  // namespace aurora_sweep
