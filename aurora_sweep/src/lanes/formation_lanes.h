// The `cpu` backend's engine for formation sweeps (docs/formation.md,
// "Formation sweeps"): L formations at once, one per SIMD lane, each at its
// own tick. A lane whose formation ended (its last tick, or a failed check
// with early stop) takes the next combination of the batch's law, as
// BatchWorker's lanes do (LaneSlots, lane_work.h); it starts on a tick
// where the layer's periods fall as on every other lane's (LayerSchedule's
// cycle), so that the lanes share when the layer runs, each at its own
// period's time and Qd. A lane's result is taken at the tick it ended. The
// tick is the scalar runner's (formation_runner.h's formationTick and
// formation_checks.h on batches); each drone's delayed
// state comes from receiveState (closed_loop.h) over the lane policies of
// lane_history.h: its LaneHistory and the delay rule on integer lanes or its
// lanes' link models; with `Predicted`, each drone's LanePredictor
// (lane_predictor.h) over its whole-state history, as formation_runner.h's
// runPredictedFormationOver. Included by batch_engine.h only.
#pragma once

#include <algorithm>
#include <memory>
#include <stdexcept>
#include <utility>
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
  using Lane = ShapeRun<T, Shape, Data>;
  using Layer = aurora_control::LayerOf<B, LaneShape>;
  using Metrics = aurora_control::FormationMetrics<B, M, LaneShape>;

  // `capacity`: each drone's history's (limits.h, historyCapacity).
  FormationBatch(const FormationSetup<T, Shape, Data>& setup, int capacity, LaneWork& work)
      : work_(work), setup_(setup), period_(setup.run.schedule.period(setup.run.drone[0].plant.Ts)),
        cycle_(scheduleCycle(setup.run.schedule)), periods_(periodsOf(setup, cycle_)) {
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
    for (int d = 0; d < D; ++d) {  // each lane's command delay is its run's (startLane)
      const auto p = aurora_control::dronePredictor(setup_.run, d);
      predictors_.emplace_back(p.form, p.model, vehicleStart<Vehicle, T>(p.model), p.path.clamp, 2 * long(capacity));
    }
  }

  // Batches of one layer law each (a triangle sweep's formation_law: the
  // layer branches on it), until no combination is left.
  void run() {
    long first = 0;
    while (work_.peek(first)) runBatch(first);
  }

 private:
  // The formations of a batch's lanes.
  struct Flights {
    aurora_control::FormationRun<B, LaneShape, Data> run;
    Layer layer;
    aurora_control::DroneParams<B, Data> params[D];
    aurora_control::DroneState<B, M, Data> state[D];
    Metrics metrics;
    // Every lane flying `lane`'s formation, started (each lane's own then set by startLane).
    Flights(const Lane& lane, const T& period) : run(broadcast(lane)), layer(run.law, run.gains, B(period)) {
      aurora_control::startFormation(run, params, state, layer);
      metrics.reset();
    }
  };

  // What every lane shares: the drones' models and starts, the law, the
  // period (the file's; the sweep varies none of them); their gains until
  // each lane's are set.
  static aurora_control::FormationRun<B, LaneShape, Data> broadcast(const Lane& s) {
    aurora_control::FormationRun<B, LaneShape, Data> run;
    for (int d = 0; d < D; ++d) castFormationDrone(s.drone[d], run.drone[d]);
    castFormationLayer(s, run);
    return run;
  }

  // The robot steps after which the layer's periods fall again as at step 0
  // (p / gcd(p, q) of LayerSchedule): a lane starts on a multiple of it.
  static long scheduleCycle(const aurora_control::LayerSchedule<T>& s) {
    long a = s.period_ticks, b = s.step_ticks;
    while (b != 0) a %= b, std::swap(a, b);
    return s.period_ticks / a;
  }

  Lane laneOf(long index) const { return formationCombination<Law>(setup_, work_.decode(index)); }

  // The batch of the layer law of combination `first`: its lanes refilled
  // with combinations of that law until the next is another's; then each
  // lane runs out.
  void runBatch(long first) {
    const Lane spare = laneOf(first);
    Flights f(spare, period_);
    for (int d = 0; d < D; ++d) fresh_[d] = loopLane<LaneOps>(f.state[d], 0);
    for (int l = 0; l < L; ++l) start_[l] = 0, offset_[l] = 0;
    starts_ = I(Int(0));
    slots_.clear();
    for (g_ = 0;; ++g_) {
      if (g_ % cycle_ == 0) refill(f, first, spare);
      if (!slots_.anyCounts()) return;
      tick(f);
      endLanes(f);
    }
  }

  // Each free lane takes the next combination of the batch's law (that of
  // `first`); with none left it reruns `first`, its result dropped, so that
  // no lane runs beyond its run's ticks for long.
  void refill(Flights& f, long first, const Lane& spare) {
    Lane taken;
    const auto take = [&](long& index) {
      if (!work_.peek(index)) return false;
      taken = laneOf(index);
      return taken.law == spare.law && work_.take(index);
    };
    slots_.refill(take, first, [&](int l, long index, bool counts) {
      startLane(l, f, index, counts ? taken : spare);
    });
  }

  // Lane l starts `lane`, the formation of combination `index`: its
  // robots' gains, delays, links and predictors, its layer and robots as a
  // batch of its own would start them, its metrics reset, its tick 0. (The
  // batch's run keeps what every lane shares: the layer's and the robots'
  // gains in force are the layer's and params'.)
  void startLane(int l, Flights& f, long index, const Lane& lane) {
    const Combination c = work_.decode(index);
    aurora_control::FormationGains<B, N> gains;
    for (int i = 0; i < N; ++i) gains.k1[i] = B(lane.gains.k1[i]), gains.k2[i] = B(lane.gains.k2[i]);
    Layer layer(f.run.law, gains, B(period_));
    aurora_control::startLayer(f.run, layer);
    LaneOps::copyLane(f.layer, layer, l);
    for (int d = 0; d < D; ++d) {
      LaneOps::setFields(f.params[d].gains, l, lane.drone[d].gains);  // the robot gains the sweep gives
      setLoopLane<LaneOps>(f.state[d], l, fresh_[d]);
      LaneOps::set(ideal_[d].delay, l, static_cast<Int>(lane.drone[d].delay));
      history_[d].startLane(l);
      if (Predicted) predictors_[d].startLane(l, aurora_control::dronePredictor(lane, d).path.delay);
      if (links_[d]) {
        links_[d]->startLane(l, lane.drone[d].link, lane.drone[d].delay, formationLinkKey<OneLane>(c, d),
                             double(lane.drone[d].plant.Ts));
      }
    }
    aurora_control::FormationMetrics<T, bool, OneLane> reset;
    reset.reset();
    setMetricsLane(f.metrics, l, reset);
    start_[l] = g_, offset_[l] = setup_.run.schedule.periodBefore(g_);  // g_ on the cycle: a period is due
    LaneOps::set(starts_, l, static_cast<Int>(g_));
  }

  // Steps 1-2 of tick k for each drone (closed_loop.h, receiveState): its
  // history keeps X_k, its link (the delay rule, or the lanes' link models)
  // picks the state it receives; `at`: each lane's tick.
  void receiveStates(const I& at, const aurora_control::DroneState<B, M, Data>* state, B xc[D][S]) {
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
  void downlink(int d, const I& at, B U[Vehicle::kInputs]) {
    if (Predicted) predictors_[d].sent(U);
    if (links_[d]) links_[d]->downlink(at, U, U);
  }

  // The layer's periods a lane can reach (its last tick, and the few it
  // runs on while it waits for the schedule's cycle): each one's time t and
  // Qd (in T, the scalar judge's: desiredBefore) and the positions of Qd,
  // computed once; every lane reads its own.
  struct Period {
    T t, qd[N], xd[N];
  };
  static std::vector<Period> periodsOf(const FormationSetup<T, Shape, Data>& setup, long cycle) {
    std::vector<Period> periods;
    for (long k = 0; k < setup.iterations + 2 * cycle; ++k) {
      Period p{T(0), {}, {}};
      if (!aurora_control::desiredBefore(setup.run, k, p.t, p.qd)) continue;
      OneLane::positions(p.qd, p.xd);
      periods.push_back(p);  // each period falls before one step (q <= p): period n is entry n
    }
    return periods;
  }

  // Whether the layer runs before each lane's tick and, when it does, each
  // lane's period time t and Qd, and the positions of Qd the metrics hold
  // (Xd_). Every lane's periods fall alike (a lane starts on the schedule's
  // cycle, `offset_` periods after the batch's tick 0); lanes that started
  // together share theirs.
  bool desired(B& t, B Qd[N]) {
    const long now = setup_.run.schedule.periodBefore(g_);
    t = B(T(0));
    if (now < 0) return false;
    bool shared = true;
    for (int l = 1; l < L; ++l) shared = shared && offset_[l] == offset_[0];
    if (shared) {
      const Period& p = period(now - offset_[0]);
      t = B(p.t);
      for (int i = 0; i < N; ++i) Qd[i] = B(p.qd[i]), Xd_[i] = B(p.xd[i]);
      return true;
    }
    alignas(64) T ts[L], qd[N][L], xd[N][L];
    for (int l = 0; l < L; ++l) {
      const Period& p = period(now - offset_[l]);
      ts[l] = p.t;
      for (int i = 0; i < N; ++i) qd[i][l] = p.qd[i], xd[i][l] = p.xd[i];
    }
    t = B::load_aligned(ts);
    for (int i = 0; i < N; ++i) Qd[i] = B::load_aligned(qd[i]), Xd_[i] = B::load_aligned(xd[i]);
    return true;
  }
  const Period& period(long n) const {
    if (n < 0 || n >= long(periods_.size())) throw std::logic_error("a formation lane past its layer's periods");
    return periods_[size_t(n)];
  }

  // Each lane's tick.
  void tick(Flights& f) {
    const T Ts = setup_.run.drone[0].plant.Ts;
    const I at = I(static_cast<Int>(g_)) - starts_;  // each lane's tick
    B k, xc[D][S], X[N], Qd[N], t;
    xsimd::iterationNumber(at, k);
    receiveStates(at, f.state, xc);
    aurora_control::modelPositions<LaneShape, Vehicle>(f.state, X);
    const bool due = desired(t, Qd);
    aurora_control::DroneStep<B, Data> step[D];
    aurora_control::formationTick<Law>(f.params, setup_.run.clamp, f.layer, due ? Qd : nullptr, t, k, xc, f.state, step,
                                       [&](int d, B U[Vehicle::kInputs]) { downlink(d, at, U); });
    f.metrics.add(criteria_, X, Xd_, aurora_control::taskTime(k, B(Ts)), B(Ts));
    f.metrics.template addCommands<Vehicle>(criteria_, f.params, step);
  }

  // Lanes whose run ended at this tick (its last, or a failed check with
  // early stop) give their result.
  void endLanes(const Flights& f) {
    alignas(64) bool ok[L];
    f.metrics.feasible().store_aligned(ok);
    bool stopped[L], last[L];
    for (int l = 0; l < L; ++l) stopped[l] = setup_.early_stop && !ok[l], last[l] = ticks(l) >= setup_.iterations;
    slots_.end(stopped, last, [&](int l) { return laneResult(l, f); });
  }
  long ticks(int l) const { return g_ - start_[l] + 1; }  // lane l's, this one included

  // Lane l's metrics as the scalar judge's, and back.
  static aurora_control::FormationMetrics<T, bool, OneLane> metricsLane(const Metrics& m, int l) {
    aurora_control::FormationMetrics<T, bool, OneLane> lane;
    lane.iae_position = LaneOps::get(m.iae_position, l), lane.iae_shape = LaneOps::get(m.iae_shape, l);
    lane.max_position = LaneOps::get(m.max_position, l), lane.max_shape = LaneOps::get(m.max_shape, l);
    lane.closest = LaneOps::get(m.closest, l), lane.ground_command = LaneOps::get(m.ground_command, l);
    for (int i = 0; i < m.kChecks; ++i) lane.ok[i] = LaneOps::get(m.ok[i], l);
    return lane;
  }
  static void setMetricsLane(Metrics& m, int l, const aurora_control::FormationMetrics<T, bool, OneLane>& lane) {
    LaneOps::set(m.iae_position, l, lane.iae_position), LaneOps::set(m.iae_shape, l, lane.iae_shape);
    LaneOps::set(m.max_position, l, lane.max_position), LaneOps::set(m.max_shape, l, lane.max_shape);
    LaneOps::set(m.closest, l, lane.closest), LaneOps::set(m.ground_command, l, lane.ground_command);
    for (int i = 0; i < m.kChecks; ++i) LaneOps::set(m.ok[i], l, lane.ok[i]);
  }

  SimResult laneResult(int l, const Flights& f) const {
    T X[N];
    for (int d = 0; d < D; ++d) {
      for (int i = 0; i < 3; ++i) X[3 * d + i] = LaneOps::get(f.state[d].model.X[Vehicle::kPosition + i], l);
    }
    return formationResult(metricsLane(f.metrics, l), ticks(l), aurora_control::closestPair<OneLane>(X));
  }

  LaneWork& work_;
  const FormationSetup<T, Shape, Data> setup_;
  const aurora_control::FormationCriteria<B> criteria_ = setup_.criteria.template cast<B>();
  const T period_;    // [s] the layer's T_F
  const long cycle_;  // [ticks] a lane starts on a multiple of it (scheduleCycle)
  const std::vector<Period> periods_;  // by period number
  History history_[D];                             // each drone's, each lane at its own tick
  aurora_control::IdealLinkOf<I> ideal_[D];         // each drone's delay [samples] per lane, over the delay rule
  std::unique_ptr<Links> links_[D];                // or each drone's lanes' link models
  aurora_control::LoopState<Data, T, bool> fresh_[D];  // a robot at its start (every lane's alike)
  B Xd_[N];  // the positions of the layer's held Qd, per lane
  long g_ = 0;       // the batch's tick
  long start_[L];    // each lane's tick 0, on the batch's (its tick: g_ - start_)
  I starts_;         // the same, as integer lanes
  long offset_[L];   // the layer's periods before start_ (its period n: the batch's n - offset_)
  LaneSlots<L> slots_{work_};
  // With Predicted, each drone's (aligned: its batches; its rings on the heap).
  std::vector<Predictor, xsimd::aligned_allocator<Predictor, 64>> predictors_;
};

}  // namespace

}  // namespace aurora_sweep
