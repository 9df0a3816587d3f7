// The `cpu` backend's engine: the model and control templates instantiated on
// xsimd batches of an instruction set `Arch`, so one instruction stream
// advances L simulations (one per SIMD lane). Lanes are independent: each has
// its own combination, iteration count and delay; a lane whose simulation
// ends (early stop or the last iteration) takes the next combination at once,
// so early stops keep paying.
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
#include <thread>
#include <vector>

#include "aurora_control/delay_buffer.h"
#include "aurora_sweep/backends.h"

namespace aurora_sweep {

namespace {

// Work is handed out in chunks of consecutive indices (neighbouring
// combinations run for similar lengths).
constexpr long kChunk = 64;

// Per-lane loads at per-lane indices. xsimd 8.1 sends the AVX-512 float
// gather to its element-wise generic code (over half the engine's time under
// perf); these overloads issue the gather instructions themselves.
template <class B, class I>
inline B gatherLanes(const typename B::value_type* base, const I& index) {
  return B::gather(base, index);
}
#if defined(__AVX512F__)
template <>
inline xsimd::batch<float, xsimd::avx512bw> gatherLanes(const float* base,
                                                       const xsimd::batch<int32_t, xsimd::avx512bw>& index) {
  return _mm512_i32gather_ps(index, base, sizeof(float));
}
template <>
inline xsimd::batch<double, xsimd::avx512bw> gatherLanes(const double* base,
                                                        const xsimd::batch<int64_t, xsimd::avx512bw>& index) {
  return _mm512_i64gather_pd(index, base, sizeof(double));
}
#endif

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

template <typename T, class Arch, int Capacity>
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
  static_assert((Capacity & (Capacity - 1)) == 0, "history capacity must be a power of two");

  BatchWorker(const SweepSpec& spec, std::vector<SimResult>& out, std::atomic<long>& next,
              Progress& progress)
      : grid_(spec.view()), first_(spec.rangeBegin()), total_(spec.rangeEnd()), out_(out), next_(next),
        progress_(progress) {
    const SimSetup<T> scalar = makeSetup<T>(spec);
    params_ = scalar.params.template cast<B>();
    criteria_ = scalar.config.criteria.template cast<B>();
    clamp_ = spec.clamp_commands;
    early_stop_ = spec.early_stop;
    iterations_ = scalar.iterations;
    for (int i = 0; i < 3; ++i) {
      desired_[i] = B(T(spec.desired[i]));
      desired_scalar_[i] = T(spec.desired[i]);
    }
    fresh_.reset(desired_scalar_);  // the initial state every lane starts from
    sim_.reset(desired_);
    history_.resize(static_cast<size_t>(Capacity) * 6 * L);
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
  T& hist(long slot, int j, int lane) { return history_[(slot * 6 + j) * L + lane]; }

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

  // Puts the next combination into lane l (or leaves it idle at the initial
  // state with zero gains when the work is done).
  void startLane(int l) {
    long index = 0;
    const bool have = takeIndex(index);
    const Combination c = have ? grid_.decode(index) : Combination{0.0, 0.0, 0};
    active_[l] = have;
    index_[l] = index;
    LaneOps::set(delay_, l, static_cast<Int>(c.delay));
    LaneOps::set(count_, l, 1);  // history holds H(1) ...
    LaneOps::set(start_, l, static_cast<Int>(step_ % Capacity));  // ... at ring slot `step_`
    LaneOps::set(kp_, l, T(c.kp));
    LaneOps::set(kd_, l, T(c.kd));
    auto& m = sim_.model;
    for (int i = 0; i < aurora_sim::kStateSize; ++i) LaneOps::set(m.X[i], l, fresh_.model.X[i]);
    for (int i = 0; i < 4; ++i) {
      LaneOps::set(m.Xa[i], l, fresh_.model.Xa[i]);
      LaneOps::set(m.Xr[i], l, fresh_.model.Xr[i]);
      LaneOps::set(m.Xra[i], l, fresh_.model.Xra[i]);
      LaneOps::set(m.W[i], l, fresh_.model.W[i]);
      LaneOps::set(sim_.metrics.ok[i], l, true);
    }
    LaneOps::set(sim_.metrics.iae, l, T(0));
    LaneOps::set(sim_.metrics.itae, l, T(0));
    LaneOps::set(sim_.metrics.iasc, l, T(0));
    LaneOps::set(sim_.t, l, T(0));
    LaneOps::set(sim_.initial_error, l, fresh_.initial_error);
    const auto h0 = aurora_control::PosVel<T>::fromState(fresh_.model.X);
    const long slot = step_ % Capacity;
    for (int j = 0; j < 3; ++j) {
      hist(slot, j, l) = h0.pos[j];
      hist(slot, 3 + j, l) = h0.vel[j];
    }
  }

  // Lane l's run as a scalar sim, assembled into its result by the runner's
  // own rule (runnerResult).
  void finishLane(int l) {
    aurora_control::PositioningSim<T, bool> lane;
    for (int i = 0; i < 4; ++i) lane.metrics.ok[i] = LaneOps::get(sim_.metrics.ok[i], l);
    lane.metrics.iae = LaneOps::get(sim_.metrics.iae, l);
    lane.metrics.itae = LaneOps::get(sim_.metrics.itae, l);
    lane.metrics.iasc = LaneOps::get(sim_.metrics.iasc, l);
    for (int i = 0; i < aurora_sim::kStateSize; ++i) lane.model.X[i] = LaneOps::get(sim_.model.X[i], l);
    const long steps = LaneOps::get(count_, l) - 1;
    out_[index_[l] - first_] = compactResult(aurora_control::runnerResult(lane, steps));
    progress_.fetch_add(1, std::memory_order_relaxed);
  }

  void step() {
    // Loop step 1: the delayed sample of each lane, by the delay rule
    // (delay_buffer.h, the same function on integer lanes; k = count),
    // gathered from the ring. All lanes write at the same slot each step (a
    // plain vector store); lane l's H(i) sits at slot start_l + i - 1.
    const I one(Int(1));
    const I mask(Int(Capacity - 1));
    const I index = aurora_control::delayedHistoryIndex(count_, delay_);  // 1-based
    const I read_base = ((start_ + index - one) & mask) * I(Int(6 * L)) + lane_;
    aurora_control::PosVel<B> xc;
    for (int j = 0; j < 3; ++j) {
      xc.pos[j] = gatherLanes<B>(history_.data(), read_base + I(Int(j * L)));
      xc.vel[j] = gatherLanes<B>(history_.data(), read_base + I(Int((3 + j) * L)));
    }
    // Steps 2-5, the shared iteration.
    const aurora_control::PdGains<B> gains{kp_, kd_};
    B U[4];
    aurora_control::positioningIteration(params_, criteria_, gains, desired_, clamp_, xc, sim_, U);
    // Step 6: append X to every lane's history, H(count + 1) at slot step_ + 1.
    ++step_;
    const long slot = step_ % Capacity;
    for (int j = 0; j < 3; ++j) {
      sim_.model.X[aurora_sim::kX + j].store_aligned(&hist(slot, j, 0));
      sim_.model.X[aurora_sim::kVx + j].store_aligned(&hist(slot, 3 + j, 0));
    }
    count_ = count_ + one;
    // Lanes whose simulation ended: the last iteration ran, or a check failed.
    const M ended = xsimd::bool_cast(count_ - one >= I(static_cast<Int>(iterations_))) |
                    aurora_control::stoppedEarly(early_stop_, sim_.metrics.feasible());
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

  aurora_sim::ArdroneParams<B> params_;
  aurora_control::FeasibilityCriteria<B> criteria_;
  bool clamp_ = false, early_stop_ = true;
  long iterations_ = 0;
  B desired_[3];
  T desired_scalar_[3];
  aurora_control::PositioningSim<T, bool> fresh_;
  aurora_control::PositioningSim<B, M> sim_;
  B kp_ = B(T(0)), kd_ = B(T(0));
  std::vector<T, xsimd::aligned_allocator<T, 64>> history_;  // [slot][6][lane]
  bool active_[L];
  long index_[L];
  I delay_ = I(Int(0));  // delay of each lane [samples]
  I count_ = I(Int(1));  // history size of each lane (the iteration k about to run)
  I start_ = I(Int(0));  // ring slot of each lane's H(1)
  I lane_;               // 0, 1, ..., L - 1
  long step_ = 0;        // batch steps done: the ring slot written last
};

template <typename T, class Arch, int Capacity>
void runBatchWith(const SweepSpec& spec, int threads, std::vector<SimResult>& out,
                  Progress& progress) {
  out.resize(spec.rangeSize());
  std::atomic<long> next{spec.rangeBegin()};
  std::vector<std::thread> pool;
  for (int t = 0; t < threads; ++t) {
    pool.emplace_back([&] { BatchWorker<T, Arch, Capacity>(spec, out, next, progress).run(); });
  }
  for (auto& th : pool) th.join();
}

}  // namespace

// The whole sweep on `threads` threads with batches of instruction set Arch.
template <class Arch>
void runBatchArch(const SweepSpec& spec, int threads, std::vector<SimResult>& out,
                  Progress& progress) {
  aurora_control::withHistoryCapacity(spec.max_delay, [&](auto capacity) {
    constexpr int kCapacity = decltype(capacity)::value;
    if (spec.precision == Precision::kDouble) {
      runBatchWith<double, Arch, kCapacity>(spec, threads, out, progress);
    } else {
      runBatchWith<float, Arch, kCapacity>(spec, threads, out, progress);
    }
  });
}

template <class Arch>
int batchLanes(Precision precision) {
  return precision == Precision::kDouble ? int(xsimd::batch<double, Arch>::size)
                                         : int(xsimd::batch<float, Arch>::size);
}

}  // namespace aurora_sweep
