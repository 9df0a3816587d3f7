// The offline runner of a formation (docs/formation.md, "One tick"): each
// drone is the closed loop of closed_loop.h over its own link (its law on
// the state its uplink delivers, its command over its downlink, one model
// step), and every period the formation layer, on the positions the drones'
// uplinks deliver, gives each drone its held reference. ROS-free.
#pragma once

#include <cmath>
#include <type_traits>
#include <utility>
#include <vector>

#include "aurora_control/loop/closed_loop.h"
#include "aurora_control/loop/delay_buffer.h"
#include "aurora_control/formation/formation_layer.h"
#include "aurora_control/formation/formation_reference.h"
#include "aurora_control/loop/loop_link.h"
#include "aurora_control/loop/predicted_loop.h"

namespace aurora_control {

// One robot of a formation, flying a law of data `Data` (control_law.h:
// its vehicle, gains and memory; the AR.Drone's laws by default): its model
// (plant and the law's nominal model), its gains, its link (link.h; ideal
// by default) with its uplink delay [samples], where it starts [m], and the
// state predictor its controller file gives (docs/predictor.md; off by
// default; its command path the run's: dronePredictor).
template <typename T, class Data>
struct FormationDrone {
  typename Data::Vehicle::template Params<T> plant, model;
  typename Data::template Gains<T> gains;
  long delay = 0;
  LinkParams link;
  T start[3];
  PredictorRun<typename Data::Vehicle, T> predictor;
};

// A formation's robots' loops: their parameters, states and steps.
template <typename T, class Data>
using DroneParams = LoopParams<Data, T>;
template <typename T, typename Mask, class Data>
using DroneState = LoopState<Data, T, Mask>;
template <typename T, class Data>
using DroneStep = LoopStep<T, Data::Vehicle::kInputs>;

// A shape's layer in precision T: the integrating layer (formation_layer.h:
// the line's, the triangle's), or the shape's own where it declares one,
// `template <typename V> using Layer = ...;` (the UAV-UGV line's runs every
// tick without integration, uav_ugv_line.h).
namespace formation_parts_detail {
template <typename T, class Shape>
FormationLayer<T, Shape> layerOf(...);
template <typename T, class Shape>
typename Shape::template Layer<T> layerOf(int);
}  // namespace formation_parts_detail
template <typename T, class Shape>
using LayerOf = decltype(formation_parts_detail::layerOf<T, Shape>(0));

template <typename T, class Shape, class Data>
struct FormationRun {
  static constexpr int kDrones = Shape::kDrones, kN = Shape::kVariables;
  FormationDrone<T, Data> drone[kDrones];
  typename Shape::Law law = Shape::kDefaultLaw;
  FormationGains<T, kN> gains = FormationGains<T, kN>::template of<Shape>();
  LayerSchedule<T> schedule;  // when the layer runs (the line's default: every 6 steps, 0.2 s at 1/30 s)
  FormationReference<T, Shape> reference;
  ClampPolicy clamp;      // none: AuRoRA's formation script does not clamp
};

// A reference held between periods (the layer's output for one drone), as
// the task controllerHalf reads: position, velocity, no acceleration, yaw 0.
template <typename T>
struct HeldReference {
  Reference<T> ref;
  AURORA_HD Reference<T> at(const T&) const { return ref; }
  AURORA_HD void hold(const T pos[3], const T vel[3]) {
    for (int i = 0; i < 3; ++i) ref.pos[i] = pos[i], ref.vel[i] = vel[i], ref.acc[i] = T(0);
    ref.yaw = ref.yaw_rate = ref.yaw_acc = T(0);
  }
};

// What an observer sees after each tick k (0-based: the drones' states went
// from X_k to X_(k+1)).
template <typename T, class Shape, class Data>
struct FormationObservation {
  using Vehicle = typename Data::Vehicle;
  long k;
  bool layer_ran;                                  // the layer ran at the start of this tick
  const T (*X_before)[Vehicle::kStates];           // each drone's state at the tick's start (X_k)
  const DroneState<T, bool, Data>* drones;          // after the model step, per drone (X_(k+1))
  const DroneStep<T, Data>* steps;                  // each drone's reference and applied command
  const LayerOf<T, Shape>& layer;
  const DroneParams<T, Data>* params;               // each robot's (its vehicle, for a mixed crew)
};

// The robots' stacked positions (3 per robot, the shape's X) of their
// states X (each Vehicle::kStates), and of their loops' models.
template <class Shape, class Vehicle, typename T, class States>
AURORA_HD inline void dronePositions(const States& X, T positions[Shape::kVariables]) {
  for (int d = 0; d < Shape::kDrones; ++d) {
    for (int i = 0; i < 3; ++i) positions[3 * d + i] = X[d][Vehicle::kPosition + i];
  }
}
template <class Shape, class Vehicle, typename T, class Loops>
AURORA_HD inline void modelPositions(const Loops& state, T positions[Shape::kVariables]) {
  for (int d = 0; d < Shape::kDrones; ++d) {
    for (int i = 0; i < 3; ++i) positions[3 * d + i] = state[d].model.X[Vehicle::kPosition + i];
  }
}

// The layer started with the drones at X0 (3 positions per drone, m): the
// offline runner's at the file's starts, real drones' where they hover
// when the formation begins (docs/formation.md, "Real robots").
template <typename T, class Shape, class Data>
AURORA_HD inline void startLayerAt(const FormationRun<T, Shape, Data>& run, const T X0[Shape::kVariables],
                                   LayerOf<T, Shape>& layer) {
  T Qd[Shape::kVariables];
  run.reference.at(T(0), Qd);
  layer.start(X0, Qd);
}

// The drones' stacked start positions (the shape's X before tick 0).
template <typename T, class Shape, class Data>
AURORA_HD inline void startPositions(const FormationRun<T, Shape, Data>& run, T X0[Shape::kVariables]) {
  for (int d = 0; d < Shape::kDrones; ++d) {
    for (int i = 0; i < 3; ++i) X0[3 * d + i] = run.drone[d].start[i];
  }
}

// The layer before its first period: the references at the drones' starts,
// the previous Qd = Qd(0) (formation_layer.h).
template <typename T, class Shape, class Data>
AURORA_HD inline void startLayer(const FormationRun<T, Shape, Data>& run, LayerOf<T, Shape>& layer) {
  T X0[Shape::kVariables];
  startPositions(run, X0);
  startLayerAt(run, X0, layer);
}

// What the layer runs on before robot step k (the schedule's rule, for the
// runner, the SIMD engine and the formation node alike): whether a period
// is due and, when it is, its time t [s] and Qd(t).
template <typename T, class Shape, class Data>
AURORA_HD inline bool desiredBefore(const FormationRun<T, Shape, Data>& run, long k, T& t, T Qd[Shape::kVariables]) {
  const long n = run.schedule.periodBefore(k);
  if (n < 0) return false;
  t = run.schedule.time(n, run.drone[0].plant.Ts);
  run.reference.at(t, Qd);
  return true;
}

// Drone d's reference as the layer holds it (position, velocity).
template <class Layer>
AURORA_HD inline auto heldReference(const Layer& layer, int d) -> Reference<typename std::decay<decltype(*layer.position(d))>::type> {
  HeldReference<typename std::decay<decltype(*layer.position(d))>::type> held;
  held.hold(layer.position(d), layer.velocity(d));
  return held.ref;
}

// Each drone's fixed parameters (its plant, model and gains; the study's
// single-drone criteria, which a formation does not judge) and its state at
// rest at its start; the layer started (startLayer).
template <typename T, class Shape, class Data, typename Mask>
AURORA_HD inline void startFormation(const FormationRun<T, Shape, Data>& run, DroneParams<T, Data>* params,
                                     DroneState<T, Mask, Data>* state, LayerOf<T, Shape>& layer) {
  using Vehicle = typename Data::Vehicle;
  for (int d = 0; d < Shape::kDrones; ++d) {
    params[d] = DroneParams<T, Data>{run.drone[d].plant, run.drone[d].model, run.drone[d].gains,
                                     FeasibilityCriteria<T>::study()};
    state[d].reset(params[d].plant, run.drone[d].start);
    for (int i = 0; i < 3; ++i) state[d].model.X[Vehicle::kPosition + i] = run.drone[d].start[i];
  }
  startLayer(run, layer);
}

// Drone d's downlink(d, U) as the link actOn (closed_loop.h) sends through.
template <class Downlink>
struct DroneDownlink {
  Downlink& to;
  int drone;
  template <typename K, typename T>
  AURORA_HD void downlink(const K&, const T*, T* U) const {
    to(drone, U);
  }
};

// The skeleton of steps 2-3 of tick k (docs/formation.md, "One tick"),
// written once for the offline runner (formationTick below) and the
// formation node (FormationController::tick): the layer on the positions
// of the states X the robots fly on when `Qd` is given (a period is due),
// then act(d, ref) for each robot towards its held reference.
template <class Vehicle, typename T, class Layer, class States, class Act>
AURORA_HD inline void layerThenRobots(Layer& layer, const T* Qd, const T& t, const States& X, Act&& act) {
  using Shape = typename Layer::Shape;
  if (Qd) {
    T seen[Shape::kVariables];
    dronePositions<Shape, Vehicle>(X, seen);
    layer.update(seen, Qd, t);
  }
  for (int d = 0; d < Shape::kDrones; ++d) act(d, heldReference(layer, d));
}

// Steps 2-3 of tick k on the states xc the drones' uplinks delivered: the
// layer when `Qd` is given, then each drone's law towards its held
// reference, its command through downlink(d, U) and one model step.
// Scalars or SIMD batches (one formation per lane, every lane at the same
// tick).
template <class Law, typename T, typename Mask, class Layer, class Downlink>
AURORA_HD inline void formationTick(const DroneParams<T, typename Law::Data>* params, const ClampPolicy& clamp,
                                    Layer& layer, const T* Qd, const T& t, const T& k,
                                    const T (*xc)[Law::Vehicle::kStates], DroneState<T, Mask, typename Law::Data>* state,
                                    DroneStep<T, typename Law::Data>* step, Downlink&& downlink) {
  layerThenRobots<typename Law::Vehicle>(layer, Qd, t, xc, [&](int d, const Reference<T>& ref) {
    HeldReference<T> held;
    held.ref = ref;
    DroneDownlink<Downlink> link{downlink, d};
    step[d] = actOn<Law>(params[d], held, clamp, k, xc[d], link, state[d]);
  });
}

// An observer may return whether to go on (false: stop the run, an early
// stop), or nothing (run to the end).
template <class Observer, class Observation>
AURORA_HD inline auto observeTick(Observer& observe, const Observation& o)
    -> typename std::enable_if<std::is_void<decltype(observe(o))>::value, bool>::type {
  observe(o);
  return true;
}
template <class Observer, class Observation>
AURORA_HD inline auto observeTick(Observer& observe, const Observation& o)
    -> typename std::enable_if<!std::is_void<decltype(observe(o))>::value, bool>::type {
  return observe(o);
}

// `iterations` ticks of law `Law` (control_law.h: a law type, all robots
// its vehicle) on every robot, robot d over links[d] (IdealLink or
// ModelLink) and its history history[d] (StateHistory, or PredictedHistory
// with a predictor). Returns the ticks run.
template <class Law, typename T, class Shape, typename Observer, typename Link, typename History>
AURORA_HD long runFormationWith(const FormationRun<T, Shape, typename Law::Data>& run, long iterations,
                                Observer& observe, Link* links, History* history) {
  using Data = typename Law::Data;
  constexpr int D = Shape::kDrones, N = Shape::kVariables, S = Law::Vehicle::kStates;
  const T Ts = run.drone[0].plant.Ts;
  LayerOf<T, Shape> layer(run.law, run.gains, run.schedule.period(Ts));
  DroneParams<T, Data> params[D];
  DroneState<T, bool, Data> state[D];
  startFormation(run, params, state, layer);
  for (long k = 0; k < iterations; ++k) {
    T xc[D][S], before[D][S], Qd[N], t = T(0);
    for (int d = 0; d < D; ++d) {
      for (int i = 0; i < S; ++i) before[d][i] = state[d].model.X[i];
      receiveState(k, history[d], links[d], state[d], xc[d]);
    }
    const bool due = desiredBefore(run, k, t, Qd);
    DroneStep<T, Data> step[D];
    formationTick<Law>(params, run.clamp, layer, due ? Qd : nullptr, t, T(k), xc, state, step,
                       [&](int d, T U[Law::Vehicle::kInputs]) { links[d].downlink(k, U, U); });
    if (!observeTick(observe, FormationObservation<T, Shape, Data>{k, due, before, state, step, layer, params})) return k + 1;
  }
  return iterations;
}

// The same with histories of `Capacity` samples (every robot's history
// below it, checked by the caller), without a predictor.
template <class Law, typename T, class Shape, int Capacity, typename Observer, typename Link>
AURORA_HD long runFormationOver(const FormationRun<T, Shape, typename Law::Data>& run, long iterations,
                                Observer& observe, Link* links) {
  StateHistory<Law, T, Capacity> history[Shape::kDrones];
  return runFormationWith<Law, T, Shape>(run, iterations, observe, links, history);
}

// Robot d's predictor as it flies (docs/predictor.md, "The commands
// applied"): the command delay its link's downlink base delay, the clamp the
// run's robots apply. The runner, the sweeps and the formation node alike.
template <typename T, class Shape, class Data>
AURORA_HD inline PredictorRun<typename Data::Vehicle, T> dronePredictor(const FormationRun<T, Shape, Data>& run, int d) {
  PredictorRun<typename Data::Vehicle, T> p = run.drone[d].predictor;
  p.path.delay = run.drone[d].link.downlink.delay;
  p.path.clamp = run.clamp.at_drone;
  return p;
}

// Whether any robot flies with a predictor.
template <typename T, class Shape, class Data>
AURORA_HD inline bool anyPredictor(const FormationRun<T, Shape, Data>& run) {
  bool on = false;
  for (int d = 0; d < Shape::kDrones; ++d) on = on || run.drone[d].predictor.on();
  return on;
}

// With each robot's predictor predictors[d] (off: the state delivered, as
// it is): as the one loop's (predicted_loop.h), robot d's history reads back
// the predictor's state and its link tells the predictor each command sent.
// The layer and the law both fly on it: the controller side sees one state
// per robot (the formation node's too, formation_controller.h).
template <class Law, typename T, class Shape, int Capacity, typename Observer, typename Link, class Predictor,
          size_t... D>
AURORA_HD long runPredictedFormationOver(const FormationRun<T, Shape, typename Law::Data>& run, long iterations,
                                         Observer& observe, Link* links, Predictor* predictors,
                                         std::index_sequence<D...>) {
  static_assert(sizeof...(D) == Shape::kDrones, "a predictor per robot");
  using History = PredictedHistory<typename Law::Vehicle, T, Capacity, Predictor>;
  History history[Shape::kDrones] = {History(predictors[D])...};
  PredictedLink<Predictor, Link> predicted[Shape::kDrones] = {{predictors[D], links[D]}...};
  return runFormationWith<Law, T, Shape>(run, iterations, observe, predicted, history);
}

// Every drone over its own link: today's delay rule when every link is
// ideal, else each drone's link model, its draws keyed by the drone's index
// (two drones over one link file lose different packets). fly(links).
template <class Law, typename T, class Shape, int Capacity, typename Fly>
long withFormationLinks(const FormationRun<T, Shape, typename Law::Data>& run, Fly&& fly) {
  constexpr int D = Shape::kDrones;
  bool ideal = true;
  for (int d = 0; d < D; ++d) ideal = ideal && run.drone[d].link.ideal();
  if (ideal) {
    IdealLink links[D];
    for (int d = 0; d < D; ++d) links[d] = IdealLink{run.drone[d].delay};
    return fly(links);
  }
  std::vector<ModelLink<Capacity, T, Law::Vehicle::kInputs>> links;  // on the heap: Capacity-sized rings
  links.reserve(D);
  for (int d = 0; d < D; ++d) {
    links.emplace_back(run.drone[d].link, run.drone[d].delay, static_cast<uint64_t>(d), double(run.drone[d].plant.Ts));
  }
  return fly(links.data());
}

// The flight tool's, Python's and the tests' runner: each robot over its
// link, with the predictor its controller file gives (HostPredictor, on the
// heap) when any robot has one.
template <class Law, typename T, class Shape, int Capacity, typename Observer>
long runFormation(const FormationRun<T, Shape, typename Law::Data>& run, long iterations, Observer& observe) {
  using Predictor = HostPredictor<typename Law::Vehicle, T>;
  return withFormationLinks<Law, T, Shape, Capacity>(run, [&](auto* links) {
    if (!anyPredictor(run)) return runFormationOver<Law, T, Shape, Capacity>(run, iterations, observe, links);
    std::vector<Predictor> predictors;
    predictors.reserve(Shape::kDrones);
    for (int d = 0; d < Shape::kDrones; ++d) {
      const PredictorRun<typename Law::Vehicle, T> p = dronePredictor(run, d);
      predictors.emplace_back(p.form, p.model, p.path);
    }
    return runPredictedFormationOver<Law, T, Shape, Capacity>(run, iterations, observe, links, predictors.data(),
                                                              std::make_index_sequence<Shape::kDrones>());
  });
}

// The ticks k = 0 .. n - 1 of a formation flight of `duration` [s] (2700
// for 90 s): the flight tool's and every sweep backend's.
inline long formationTicks(double duration, double Ts) { return std::lround(duration / Ts); }

// The history drone d's link needs (its uplink delay plus jitter, or its
// command path's).
template <typename T, class Shape, class Data>
long formationHistory(const FormationRun<T, Shape, Data>& run) {
  long longest = 0;
  for (int d = 0; d < Shape::kDrones; ++d) {
    const long h = run.drone[d].link.historyNeeded(run.drone[d].delay);
    longest = h > longest ? h : longest;
  }
  return longest;
}

}  // namespace aurora_control
