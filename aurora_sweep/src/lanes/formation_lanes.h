// The `cpu` backend's engine for formation sweeps (docs/formation.md,
// "Formation sweeps"): L formations at once, one per SIMD lane, every lane
// at the same tick (the layer's periods fall on the same ticks). A batch
// takes L consecutive combinations and runs until every lane's formation
// ended (its last tick, or a failed check with early stop); a lane's
// result is taken at the tick it ended. The tick is the scalar runner's
// (formation_runner.h's formationTick and formation_checks.h on batches);
// each drone's delayed state comes from receiveState (closed_loop.h) over
// the lane policies of lane_history.h: its LaneHistory and the delay rule
// on integer lanes or its lanes' link models; with `Predicted`, each drone's
// LanePredictor (lane_predictor.h) over its whole-state history, as
// formation_runner.h's runPredictedFormationOver. Included by batch_engine.h only.
#pragma once

#include <memory>
#include <vector>

#include "aurora_sweep/formation_simulation.h"

namespace aurora_sweep {

namespace {

template <typename T, class Arch, class Law, template <typename> class Shape, bool Predicted = false>
class FormationBatch {
 public:
  using LaneOps = Lanes<T, Arch>;
  using B = typename LaneOps::B;
  using M = typename LaneOps::M;
  using LaneShape = Shape<B>;  // the shape on lanes ...
  using OneLane = Shape<T>;  // ... and on one lane (the scalar judge's)
  static constexpr int L = LaneOps::L, D = OneLane::kDrones, N = OneLane::kVariables;
  using Int = xsimd::as_integer_t<T>;
  using I = xsimd::batch<Int, Arch>;
  using Data = typename Law::Data;
  using Vehicle = typename Law::Vehicle;
  static constexpr int S = Vehicle::kStates;
  using Reader = typename std::conditional<Predicted, aurora_control::WholeStateReader<Vehicle>, Law>::type;
  using History = LaneHistory<Reader, T, Arch>;
  using Links = LaneModelLinks<Reader, T, Arch>;
  using Predictor = LanePredictor<Vehicle, T, Arch>;

  // `capacity`: each drone's history's (limits.h, historyCapacity).
  FormationBatch(const FormationSetup<T, Shape, Data>& setup, int capacity, const GridView& grid, long first,
                 long total, std::vector<SimResult>& out, std::atomic<long>& next, Progress& progress)
      : grid_(grid), first_(first), total_(total), out_(out), next_(next), progress_(progress), setup_(setup) {
    // A sweep's link values may change a drone's link per combination: the
    // vectorized links apply unless the drone's own jitter is geometric.
    for (int d = 0; d < D; ++d) {
      history_[d].allocate(capacity);
      ideal_[d].delay = I(Int(0));
      if (!setup_.ideal_link) {
        links_[d].reset(new Links(setup_.run.drone[d].link, double(setup_.run.drone[d].plant.Ts), history_[d]));
      }
    }
    if (!Predicted) return;
    predictors_.reserve(D);
    for (int d = 0; d < D; ++d) {  // each lane's command delay is its run's (startLanes)
      const auto p = aurora_control::dronePredictor(setup_.run, d);
      predictors_.emplace_back(p.form, p.model, vehicleStart<Vehicle, T>(p.model), p.path.clamp, 2 * long(capacity));
    }
  }

  void run() {
    long first = 0;
    int count = 0;
    while (takeBatch(first, count)) runBatch(first, count);
  }

 private:
  bool takeBatch(long& first, int& count) {
    first = next_.fetch_add(L, std::memory_order_relaxed);
    if (first >= total_) return false;
    count = static_cast<int>(std::min<long>(L, total_ - first));
    return true;
  }

  // The lanes' runs (lanes past `count` repeat the first, their results dropped).
  void startLanes(long first, int count, aurora_control::FormationRun<B, LaneShape, Data>& run) {
    for (int l = 0; l < L; ++l) {
      const Combination c = grid_.decode(first + (l < count ? l : 0));
      const ShapeRun<T, Shape, Data> lane = formationCombination<Law>(setup_, c);
      if (l == 0) broadcast(lane, run);
      for (int i = 0; i < N; ++i) LaneOps::set(run.gains.k1[i], l, lane.gains.k1[i]), LaneOps::set(run.gains.k2[i], l, lane.gains.k2[i]);
      for (int d = 0; d < D; ++d) {
        LaneOps::setFields(run.drone[d].gains, l, lane.drone[d].gains);  // the robot gains the sweep gives
        LaneOps::set(ideal_[d].delay, l, static_cast<Int>(lane.drone[d].delay));
        history_[d].startLane(l);
        if (Predicted) predictors_[d].startLane(l, aurora_control::dronePredictor(lane, d).path.delay);
        if (links_[d]) {
          links_[d]->startLane(l, lane.drone[d].link, lane.drone[d].delay, formationLinkKey<OneLane>(c, d),
                               double(lane.drone[d].plant.Ts));
        }
      }
    }
  }

  // What every lane shares: the drones' models and starts, the law, the
  // period (the file's; the sweep varies none of them); their gains until
  // each lane's are set.
  static void broadcast(const ShapeRun<T, Shape, Data>& s, aurora_control::FormationRun<B, LaneShape, Data>& run) {
    for (int d = 0; d < D; ++d) castFormationDrone(s.drone[d], run.drone[d]);
    castFormationLayer(s, run);
  }

  // Steps 1-2 of tick k for each drone (closed_loop.h, receiveState): its
  // history keeps X_k, its link (the delay rule, or the lanes' link models)
  // picks the state it receives.
  void receiveStates(long k, const aurora_control::DroneState<B, M, Data>* state, B xc[D][S]) {
    const I at(static_cast<Int>(k));
    for (int d = 0; d < D; ++d) {
      if (links_[d]) receiveOver(at, d, *links_[d], state[d], xc[d], std::integral_constant<bool, Predicted>());
      else receiveOver(at, d, ideal_[d], state[d], xc[d], std::integral_constant<bool, Predicted>());
    }
  }
  template <class Link>
  void receiveOver(const I& at, int d, Link& link, const aurora_control::DroneState<B, M, Data>& state, B* xc,
                   std::false_type /*predicted*/) {
    aurora_control::receiveState(at, history_[d], link, state, xc);
  }
  template <class Link>
  void receiveOver(const I& at, int d, Link& link, const aurora_control::DroneState<B, M, Data>& state, B* xc,
                   std::true_type /*predicted*/) {
    PredictedLaneHistory<History, Predictor> predicted{history_[d], predictors_[d]};
    aurora_control::receiveState(at, predicted, link, state, xc);
  }

  // Drone d's sent commands U (told to its predictor) become the ones it
  // applies (ideal: as sent).
  void downlink(int d, long k, B U[Vehicle::kInputs]) {
    if (Predicted) predictors_[d].sent(U);
    if (links_[d]) links_[d]->downlink(I(static_cast<Int>(k)), U, U);
  }

  // The lanes of a batch share their layer's law (a triangle sweep's
  // formation_law: the layer branches on it): runs of consecutive
  // combinations of one law (the whole batch unless formation_law varies
  // fastest).
  void runBatch(long first, int count) {
    for (int start = 0, end = 0; start < count; start = end) {
      const auto law = lawOf(first + start);
      for (end = start + 1; end < count && lawOf(first + end) == law;) ++end;
      runLanes(first + start, end - start);
    }
  }
  typename OneLane::Law lawOf(long index) const { return formationCombination<Law>(setup_, grid_.decode(index)).law; }

  void runLanes(long first, int count) {
    aurora_control::FormationRun<B, LaneShape, Data> run;
    startLanes(first, count, run);
    aurora_control::LayerOf<B, LaneShape> layer(run.law, run.gains, B(setup_.run.schedule.period(setup_.run.drone[0].plant.Ts)));
    aurora_control::DroneParams<B, Data> params[D];
    aurora_control::DroneState<B, M, Data> state[D];
    aurora_control::startFormation(run, params, state, layer);
    aurora_control::FormationMetrics<B, M, LaneShape> metrics;
    metrics.reset();
    const aurora_control::FormationCriteria<B> criteria = setup_.criteria.template cast<B>();
    bool ended[L];
    for (int l = 0; l < L; ++l) ended[l] = l >= count;
    for (long k = 0; k < setup_.iterations; ++k) {
      if (tick(k, run, layer, params, state, metrics, criteria, first, ended)) break;
    }
    for (int l = 0; l < count; ++l) {
      if (!ended[l]) finishLane(l, first, metrics, state, setup_.iterations);
    }
  }

  // Tick k on every lane; true when every lane has ended.
  bool tick(long k, const aurora_control::FormationRun<B, LaneShape, Data>& run, aurora_control::LayerOf<B, LaneShape>& layer,
            const aurora_control::DroneParams<B, Data>* params, aurora_control::DroneState<B, M, Data>* state,
            aurora_control::FormationMetrics<B, M, LaneShape>& metrics, const aurora_control::FormationCriteria<B>& criteria,
            long first, bool* ended) {
    const T Ts = setup_.run.drone[0].plant.Ts;
    B xc[D][S], X[N];
    receiveStates(k, state, xc);
    aurora_control::modelPositions<LaneShape, Vehicle>(state, X);
    T qd[N], t = T(0);
    B Qd[N];
    const bool due = aurora_control::desiredBefore(setup_.run, k, t, qd);  // every lane's, in T
    if (due) {
      // Every lane's Qd and its positions (the scalar judge's, in T).
      T xd[N];
      OneLane::positions(qd, xd);
      for (int i = 0; i < N; ++i) Qd[i] = B(qd[i]), Xd_[i] = B(xd[i]);
    }
    aurora_control::DroneStep<B, Data> step[D];
    aurora_control::formationTick<Law>(params, setup_.run.clamp, layer, due ? Qd : nullptr, B(t), B(T(k)), xc, state, step,
                                       [&](int d, B U[Vehicle::kInputs]) { downlink(d, k, U); });
    metrics.add(criteria, X, Xd_, B(aurora_control::taskTime(T(k), Ts)), B(Ts));
    metrics.template addCommands<Vehicle>(criteria, params, step);
    return endLanes(k, first, metrics, state, ended);
  }

  // Lanes whose check failed (early stop) end at tick k.
  bool endLanes(long k, long first, const aurora_control::FormationMetrics<B, M, LaneShape>& metrics,
                const aurora_control::DroneState<B, M, Data>* state, bool* ended) {
    if (!setup_.early_stop) return false;
    alignas(64) bool ok[L];
    metrics.feasible().store_aligned(ok);
    bool all = true;
    for (int l = 0; l < L; ++l) {
      if (!ended[l] && !ok[l]) finishLane(l, first, metrics, state, k + 1), ended[l] = true;
      all = all && ended[l];
    }
    return all;
  }

  void finishLane(int l, long first, const aurora_control::FormationMetrics<B, M, LaneShape>& m,
                  const aurora_control::DroneState<B, M, Data>* state, long ticks) {
    aurora_control::FormationMetrics<T, bool, OneLane> lane;
    lane.iae_position = LaneOps::get(m.iae_position, l), lane.iae_shape = LaneOps::get(m.iae_shape, l);
    lane.max_position = LaneOps::get(m.max_position, l), lane.max_shape = LaneOps::get(m.max_shape, l);
    lane.closest = LaneOps::get(m.closest, l), lane.ground_command = LaneOps::get(m.ground_command, l);
    for (int i = 0; i < m.kChecks; ++i) lane.ok[i] = LaneOps::get(m.ok[i], l);
    T X[N];
    for (int d = 0; d < D; ++d) {
      for (int i = 0; i < 3; ++i) X[3 * d + i] = LaneOps::get(state[d].model.X[Vehicle::kPosition + i], l);
    }
    out_[first + l - first_] = formationResult(lane, ticks, aurora_control::closestPair<OneLane>(X));
    progress_.fetch_add(1, std::memory_order_relaxed);
  }

  const GridView grid_;
  const long first_, total_;
  std::vector<SimResult>& out_;
  std::atomic<long>& next_;
  Progress& progress_;
  const FormationSetup<T, Shape, Data> setup_;
  History history_[D];                             // each drone's, every lane at the same tick
  aurora_control::IdealLinkOf<I> ideal_[D];         // each drone's delay [samples] per lane, over the delay rule
  std::unique_ptr<Links> links_[D];                // or each drone's lanes' link models
  B Xd_[N];  // the positions of the layer's held Qd (the same on every lane)
  // With Predicted, each drone's (aligned: its batches; its rings on the heap).
  std::vector<Predictor, xsimd::aligned_allocator<Predictor, 64>> predictors_;
};

}  // namespace

}  // namespace aurora_sweep
