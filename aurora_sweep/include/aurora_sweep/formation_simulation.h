// One formation of a formation sweep (docs/formation.md, "Formation
// sweeps"), from its combination index: the formation file's run with the
// combination's robot delays, formation gains and link values, flown by the
// offline formation runner and judged by the formation's checks. Written
// against a shape (a template of the scalar, as LineFormation; its
// parameters where shapeLayout puts them). The per-thread body of the CUDA
// kernel and of the scalar loop (host and device, no allocation); the SIMD
// engine builds each lane's run with the same formationCombination().
#pragma once

#include <cstddef>
#include <cstring>
#include <type_traits>
#include <utility>

#include "aurora_control/formation/formation_judge.h"
#include "aurora_control/formation/formation_runner.h"
#include "aurora_sweep/robot_gains.h"
#include "aurora_sweep/simulation.h"

namespace aurora_sweep {

// A shape's run in precision T, its robots flying laws of data `Data`.
template <typename T, template <typename> class Shape, class Data>
using ShapeRun = aurora_control::FormationRun<T, Shape<T>, Data>;

// Everything a formation of the sweep needs besides its combination.
template <typename T, template <typename> class Shape, class Data>
struct FormationSetup {
  ShapeRun<T, Shape, Data> run;  // the formation file's, in T
  aurora_control::FormationCriteria<T> criteria;
  long iterations;  // ticks (2700 for 90 s)
  bool early_stop;  // stop a run at its first failed check
  bool ideal_link;  // every drone over today's delay rule (SweepSpec::linkIdeal)
};

// Robot `from`'s fixed values in precision T: its models, gains (each law's
// data gives its castGains, found by argument-dependent lookup), delay,
// link and start.
template <typename T, typename U, class Data>
void castFormationDrone(const aurora_control::FormationDrone<U, Data>& from, aurora_control::FormationDrone<T, Data>& to) {
  to.plant = from.plant.template cast<T>();
  to.model = from.model.template cast<T>();
  castGains(from.gains, to.gains);
  to.delay = from.delay;
  to.link = from.link;
  for (int i = 0; i < 3; ++i) to.start[i] = T(from.start[i]);
  to.predictor = from.predictor.template cast<T>();
}

// The formation's own values (law, gains, period, reference, clamp) in T.
template <typename T, class ToShape, typename U, class FromShape, class Data>
void castFormationLayer(const aurora_control::FormationRun<U, FromShape, Data>& r,
                        aurora_control::FormationRun<T, ToShape, Data>& run) {
  constexpr int N = FromShape::kVariables;
  run.law = r.law;
  for (int i = 0; i < N; ++i) run.gains.k1[i] = T(r.gains.k1[i]), run.gains.k2[i] = T(r.gains.k2[i]);
  run.schedule = r.schedule.template cast<T>();
  run.reference.path = r.reference.path;
  run.reference.duration = T(r.reference.duration);
  for (int i = 0; i < 2; ++i) run.reference.amplitude[i] = T(r.reference.amplitude[i]);
  for (int i = 0; i < N; ++i) run.reference.Q[i] = T(r.reference.Q[i]);
  run.clamp = r.clamp;
}

// The file's run in precision T (its values are loaded in double).
template <typename T, template <typename> class Shape, class Data>
ShapeRun<T, Shape, Data> castFormationRun(const ShapeRun<double, Shape, Data>& r) {
  ShapeRun<T, Shape, Data> run;
  for (int d = 0; d < Shape<T>::kDrones; ++d) castFormationDrone(r.drone[d], run.drone[d]);
  castFormationLayer(r, run);
  return run;
}

// A shape's law as a sweep's formation_law sets it: a shape whose sweep
// varies its law declares setSweptLaw(its law&, value) beside its law type
// (the triangle's, triangle_formation.h), found by that type's namespace;
// the others fly their file's law (this default).
template <class Law>
AURORA_HD inline void setSweptLaw(Law&, double) {}

// A combination's formation, its robots flying law `Law`: each robot's
// delay, its law's gains the sweep gives (robot_gains.h), the formation's
// gains, and each robot's link with the link values the sweep gives, the
// robots' common ones (combinationLink) then the robot's own
// (uplink_loss_2); a value it does not give keeps the robot's file's.
template <class Law, typename T, template <typename> class Shape, class Data>
AURORA_HD inline ShapeRun<T, Shape, Data> formationCombination(const FormationSetup<T, Shape, Data>& s,
                                                               const Combination& c) {
  static_assert(std::is_same<Data, typename Law::Data>::value, "the law flies the setup's robots");
  constexpr ShapeLayout at = shapeLayout<Shape<T>>();
  static_assert(at.robots <= kRobotGainRobots, "a robot gain room for every robot");
  ShapeRun<T, Shape, Data> run = s.run;
  for (int d = 0; d < at.robots; ++d) {
    run.drone[d].delay = static_cast<long>(c.v[at.delay(d)]);
    run.drone[d].link = combinationLink(run.drone[d].link, run.drone[d].delay, c);
    applyLinkValues(run.drone[d].link, c.v + at.linkValue(d, 0));  // its own last
    RobotGains<Law>::set(run.drone[d].gains, run.drone[d].model, c.v + robotGainParam(d, 0));
  }
  for (int i = 0; i < at.variables; ++i) {
    run.gains.k1[i] = T(c.v[at.k1(i)]);
    run.gains.k2[i] = T(c.v[at.k2(i)]);
  }
  setSweptLaw(run.law, c.v[kParamFormationLaw]);
  return run;
}

// Drone d's link draws are keyed by the combination and the drone (the
// flight tool's key is the drone's index: combination 0 draws as it does).
template <class Shape>
AURORA_HD inline uint64_t formationLinkKey(const Combination& c, int drone) {
  return static_cast<uint64_t>(c.key) * Shape::kDrones + static_cast<uint64_t>(drone);
}

// A formation's record: the sweep's 48 bytes (SimResult) with each field
// named for what it holds (its columns: result_columns.h's formation list).
struct FormationRecord {
  float max_position_error, max_shape_error, end_distance;  // [m] after settle_time; the closest pair at the end
  int ticks;                                                // ticks run
  double iae_position, iae_shape;                           // [m s] after settle_time
  double min_distance;                                      // [m] the closest two drones came, whole flight
  unsigned char ok;                                         // SimResult::ok's bits
  unsigned char zero[3];
  float ground_command;  // the largest share of a ground robot's check 5 limits its commands used (0: none)
};
static_assert(sizeof(FormationRecord) == sizeof(SimResult) &&
                  offsetof(FormationRecord, ticks) == offsetof(SimResult, steps) &&
                  offsetof(FormationRecord, iae_position) == offsetof(SimResult, iae) &&
                  offsetof(FormationRecord, min_distance) == offsetof(SimResult, iasc) &&
                  offsetof(FormationRecord, ok) == offsetof(SimResult, ok) &&
                  offsetof(FormationRecord, ground_command) == offsetof(SimResult, extra),
              "a formation's record is the sweep's record, field for field");

// The record of a formation's metrics after `ticks` ticks, its drones
// `end_distance` apart at the end.
template <typename T, class Shape>
AURORA_HD inline SimResult formationResult(const aurora_control::FormationMetrics<T, bool, Shape>& m, long ticks,
                                           T end_distance) {
  FormationRecord f;
  for (int i = 0; i < 3; ++i) f.zero[i] = 0;
  f.max_position_error = static_cast<float>(m.max_position);
  f.max_shape_error = static_cast<float>(m.max_shape);
  f.end_distance = static_cast<float>(end_distance);
  f.ticks = static_cast<int>(ticks);
  f.iae_position = double(m.iae_position);
  f.iae_shape = double(m.iae_shape);
  f.min_distance = double(m.closest);
  f.ground_command = static_cast<float>(m.ground_command);
  f.ok = 0;
  for (int i = 0; i < m.kChecks; ++i) f.ok |= static_cast<unsigned char>((m.ok[i] ? 1 : 0) << checkBit(i));
  f.ok |= static_cast<unsigned char>((m.feasible() ? 1 : 0) << kFeasibleBit);
  SimResult s;
  memcpy(&s, &f, sizeof s);
  return s;
}

// The closest two drones' distance at the end of a run (positions after
// its last tick).
template <typename T, class Shape, class Observer, class Data>
struct EndDistance {
  Observer& judge;
  T distance = T(0);
  AURORA_HD bool operator()(const aurora_control::FormationObservation<T, Shape, Data>& o) {
    T X[Shape::kVariables];
    aurora_control::modelPositions<Shape, typename Data::Vehicle>(o.drones, X);
    distance = aurora_control::closestPair<Shape>(X);
    return judge(o);
  }
};

// Over links[d] for robot d (in this frame, no allocation), without a
// predictor ...
template <class Law, typename T, int Capacity, class Shape, class Observer, class Link>
AURORA_HD inline long flyOver(const aurora_control::FormationRun<T, Shape, typename Law::Data>& run, long iterations,
                              Observer& observe, Link* links, std::false_type /*predicted*/) {
  return aurora_control::runFormationOver<Law, T, Shape, Capacity>(run, iterations, observe, links);
}

// ... or with each robot's (dronePredictor; off for a robot without one),
// its rings twice the history, as a single robot's (simulation.h).
template <class Predictor, typename T, class Shape, class Data>
AURORA_HD inline Predictor robotPredictor(const aurora_control::FormationRun<T, Shape, Data>& run, int d) {
  const aurora_control::PredictorRun<typename Data::Vehicle, T> p = aurora_control::dronePredictor(run, d);
  return Predictor(p.form, p.model, p.path);
}
template <class Law, typename T, int Capacity, class Shape, class Observer, class Link, size_t... D>
AURORA_HD inline long flyPredicted(const aurora_control::FormationRun<T, Shape, typename Law::Data>& run, long iterations,
                                   Observer& observe, Link* links, std::index_sequence<D...> robots) {
  using Predictor = aurora_control::StatePredictor<typename Law::Vehicle, T, 2 * Capacity>;
  Predictor predictors[Shape::kDrones] = {robotPredictor<Predictor>(run, int(D))...};
  return aurora_control::runPredictedFormationOver<Law, T, Shape, Capacity>(run, iterations, observe, links,
                                                                            predictors, robots);
}
template <class Law, typename T, int Capacity, class Shape, class Observer, class Link>
AURORA_HD inline long flyOver(const aurora_control::FormationRun<T, Shape, typename Law::Data>& run, long iterations,
                              Observer& observe, Link* links, std::true_type /*predicted*/) {
  return flyPredicted<Law, T, Capacity>(run, iterations, observe, links, std::make_index_sequence<Shape::kDrones>());
}

// Over today's delay rule on every drone.
template <class Law, typename T, int Capacity, class Shape, class Observer, class Predicted>
AURORA_HD inline long flyFormation(const aurora_control::FormationRun<T, Shape, typename Law::Data>& run, const Combination&,
                                   long iterations, Observer& observe, std::false_type /*linked*/, Predicted predicted) {
  aurora_control::IdealLink links[Shape::kDrones];
  for (int d = 0; d < Shape::kDrones; ++d) links[d] = aurora_control::IdealLink{run.drone[d].delay};
  return flyOver<Law, T, Capacity>(run, iterations, observe, links, predicted);
}

// Over each drone's link model, built in this frame (no allocation).
template <class Law, typename T, int Capacity, class Shape, class Observer, class Predicted, size_t... D>
AURORA_HD inline long flyFormationOverModels(const aurora_control::FormationRun<T, Shape, typename Law::Data>& run,
                                             const Combination& c, long iterations, Observer& observe,
                                             Predicted predicted, std::index_sequence<D...>) {
  using Link = aurora_control::ModelLink<Capacity, T, Law::Vehicle::kInputs>;
  Link links[Shape::kDrones] = {Link(run.drone[D].link, run.drone[D].delay, formationLinkKey<Shape>(c, int(D)),
                                     double(run.drone[D].plant.Ts))...};
  return flyOver<Law, T, Capacity>(run, iterations, observe, links, predicted);
}
template <class Law, typename T, int Capacity, class Shape, class Observer, class Predicted>
AURORA_HD inline long flyFormation(const aurora_control::FormationRun<T, Shape, typename Law::Data>& run, const Combination& c,
                                   long iterations, Observer& observe, std::true_type /*linked*/, Predicted predicted) {
  return flyFormationOverModels<Law, T, Capacity>(run, c, iterations, observe, predicted,
                                                  std::make_index_sequence<Shape::kDrones>());
}

namespace formation_predictor_detail {
template <class Data>
constexpr bool predicts(decltype(Data::kPredicts)*) {
  return Data::kPredicts;
}
template <class Data>
constexpr bool predicts(...) {
  return true;
}
template <typename T, class Shape, class Data, class F>
void withPredictor(std::true_type, const aurora_control::FormationRun<T, Shape, Data>& run, F&& f) {
  if (aurora_control::anyPredictor(run)) return f(std::true_type());
  f(std::false_type());
}
template <typename T, class Shape, class Data, class F>
void withPredictor(std::false_type, const aurora_control::FormationRun<T, Shape, Data>&, F&& f) {
  f(std::false_type());
}
}  // namespace formation_predictor_detail

// Calls f(std::true_type()) when a robot of `run` flies with a predictor
// (its controller file's), else f(std::false_type()): the one place a
// formation sweep's backends choose. Robots whose law data declares
// kPredicts false (a mixed crew's, either_law.h) fly without: no predicted
// code is built for them.
template <typename T, class Shape, class Data, class F>
void withFormationPredictor(const aurora_control::FormationRun<T, Shape, Data>& run, F&& f) {
  using Predicts = std::integral_constant<bool, formation_predictor_detail::predicts<Data>(nullptr)>;
  formation_predictor_detail::withPredictor(Predicts(), run, f);
}

// Formation `index` of the sweep (over its drones' links when `Linked`),
// every robot flying law `Law` (a law type), with the predictors of its
// robots' controller files when `Predicted`: the CUDA thread's and the
// scalar loop's body.
template <class Law, typename T, int Capacity, bool Linked = false, bool Predicted = false,
          template <typename> class Shape>
AURORA_HD inline SimResult simulateFormation(const FormationSetup<T, Shape, typename Law::Data>& setup,
                                             const GridView& grid, long index) {
  using Data = typename Law::Data;
  const Combination c = grid.decode(index);
  const ShapeRun<T, Shape, Data> run = formationCombination<Law>(setup, c);
  using Judge = aurora_control::FormationJudge<T, Shape<T>, Data>;
  Judge judge{setup.criteria, setup.early_stop, run.drone[0].plant.Ts, {}, {}};
  judge.metrics.reset();
  EndDistance<T, Shape<T>, Judge, Data> observe{judge};
  const long ticks = flyFormation<Law, T, Capacity>(run, c, setup.iterations, observe,
                                                    std::integral_constant<bool, Linked>(),
                                                    std::integral_constant<bool, Predicted>());
  return formationResult(judge.metrics, ticks, observe.distance);
}

}  // namespace aurora_sweep
