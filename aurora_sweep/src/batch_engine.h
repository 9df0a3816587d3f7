// The `cpu` backend's engine: the model and control templates instantiated on
// xsimd batches of an instruction set `Arch`, so one instruction stream
// advances L simulations (one per SIMD lane). Lanes are independent: each has
// its own combination, iteration count and delay; a lane whose simulation
// ends (early stop or the last iteration) takes the next combination at once,
// so early stops keep paying. Over a link each lane has its own link model
// (the scalar runner's ModelLink, stepped lane by lane): it picks the lane's
// state from the history and the command its drone applies.
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
// lookup from aurora_sim::ardroneStep): xsimd shares the range reduction.
template <class T, class A>
inline void sinCos(const batch<T, A>& x, batch<T, A>& s, batch<T, A>& c) {
  const auto sc = xsimd::sincos(x);
  s = sc.first;
  c = sc.second;
}
}  // namespace xsimd

#include <algorithm>
#include <cmath>
#include <memory>
#include <thread>
#include <vector>

#include "aurora_control/delay_buffer.h"
#include "aurora_sweep/backends.h"
#include "gather_lanes.h"
#include "lane_links.h"

namespace aurora_sweep {

namespace {

// Work is handed out in chunks of consecutive indices (neighbouring
// combinations run for similar lengths).
constexpr long kChunk = 64;

template <typename T, class A>
struct Lanes {
  using Arch = A;
  using B = xsimd::batch<T, Arch>;
  using M = xsimd::batch_bool<T, Arch>;
  static constexpr int L = static_cast<int>(B::size);

  // One lane of a batch (of T or of integers of T's width).
  template <class Batch>
  static void set(Batch& b, int lane, typename Batch::value_type v) {
    alignas(64) typename Batch::value_type tmp[L];
    b.store_aligned(tmp);
    tmp[lane] = v;
    b = Batch::load_aligned(tmp);
  }
  template <class Batch>
  static typename Batch::value_type get(const Batch& b, int lane) {
    alignas(64) typename Batch::value_type tmp[L];
    b.store_aligned(tmp);
    return tmp[lane];
  }
  static void set(M& m, int lane, bool v) {
    B as_number = xsimd::select(m, B(T(1)), B(T(0)));
    set(as_number, lane, v ? T(1) : T(0));
    m = as_number != B(T(0));
  }
  static bool get(const M& m, int lane) {
    alignas(64) bool tmp[L];
    m.store_aligned(tmp);
    return tmp[lane];
  }
};

template <typename T, class Arch, int Capacity, aurora_control::LawType Law>
class BatchWorker {
 public:
  using LaneOps = Lanes<T, Arch>;
  using B = typename LaneOps::B;
  using M = typename LaneOps::M;
  static constexpr int L = LaneOps::L;
  // Integer lanes of the same width (int32 for float, int64 for double), for
  // the per-lane history indices: gathers and scatters instead of lane loops.
  using Int = xsimd::as_integer_t<T>;
  using I = xsimd::batch<Int, typename LaneOps::Arch>;
  // What the history keeps of a state: what the law reads (6 or 12).
  using Input = aurora_control::LawInput<Law>;
  static constexpr int W = Input::kWidth;
  static_assert((Capacity & (Capacity - 1)) == 0, "history capacity must be a power of two");

  BatchWorker(const SweepSpec& spec, std::vector<SimResult>& out, std::atomic<long>& next,
              Progress& progress)
      : grid_(spec.view()), first_(spec.rangeBegin()), total_(spec.rangeEnd()), out_(out), next_(next),
        progress_(progress), setup_(makeSetup<T>(spec)) {
    if (!setup_.ideal_link && laneLinksApply(setup_.config.link)) {
      lane_links_.reset(new LaneLinks<Capacity, T, Arch>(std::lround(setup_.config.link.cmd_timeout / double(setup_.model.Ts))));
    } else if (!setup_.ideal_link) {
      links_.reserve(L);
      for (int l = 0; l < L; ++l) links_.emplace_back(setup_.config.link, 0, 0, double(setup_.model.Ts));
    }
    loop_.model = setup_.model.template cast<B>();
    loop_.plant = loop_.model;  // per lane when the model varies (startLane)
    loop_.criteria = setup_.config.criteria.template cast<B>();
    // The initial state every lane starts from, towards the task's first
    // reference; every lane of sim_ starts there (startLane then sets a lane's run).
    const aurora_control::Reference<T> start = setup_.config.task.at(T(0));
    fresh_.reset(start.pos);
    const B start_pos[3] = {B(start.pos[0]), B(start.pos[1]), B(start.pos[2])};
    sim_.reset(start_pos);
    history_.resize(static_cast<size_t>(Capacity) * W * L);
    alignas(64) Int iota[L];
    for (int l = 0; l < L; ++l) iota[l] = static_cast<Int>(l);
    lane_ = I::load_aligned(iota);
  }

  void run() {
    for (int l = 0; l < L; ++l) {
      active_[l] = false;
      startLane(l);
    }
    while (anyActive()) {
      step();
    }
  }

 private:
  T& hist(long slot, int j, int lane) { return history_[(slot * W + j) * L + lane]; }

  bool takeIndex(long& index) {
    if (chunk_next_ >= chunk_end_) {
      chunk_next_ = next_.fetch_add(kChunk, std::memory_order_relaxed);
      chunk_end_ = std::min(chunk_next_ + kChunk, total_);
      if (chunk_next_ >= total_) return false;
    }
    index = chunk_next_++;
    return true;
  }

  bool anyActive() const {
    for (int l = 0; l < L; ++l) {
      if (active_[l]) return true;
    }
    return false;
  }

  // Lane `lane` of every field of a struct of batches set from the struct of
  // scalars (gains, model parameters, the law's memory: structs of T only).
  template <template <class> class S>
  static void setLane(S<B>& batches, int lane, const S<T>& scalars) {
    constexpr size_t n = sizeof(S<T>) / sizeof(T);
    static_assert(sizeof(S<T>) == n * sizeof(T) && sizeof(S<B>) == n * sizeof(B), "a struct of T only");
    B* to = reinterpret_cast<B*>(&batches);
    const T* from = reinterpret_cast<const T*>(&scalars);
    for (size_t i = 0; i < n; ++i) LaneOps::set(to[i], lane, from[i]);
  }

  // Puts the next combination into lane l (or leaves it idle, rerunning the
  // range's first combination, when the work is done).
  void startLane(int l) {
    long index = first_;
    const bool have = takeIndex(index);
    const Combination c = grid_.decode(have ? index : first_);
    const aurora_control::StudyRun<T> run = studyRun(setup_, c);
    if (lane_links_) {
      lane_links_->start(l, combinationLink(setup_.config.link, run.delay, c), static_cast<uint64_t>(c.key));
    } else if (!setup_.ideal_link) {
      links_[l] = Link(combinationLink(setup_.config.link, run.delay, c), run.delay, static_cast<uint64_t>(c.key),
                       double(setup_.model.Ts));
    }
    active_[l] = have;
    index_[l] = index;
    LaneOps::set(delay_, l, static_cast<Int>(run.delay));
    LaneOps::set(count_, l, 1);  // history holds H(1) ...
    LaneOps::set(start_, l, static_cast<Int>(step_ % Capacity));  // ... at ring slot `step_`
    setLane(loop_.gains, l, run.gains);
    if (setup_.varies_model) setLane(loop_.plant, l, run.plant);
    setLane(sim_.model, l, fresh_.model);
    setLane(sim_.memory, l, fresh_.memory);
    for (int i = 0; i < 4; ++i) LaneOps::set(sim_.metrics.ok[i], l, true);
    LaneOps::set(sim_.metrics.iae, l, T(0));
    LaneOps::set(sim_.metrics.itae, l, T(0));
    LaneOps::set(sim_.metrics.iasc, l, T(0));
    LaneOps::set(sim_.t, l, T(0));
    LaneOps::set(sim_.initial_error, l, fresh_.initial_error);
    const auto h0 = aurora_control::LawSample<T, Law>::fromState(fresh_.model.X);
    const long slot = step_ % Capacity;
    for (int j = 0; j < W; ++j) hist(slot, j, l) = h0.v[j];
  }

  // Lane l's run as a scalar sim, assembled into its result by the runner's
  // own rule (runnerResult).
  void finishLane(int l) {
    aurora_control::LoopState<T, bool> lane;
    for (int i = 0; i < 4; ++i) lane.metrics.ok[i] = LaneOps::get(sim_.metrics.ok[i], l);
    lane.metrics.iae = LaneOps::get(sim_.metrics.iae, l);
    lane.metrics.itae = LaneOps::get(sim_.metrics.itae, l);
    lane.metrics.iasc = LaneOps::get(sim_.metrics.iasc, l);
    for (int i = 0; i < aurora_sim::kStateSize; ++i) lane.model.X[i] = LaneOps::get(sim_.model.X[i], l);
    const long steps = LaneOps::get(count_, l) - 1;
    out_[index_[l] - first_] = compactResult(aurora_control::runnerResult(lane, steps));
    progress_.fetch_add(1, std::memory_order_relaxed);
  }

  // Each lane's iteration k = count - 1.
  void laneSteps(long k[L]) const {
    alignas(64) Int c[L];
    count_.store_aligned(c);
    for (int l = 0; l < L; ++l) k[l] = long(c[l]) - 1;
  }

  // Over a link: each lane's history index (1-based) of the state its
  // controller receives at its iteration k.
  I linkedHistoryIndex() {
    if (lane_links_) return lane_links_->uplink(count_, start_, step_);
    long k[L];
    laneSteps(k);
    return modelLinksUplink<I>(links_, k);
  }

  // Over a link: each lane's sent command U becomes the one its drone
  // receives (the newest arrived, or hover).
  void linkCommands(B U[4]) {
    if (lane_links_) return lane_links_->downlink(count_, start_, step_, U);
    long k[L];
    laneSteps(k);
    modelLinksDownlink(links_, k, U);
  }

  // Loop steps 2-5, the closed loop's iteration k on every lane: both halves
  // at once over an ideal link, else the link between them.
  void loopStep(const B& k, const B xc[aurora_sim::kStateSize]) {
    if (setup_.ideal_link) {
      aurora_control::closedLoopStep<Law>(loop_, setup_.config.task, clamp_, k, xc, sim_);
      return;
    }
    B U[4], applied[4];
    const aurora_control::Reference<B> ref =
        aurora_control::controllerHalf<Law>(loop_, setup_.config.task, clamp_, k, xc, sim_, U);
    linkCommands(U);
    aurora_control::droneHalf(loop_, clamp_, ref, U, sim_, applied);
  }

  void step() {
    // Loop step 1: the delayed sample of each lane, by the delay rule
    // (delay_buffer.h, the same function on integer lanes; k = count) or
    // the lane's link, gathered from the ring. All lanes write at the same
    // slot each step (a plain vector store); lane l's H(i) sits at slot
    // start_l + i - 1.
    const I one(Int(1));
    const I mask(Int(Capacity - 1));
    const I index = setup_.ideal_link ? aurora_control::delayedHistoryIndex(count_, delay_)
                                      : linkedHistoryIndex();  // 1-based
    const I read_base = ((start_ + index - one) & mask) * I(Int(W * L)) + lane_;
    aurora_control::LawSample<B, Law> delayed;
    for (int j = 0; j < W; ++j) delayed.v[j] = gatherLanes<B>(history_.data(), read_base + I(Int(j * L)));
    B xc[aurora_sim::kStateSize];
    delayed.toState(xc);
    loopStep(xsimd::batch_cast<T>(count_ - one), xc);
    // Step 6: append X to every lane's history, H(count + 1) at slot step_ + 1.
    ++step_;
    const long slot = step_ % Capacity;
    for (int j = 0; j < W; ++j) sim_.model.X[Input::state(j)].store_aligned(&hist(slot, j, 0));
    count_ = count_ + one;
    // Lanes whose simulation ended: the last iteration ran, or a check failed.
    const M ended = xsimd::bool_cast(count_ - one >= I(static_cast<Int>(setup_.iterations))) |
                    aurora_control::stoppedEarly(setup_.config.early_stop, sim_.metrics.feasible());
    if (!xsimd::any(ended)) return;
    alignas(64) bool ended_lanes[L];
    ended.store_aligned(ended_lanes);
    for (int l = 0; l < L; ++l) {
      if (ended_lanes[l] && active_[l]) {
        finishLane(l);
        startLane(l);
      }
    }
  }

  const GridView grid_;
  const long first_;  // the range computed: [first_, total_)
  const long total_;
  std::vector<SimResult>& out_;
  std::atomic<long>& next_;
  Progress& progress_;
  long chunk_next_ = 0, chunk_end_ = 0;

  const SimSetup<T> setup_;
  // Each lane's drone and gains; the nominal model the underactuated law inverts.
  aurora_control::LoopParams<B> loop_;
  const aurora_control::ClampPolicy clamp_{setup_.config.clamp_commands, setup_.config.clamp_at_drone};
  aurora_control::LoopState<T, bool> fresh_;
  aurora_control::LoopState<B, M> sim_;
  std::vector<T, xsimd::aligned_allocator<T, 64>> history_;  // [slot][W][lane]
  using Link = aurora_control::ModelLink<Capacity, T>;
  std::unique_ptr<LaneLinks<Capacity, T, Arch>> lane_links_;  // over a link: every lane's, vectorized ...
  std::vector<Link> links_;  // ... or each lane's ModelLink (a geometric jitter); both empty over an ideal link
  bool active_[L];
  long index_[L];
  I delay_ = I(Int(0));  // delay of each lane [samples]
  I count_ = I(Int(1));  // history size of each lane (the iteration k about to run)
  I start_ = I(Int(0));  // ring slot of each lane's H(1)
  I lane_;               // 0, 1, ..., L - 1
  long step_ = 0;        // batch steps done: the ring slot written last
};

}  // namespace

}  // namespace aurora_sweep

#include "formation_lanes.h"

namespace aurora_sweep {

namespace {

template <typename T, class Arch, int Capacity, aurora_control::LawType Law>
void runBatchWith(const SweepSpec& spec, int threads, std::vector<SimResult>& out,
                  Progress& progress) {
  out.resize(spec.rangeSize());
  std::atomic<long> next{spec.rangeBegin()};
  std::vector<std::thread> pool;
  for (int t = 0; t < threads; ++t) {
    pool.emplace_back([&] {
      if (spec.formation()) {
        FormationBatch<T, Arch, Capacity, Law>(spec, out, next, progress).run();
      } else {
        BatchWorker<T, Arch, Capacity, Law>(spec, out, next, progress).run();
      }
    });
  }
  for (auto& th : pool) th.join();
}

}  // namespace

// The whole sweep on `threads` threads with batches of instruction set Arch.
template <class Arch>
void runBatchArch(const SweepSpec& spec, int threads, std::vector<SimResult>& out,
                  Progress& progress) {
  withSweepTypes(spec, [&](auto type, auto capacity, auto law) {
    runBatchWith<decltype(type), Arch, decltype(capacity)::value, decltype(law)::value>(spec, threads, out,
                                                                                      progress);
  });
}

template <class Arch>
int batchLanes(Precision precision) {
  return precision == Precision::kDouble ? int(xsimd::batch<double, Arch>::size)
                                         : int(xsimd::batch<float, Arch>::size);
}

}  // namespace aurora_sweep
