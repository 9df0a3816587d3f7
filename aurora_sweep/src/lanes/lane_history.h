// The SIMD engine's history and links as the policies of the one iteration
// (closed_loop.h, loopIteration): the same interface as the scalar runner's
// StateHistory, IdealLink and ModelLink, on lanes. Each lane runs its own
// simulation; `k` is each lane's iteration as integer lanes. Included by
// batch_engine.h only.
#pragma once

#include <cstring>
#include <stdexcept>
#include <type_traits>

#include <xsimd/xsimd.hpp>

#include <vector>

#include "aurora_control/law/law_sample.h"
#include "gather_lanes.h"
#include "lane_links.h"

namespace aurora_sweep {

namespace {

// One lane of a SIMD batch, read or written (the engine sets each lane's run).
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
  // Lane `lane` of every field of a struct of batches set from the same
  // struct of scalars (gains, model parameters, a law's memory, a state:
  // structs of T only, or empty).
  template <class Batches, class Scalars>
  static void setFields(Batches& batches, int lane, const Scalars& scalars) {
    constexpr bool kEmpty = std::is_empty<Scalars>::value;
    constexpr size_t n = kEmpty ? 0 : sizeof(Scalars) / sizeof(T);
    static_assert(kEmpty || (sizeof(Scalars) == n * sizeof(T) && sizeof(Batches) == n * sizeof(B)),
                  "a struct of T only");
    B* to = reinterpret_cast<B*>(&batches);
    const T* from = reinterpret_cast<const T*>(&scalars);
    for (size_t i = 0; i < n; ++i) set(to[i], lane, from[i]);
  }
  // Lane `lane` of every field of a struct of batches, into the same struct
  // of scalars.
  template <class Batches, class Scalars>
  static void getFields(const Batches& batches, int lane, Scalars& scalars) {
    constexpr bool kEmpty = std::is_empty<Scalars>::value;
    constexpr size_t n = kEmpty ? 0 : sizeof(Scalars) / sizeof(T);
    static_assert(kEmpty || (sizeof(Scalars) == n * sizeof(T) && sizeof(Batches) == n * sizeof(B)),
                  "a struct of T only");
    const B* from = reinterpret_cast<const B*>(&batches);
    T* to = reinterpret_cast<T*>(&scalars);
    for (size_t i = 0; i < n; ++i) to[i] = get(from[i], lane);
  }
  // Lane `lane` of every batch of a struct copied from another of its type,
  // where the struct holds batches and values every lane shares (a formation
  // layer: its law; FormationBatch restarts one lane's). Byte by byte within
  // each batch-sized slot: a shared value's bytes are the same in both.
  template <class S>
  static void copyLane(S& to, const S& from, int lane) {
    static_assert(std::is_trivially_copyable<S>::value && sizeof(S) % sizeof(B) == 0 && alignof(B) == sizeof(B),
                  "batches and shared values only");
    unsigned char* dst = reinterpret_cast<unsigned char*>(&to);
    const unsigned char* src = reinterpret_cast<const unsigned char*>(&from);
    for (size_t at = size_t(lane) * sizeof(T); at < sizeof(S); at += sizeof(B)) std::memcpy(dst + at, src + at, sizeof(T));
  }
};

// Every lane's last `capacity` states as law `Law` reads them, in one ring
// of slots [slot][j][lane]: every lane writes the same slot at each push (a
// plain vector store); lane l's H(i) sits at slot start_l + i - 1. The
// capacity is the run's (limits.h, historyCapacity), set before the first
// push: one engine for every capacity (each a compile of its own before).
template <class Law, typename T, class Arch>
class LaneHistory {
 public:
  using B = xsimd::batch<T, Arch>;
  using Int = xsimd::as_integer_t<T>;
  using I = xsimd::batch<Int, Arch>;
  using Input = typename Law::Input;
  static constexpr int L = static_cast<int>(B::size);
  static constexpr int W = Input::kWidth;
  static constexpr int kStates = Law::Vehicle::kStates;

  LaneHistory() {
    alignas(64) Int iota[L];
    for (int l = 0; l < L; ++l) iota[l] = static_cast<Int>(l);
    lane_ = I::load_aligned(iota);
  }

  // The ring's size in states (a power of two).
  void allocate(int capacity) {
    if (capacity <= 0 || (capacity & (capacity - 1)) != 0) {
      throw std::invalid_argument("history capacity must be a power of two");
    }
    mask_ = capacity - 1;
    ring_.assign(static_cast<size_t>(capacity) * W * L, T(0));
  }
  int capacity() const { return int(mask_) + 1; }

  // Lane l starts a run: empty, its H(1) at the next slot pushed.
  void startLane(int l) {
    Lanes<T, Arch>::set(count_, l, Int(0));
    Lanes<T, Arch>::set(start_, l, static_cast<Int>((slot_ + 1) & mask_));
  }

  // States kept by each lane: its iteration k about to run (k + 1 once pushed).
  const I& size() const { return count_; }
  const I& start() const { return start_; }
  long slot() const { return slot_; }  // the ring slot written last

  void push(const B X[kStates]) {
    ++slot_;
    const long slot = slot_ & mask_;
    for (int j = 0; j < W; ++j) X[Input::state(j)].store_aligned(&ring_[(slot * W + j) * L]);
    count_ = count_ + I(Int(1));
  }

  // Each lane's state of its step `step` (0-based), gathered from the ring;
  // latched per lane as StateHistory::read does (a step read before is the
  // state read then: after a long loss burst its slot holds a newer state).
  void read(const I& step, B X[kStates]) {
    const I slot = (start_ + step) & I(static_cast<Int>(mask_));
    const I base = slot * I(Int(W * L)) + lane_;
    const auto fresh = xsimd::bool_cast(step != held_step_ | count_ != held_count_);
    aurora_control::LawSample<B, Law> sample;
    // Where every lane reads one slot (a drone whose delay the batch's lanes
    // share), a plain load per input gives what the gather would.
    long same = -1;
    const bool one_slot = sameSlot(slot, same);
    for (int j = 0; j < W; ++j) {
      const B stored = one_slot ? B::load_aligned(&ring_[(same * W + j) * L])
                                : gatherLanes<B>(ring_.data(), base + I(Int(j * L)));
      held_[j] = xsimd::select(fresh, stored, held_[j]);
      sample.v[j] = held_[j];
    }
    held_step_ = step;
    held_count_ = count_ + I(Int(1));  // a restarted lane (count 0 again) never reuses its old run's state
    sample.toState(X);
  }

 private:
  // Whether every lane's slot is one (`slot` then).
  static bool sameSlot(const I& slots, long& slot) {
    alignas(64) Int at[L];
    slots.store_aligned(at);
    for (int l = 1; l < L; ++l) {
      if (at[l] != at[0]) return false;
    }
    slot = long(at[0]);
    return true;
  }

  std::vector<T, xsimd::aligned_allocator<T, 64>> ring_;
  B held_[W];                         // each lane's state read last (read's latch) ...
  I held_step_ = I(Int(-1));          // ... its step
  I held_count_ = I(Int(-1));         // ... and the lane's count at the next read (a new run's differs)
  I count_ = I(Int(0));
  I start_ = I(Int(0));
  I lane_;
  long slot_ = 0;
  long mask_ = -1;  // capacity - 1 (allocate)
};

// Every lane over its own link model: vectorized (LaneLinks) or, where those
// do not apply (a geometric jitter), each lane's ModelLink in turn.
template <class Law, typename T, class Arch>
class LaneModelLinks {
 public:
  using History = LaneHistory<Law, T, Arch>;
  using B = typename History::B;
  using Int = typename History::Int;
  using I = typename History::I;
  static constexpr int L = History::L, kInputs = Law::Vehicle::kInputs;
  template <int Capacity>
  using Link = aurora_control::ModelLink<Capacity, T, kInputs>;

  LaneModelLinks(const aurora_control::LinkParams& base, double Ts, const History& history) : history_(history) {
    if (laneLinksApply(base)) {
      lanes_.reset(new LaneLinks<T, Arch, kInputs>(history.capacity(), std::lround(base.cmd_timeout / Ts)));
    } else {
      withLinks([&](auto& links) {
        links.reserve(L);
        for (int l = 0; l < L; ++l) links.emplace_back(base, 0, 0, Ts);
      });
    }
  }

  // Lane l's run over `link`, its draws keyed by `key`.
  void startLane(int l, const aurora_control::LinkParams& link, long delay, uint64_t key, double Ts) {
    if (lanes_) return lanes_->start(l, link, key);
    withLinks([&](auto& links) { links[l] = typename std::decay<decltype(links)>::type::value_type(link, delay, key, Ts); });
  }

  // The step (0-based) whose state each lane's controller receives at its k.
  I uplinkIndex(const I& k) {
    const I one(Int(1));
    if (lanes_) return lanes_->uplink(k + one, history_.start(), history_.slot()) - one;
    long steps[L];
    laneSteps(k, steps);
    I index;
    withLinks([&](auto& links) { index = modelLinksUplink<I>(links, steps); });
    return index - one;
  }

  // The commands each lane sent at its k become the ones its vehicle applies.
  void downlink(const I& k, const B*, B* U) {
    if (lanes_) return lanes_->downlink(k + I(Int(1)), history_.start(), history_.slot(), U);
    long steps[L];
    laneSteps(k, steps);
    withLinks([&](auto& links) { modelLinksDownlink<kInputs>(links, steps, U); });
  }

 private:
  static void laneSteps(const I& k, long (&steps)[L]) {
    alignas(64) Int at[L];
    k.store_aligned(at);
    for (int l = 0; l < L; ++l) steps[l] = long(at[l]);
  }

  // f(the lane-by-lane links) of the history's capacity: a ModelLink's
  // rings are arrays (a lane's run starts a new one: the smallest tier).
  template <class F>
  void withLinks(F&& f) {
    switch (history_.capacity()) {
      case aurora_control::kShortHistory: return f(short_);
      case aurora_control::kMediumHistory: return f(medium_);
      default: return f(full_);
    }
  }

  const History& history_;
  std::unique_ptr<LaneLinks<T, Arch, kInputs>> lanes_;
  std::vector<Link<aurora_control::kShortHistory>> short_;
  std::vector<Link<aurora_control::kMediumHistory>> medium_;
  std::vector<Link<aurora_control::kDelayHistory>> full_;
};

}  // namespace

}  // namespace aurora_sweep
