// The `cpu` backend's engine: the model and control templates instantiated on
// xsimd batches of an instruction set `Arch`, so one instruction stream
// advances L simulations (one per SIMD lane). Lanes are independent: each has
// its own combination, iteration count and delay; a lane whose simulation
// ends (early stop or the last iteration) takes the next combination at once,
// so early stops keep paying (LaneSlots, lane_work.h: the formation engine's
// lanes take turns by the same rule). Over a link each lane has its own link
// model (the scalar runner's ModelLink, stepped lane by lane): it picks the
// lane's state from the history and the command its drone applies.
//
// Included only by batch_isa.cpp, which is compiled once per instruction set
// into its own shared library that exports nothing but its entry points
// (CMakeLists, batch_isa.map): every inline function and template of this
// code, the model's and the standard library's, stays inside the library of
// its instruction set. cpu_dispatch.cpp picks the library at run time.
#pragma once

#include <xsimd/xsimd.hpp>

namespace xsimd {
// The model's sin and cos of one angle in one go (found by argument-dependent
// lookup from the AR.Drone's model step): xsimd shares the range reduction.
// A lane that is not finite (a diverged flight runs on beside the others)
// takes NaN (x - x: the NaN its sin and cos give), without the call: xsimd
// reduces a batch with such a lane element by element, at a scalar's cost.
template <class T, class A>
inline void sinCos(const batch<T, A>& x, batch<T, A>& s, batch<T, A>& c) {
  const auto bad = !xsimd::isfinite(x);
  const auto sc = xsimd::sincos(xsimd::select(bad, batch<T, A>(T(0)), x));
  const batch<T, A> nan = x - x;
  s = xsimd::select(bad, nan, sc.first);
  c = xsimd::select(bad, nan, sc.second);
}
// Each lane's iteration number as a batch of T (aurora_control::loopIteration).
template <class T, class A>
inline void iterationNumber(const batch<as_integer_t<T>, A>& k, batch<T, A>& out) {
  out = batch_cast<T>(k);
}
}  // namespace xsimd

#include <algorithm>
#include <cmath>
#include <memory>
#include <thread>
#include <type_traits>
#include <vector>

#include "aurora_sweep/backends.h"
#include "lane_history.h"
#include "lane_predictor.h"
#include "lane_work.h"

namespace aurora_sweep {

namespace {

// Lane l of a loop state of batches set from one of scalars (a lane's
// fresh run: BatchWorker's next combination, FormationBatch's robots).
template <class LaneOps, class Data, typename T>
void setLoopLane(aurora_control::LoopState<Data, typename LaneOps::B, typename LaneOps::M>& to, int l,
                 const aurora_control::LoopState<Data, T, bool>& from) {
  LaneOps::setFields(to.model, l, from.model);
  LaneOps::setFields(to.memory, l, from.memory);
  for (int i = 0; i < aurora_control::kPositioningChecks; ++i) LaneOps::set(to.metrics.ok[i], l, from.metrics.ok[i]);
  LaneOps::set(to.metrics.iae, l, from.metrics.iae);
  LaneOps::set(to.metrics.itae, l, from.metrics.itae);
  LaneOps::set(to.metrics.iasc, l, from.metrics.iasc);
  LaneOps::set(to.t, l, from.t);
  LaneOps::set(to.initial_error, l, from.initial_error);
}

// Lane l of a loop state of batches, as one of scalars.
template <class LaneOps, class Data>
aurora_control::LoopState<Data, typename LaneOps::B::value_type, bool> loopLane(
    const aurora_control::LoopState<Data, typename LaneOps::B, typename LaneOps::M>& from, int l) {
  aurora_control::LoopState<Data, typename LaneOps::B::value_type, bool> to;
  LaneOps::getFields(from.model, l, to.model);
  LaneOps::getFields(from.memory, l, to.memory);
  for (int i = 0; i < aurora_control::kPositioningChecks; ++i) to.metrics.ok[i] = LaneOps::get(from.metrics.ok[i], l);
  to.metrics.iae = LaneOps::get(from.metrics.iae, l);
  to.metrics.itae = LaneOps::get(from.metrics.itae, l);
  to.metrics.iasc = LaneOps::get(from.metrics.iasc, l);
  to.t = LaneOps::get(from.t, l);
  to.initial_error = LaneOps::get(from.initial_error, l);
  return to;
}

// Runs the combinations [first, total) of `grid` on the lanes of batches of
// instruction set Arch, law `Law` on its vehicle (setup), histories of
// `capacity` samples; each lane's iteration is loopIteration (closed_loop.h)
// over lane policies (lane_history.h), with the state predictor when
// `Predicted` (lane_predictor.h: the history then keeps whole states).
template <typename T, class Arch, class Law, bool Predicted = false>
class BatchWorker {
 public:
  using LaneOps = Lanes<T, Arch>;
  using B = typename LaneOps::B;
  using M = typename LaneOps::M;
  static constexpr int L = LaneOps::L;
  using Vehicle = typename Law::Vehicle;
  using Data = typename Law::Data;
  using Reader = typename std::conditional<Predicted, aurora_control::WholeStateReader<Vehicle>, Law>::type;
  using History = LaneHistory<Reader, T, Arch>;
  using Predictor = LanePredictor<Vehicle, T, Arch>;
  using Int = typename History::Int;
  using I = typename History::I;

  BatchWorker(const SimSetup<Vehicle, T>& setup, int capacity, LaneWork& work)
      : work_(work), setup_(setup), capacity_(capacity) {
    history_.allocate(capacity_);
    if (!setup_.ideal_link) {
      links_.reset(new LaneModelLinks<Reader, T, Arch>(setup_.config.link, double(setup_.model.Ts), history_));
    }
    loop_.model = setup_.model.template cast<B>();
    loop_.plant = loop_.model;  // per lane when the model varies (startLane)
    loop_.criteria = setup_.config.criteria.template cast<B>();
    // The initial state every lane starts from, towards the task's first
    // reference; every lane of sim_ starts there (startLane then sets a lane's run).
    const aurora_control::Reference<T> start = setup_.config.task.at(T(0));
    fresh_.reset(setup_.model, start.pos);
    const B start_pos[3] = {B(start.pos[0]), B(start.pos[1]), B(start.pos[2])};
    sim_.reset(loop_.model, start_pos);
  }

  void run() {
    refill();
    while (slots_.anyCounts()) step();
  }

 private:
  // Each free lane takes the next combination (or, when the work is done,
  // reruns the range's first, its result dropped). Out of line, as turn().
  [[gnu::noinline]] void refill() {
    slots_.refill([&](long& index) { return work_.take(index); }, work_.first(),
                  [&](int l, long index, bool) { startLane(l, index); });
  }

  // Lane l starts combination `index`.
  void startLane(int l, long index) {
    const Combination c = work_.decode(index);
    const aurora_control::StudyRun<Data, T> run = studyRun<Law>(setup_, c);
    long command_delay = 0;  // over the ideal link none
    if (links_) {
      const aurora_control::LinkParams link = combinationLink(setup_.config.link, run.delay, c);
      links_->startLane(l, link, run.delay, static_cast<uint64_t>(c.key), double(setup_.model.Ts));
      command_delay = link.downlink.delay;
    }
    predictor_.startLane(l, command_delay);
    LaneOps::set(ideal_.delay, l, static_cast<Int>(run.delay));
    history_.startLane(l);
    LaneOps::setFields(loop_.gains, l, run.gains);
    if (setup_.varies_model) LaneOps::setFields(loop_.plant, l, run.plant);
    setLoopLane<LaneOps>(sim_, l, fresh_);
  }

  // Lane l's run as a scalar sim, assembled into its result by the runner's
  // own rule (runnerResult).
  SimResult laneResult(int l) const {
    aurora_control::LoopState<Data, T, bool> lane;
    for (int i = 0; i < aurora_control::kPositioningChecks; ++i) lane.metrics.ok[i] = LaneOps::get(sim_.metrics.ok[i], l);
    lane.metrics.iae = LaneOps::get(sim_.metrics.iae, l);
    lane.metrics.itae = LaneOps::get(sim_.metrics.itae, l);
    lane.metrics.iasc = LaneOps::get(sim_.metrics.iasc, l);
    for (int i = 0; i < Vehicle::kStates; ++i) lane.model.X[i] = LaneOps::get(sim_.model.X[i], l);
    const long steps = LaneOps::get(history_.size(), l);
    return compactResult(aurora_control::runnerResult(lane, steps));
  }

  // Each lane's iteration k (loopIteration), over the delay rule or its
  // link, with the predictor or without.
  M iterate() {
    const std::integral_constant<bool, Predicted> predicted;
    if (links_) return iterateOver(*links_, predicted);
    return iterateOver(ideal_, predicted);
  }
  template <class H, class Link>
  M iterationOver(H& history, Link& link) {
    const I k = history_.size();  // a copy: the iteration's push moves the count
    const aurora_control::NoObserver none;
    return aurora_control::loopIteration<Law>(loop_, setup_.config.task, clamp_, setup_.config.early_stop, k,
                                              history, link, sim_, none);
  }
  template <class Link>
  M iterateOver(Link& link, std::false_type) {
    return iterationOver(history_, link);
  }
  template <class Link>
  M iterateOver(Link& link, std::true_type) {
    PredictedLaneHistory<History, Predictor> history{history_, predictor_};
    PredictedLaneLink<Link, Predictor> predicted{link, predictor_};
    return iterationOver(history, predicted);
  }

  // One iteration on every lane; a lane whose run ended (its last
  // iteration ran, or a check failed with early stop) takes the next.
  void step() {
    const M stopped = iterate();  // before the count below: the iteration pushes
    const M last = xsimd::bool_cast(history_.size() >= I(static_cast<Int>(setup_.iterations)));
    if (xsimd::any(stopped | last)) turn(stopped, last);
  }
  // The ended lanes give their result and take the next. This rare path and
  // refill() are out of line so that they do not use up the inlining the
  // iteration needs: inlined, the thesis grid ran about 12 % slower
  // (controllerHalf and the history's reads were left as calls).
  [[gnu::noinline]] void turn(const M& stopped, const M& last) {
    alignas(64) bool stopped_lanes[L], last_lanes[L];
    stopped.store_aligned(stopped_lanes);
    last.store_aligned(last_lanes);
    slots_.end(stopped_lanes, last_lanes, [&](int l) { return laneResult(l); });
    refill();
  }

  LaneWork& work_;
  const SimSetup<Vehicle, T> setup_;
  const int capacity_;  // the history's (limits.h, historyCapacity)
  // Each lane's vehicle and gains; the nominal model the law inverts.
  aurora_control::LoopParams<Data, B> loop_;
  const aurora_control::ClampPolicy clamp_{setup_.config.clamp_commands, setup_.config.clamp_at_drone};
  aurora_control::LoopState<Data, T, bool> fresh_;
  aurora_control::LoopState<Data, B, M> sim_;
  History history_;
  aurora_control::IdealLinkOf<I> ideal_{I(Int(0))};        // each lane's delay [samples], over the delay rule
  std::unique_ptr<LaneModelLinks<Reader, T, Arch>> links_;  // or each lane's link model
  // With Predicted, in this object (its batches need the alignment the
  // engine's C++14 `new` does not give; its rings are on the heap).
  typename std::conditional<Predicted, Predictor, NoLanePredictor>::type predictor_{
      setup_.predictor, setup_.predictor_model, vehicleStart<Vehicle, T>(setup_.model), setup_.config.clamp_at_drone,
      2 * capacity_};
  LaneSlots<L> slots_{work_};
};

}  // namespace

}  // namespace aurora_sweep

#include "formation_lanes.h"

namespace aurora_sweep {

namespace {

// work() on each of `threads` threads.
template <class Work>
void onThreads(int threads, Work&& work) {
  std::vector<std::thread> pool;
  for (int t = 0; t < threads; ++t) pool.emplace_back(work);
  for (auto& th : pool) th.join();
}

// work(lanes) on each of `threads` threads, each with its LaneWork of the
// spec's range.
template <class Work>
void onRange(const SweepSpec& spec, int threads, std::vector<SimResult>& out, Progress& progress, Work&& work) {
  out.resize(spec.rangeSize());
  std::atomic<long> next{spec.rangeBegin()};
  const GridView grid = spec.view();
  onThreads(threads, [&] {
    LaneWork lanes(grid, spec.rangeBegin(), spec.rangeEnd(), out, next, progress);
    work(lanes);
  });
}

template <typename T, class Arch, class Law>
void runBatchWith(const SweepSpec& spec, int capacity, int threads, std::vector<SimResult>& out, Progress& progress) {
  const auto setup = makeSetup<typename Law::Vehicle, T>(spec);
  onRange(spec, threads, out, progress, [&](LaneWork& lanes) {
    if (spec.predicting()) {
      BatchWorker<T, Arch, Law, true>(setup, capacity, lanes).run();
    } else {
      BatchWorker<T, Arch, Law>(setup, capacity, lanes).run();
    }
  });
}

template <typename T, class Arch, class Law, template <typename> class Shape>
void runFormationBatchWith(const SweepSpec& spec, const ShapeRun<double, Shape, typename Law::Data>& run, int capacity,
                           int threads, std::vector<SimResult>& out, Progress& progress) {
  const FormationSetup<T, Shape, typename Law::Data> setup = makeFormationSetup<T>(spec, run);
  withFormationPredictor(run, [&](auto predicted) {
    onRange(spec, threads, out, progress, [&](LaneWork& lanes) {
      FormationBatch<T, Arch, Law, Shape, decltype(predicted)::value>(setup, capacity, lanes).run();
    });
  });
}

}  // namespace

// The whole sweep on `threads` threads with batches of instruction set Arch.
template <class Arch>
void runBatchArch(const SweepSpec& spec, int threads, std::vector<SimResult>& out,
                  Progress& progress) {
  // The history's capacity the types' dispatch chose, as a run-time value
  // here (one engine for all).
  if (spec.formation()) {
    return withFormationTypes(spec, [&](auto type, auto capacity, auto law, const auto& run) {
      runFormationBatchWith<decltype(type), Arch, decltype(law)>(spec, run, decltype(capacity)::value, threads, out,
                                                                 progress);
    });
  }
  withSweepTypes(spec, [&](auto type, auto capacity, auto law) {
    runBatchWith<decltype(type), Arch, decltype(law)>(spec, decltype(capacity)::value, threads, out, progress);
  });
}

template <class Arch>
int batchLanes(Precision precision) {
  return precision == Precision::kDouble ? int(xsimd::batch<double, Arch>::size)
                                         : int(xsimd::batch<float, Arch>::size);
}

}  // namespace aurora_sweep
