// The SIMD engine's link models, one per lane, as structs of arrays: the
// rules of the scalar channels (aurora_control/link/link.h, docs/links.md: one
// Philox block per step, the loss chain and the uniform jitter on the draws'
// words, the receive rule, the drone's hover on a stale command) written as
// loops over the lanes without branches, so that the compiler turns them
// into vector instructions of the engine's instruction set. A lane's results
// equal ModelLink's bit for bit (test_sweep_link). Links whose jitter is
// geometric (a logarithm, which would round differently on lanes) run
// ModelLink lane by lane instead (laneLinksApply).
#pragma once

#include <xsimd/xsimd.hpp>

#include <algorithm>
#include <cstdint>
#include <vector>

#include "aurora_control/link/link.h"
#include "gather_lanes.h"

namespace aurora_sweep {

// Whether every combination of a sweep over `link` can run on LaneLinks:
// no direction has a geometric jitter (the sweep's values set maxima only).
inline bool laneLinksApply(const aurora_control::LinkParams& link) {
  return link.uplink.jitter != aurora_control::JitterKind::kGeometric &&
         link.downlink.jitter != aurora_control::JitterKind::kGeometric;
}

// Philox4x32-10 on L independent lanes: Random123's philox4x32 block (its
// multipliers, Weyl constants and round) on batches of 64-bit lanes, each
// holding one 32-bit word, so that a round's products are single 32 x 32 ->
// 64-bit multiplies (mulLow32); test_sweep_link checks every word against
// Random123's own.
template <int L, class Arch>
struct LanePhilox {
  using U = xsimd::batch<uint64_t, Arch>;
  static constexpr int kPerBatch = static_cast<int>(U::size);
  static_assert(L % kPerBatch == 0, "whole batches of lanes");
  static constexpr uint64_t kM0 = 0xD2511F53u, kM1 = 0xCD9E8D57u;  // PHILOX_M4x32_0, _1
  static constexpr uint64_t kW0 = 0x9E3779B9u, kW1 = 0xBB67AE85u;  // PHILOX_W32_0, _1

  // ctr[4][L], key[2][L] in (32-bit values); out[4][L]: the four words of
  // each lane's block.
  static void blocks(const uint64_t ctr[4][L], const uint64_t key[2][L], uint64_t out[4][L]) {
    const U low(uint64_t(0xffffffffu)), m0(kM0), m1(kM1);
    for (int b = 0; b < L; b += kPerBatch) {
      U c0 = U::load_unaligned(ctr[0] + b), c1 = U::load_unaligned(ctr[1] + b);
      U c2 = U::load_unaligned(ctr[2] + b), c3 = U::load_unaligned(ctr[3] + b);
      U k0 = U::load_unaligned(key[0] + b), k1 = U::load_unaligned(key[1] + b);
      for (int round = 0; round < 10; ++round) {
        const U p0 = mulLow32(c0, m0), p1 = mulLow32(c2, m1);
        c0 = (p1 >> 32) ^ c1 ^ k0;
        c1 = p1 & low;
        c2 = (p0 >> 32) ^ c3 ^ k1;
        c3 = p0 & low;
        k0 = (k0 + U(kW0)) & low;
        k1 = (k1 + U(kW1)) & low;
      }
      c0.store_unaligned(out[0] + b), c1.store_unaligned(out[1] + b);
      c2.store_unaligned(out[2] + b), c3.store_unaligned(out[3] + b);
    }
  }
};

// One direction on every lane: its parameters, its loss chain's state, the
// newest packet received, and the arrival step of each packet sent (a ring
// indexed by the engine's global slot, as the history: lane l's packet j at
// slot start_l + j). Integers of the lanes' width (Int: int32 lanes for
// float, int64 for double), so a receive is a few gathers.
template <class Int, class Arch>
struct LaneChannel {
  using I = xsimd::batch<Int, Arch>;
  static constexpr int L = static_cast<int>(I::size);
  Int delay[L];  // (members: the engine's `new` does not over-align in C++14, so unaligned loads)
  Int jitter_max[L];          // 0: none
  // Each lane's aurora_control::LossRule, as arrays (the send loop vectorizes).
  uint64_t good[L], bad[L], flips[L];
  uint64_t lost[L];                       // 0 or 1: the chain's state
  Int newest[L];
  Int newest_at[L];
  long mask;                              // the ring's slots - 1 (a power of two - 1)
  std::vector<Int, xsimd::aligned_allocator<Int, 64>> arrival;
  long longest_jitter = 0;                // the largest jitter_max any lane has had

  explicit LaneChannel(long window) : mask(window - 1), arrival(static_cast<size_t>(window) * L) {}

  void start(int l, const aurora_control::LinkDirection& d, long delay_samples) {
    delay[l] = static_cast<Int>(delay_samples);
    jitter_max[l] = static_cast<Int>(d.jitter == aurora_control::JitterKind::kNone ? 0 : d.jitter_max);
    longest_jitter = std::max(longest_jitter, long(jitter_max[l]));
    const aurora_control::LossRule rule = aurora_control::LossRule::of(d);
    good[l] = rule.good, bad[l] = rule.bad, flips[l] = rule.flips;
    lost[l] = 0, newest[l] = -1, newest_at[l] = -1;
  }

  // Sends every lane's packet of its step k[l] at global slot `slot`, from
  // the words of its draws (jitter_w, loss_w): the one-run channel's rules
  // (lossStep, packetArrival) with the uniform jitter (uniformJitter).
  void send(const Int k[L], long slot, const uint64_t jitter_w[L], const uint64_t loss_w[L]) {
    Int* at = &arrival[static_cast<size_t>(slot & mask) * L];
    for (int l = 0; l < L; ++l) {
      lost[l] = aurora_control::lossStep(lost[l], loss_w[l], good[l], bad[l], flips[l]);
      const Int jitter = static_cast<Int>(aurora_control::uniformJitter(static_cast<uint32_t>(jitter_w[l]), jitter_max[l]));
      at[l] = aurora_control::packetArrival<Int>(lost[l], k[l], delay[l], jitter);
    }
  }

  // LinkChannel::receive on every lane: the newest-sent packet that has
  // arrived by k, scanning from k - delay down over the jitter's window.
  // Returns the ring index (slot L + lane) of each lane's newest packet.
  // Conditions are integer masks (all ones: true), not batch_bool: xsimd
  // 8.1 builds some integer comparisons element by element.
  I receive(const I& k, const I& start, const I& lane) {
    const I zero(Int(0)), ones(Int(-1)), slots(static_cast<Int>(mask)), jmax = I::load_unaligned(jitter_max);
    const I d = I::load_unaligned(delay);
    I best = I::load_unaligned(newest), best_at = I::load_unaligned(newest_at), pending = ones;
    for (long o = 0; o <= longest_jitter; ++o) {
      const I j = k - d - I(Int(o));
      const I a = gatherLanes<I>(arrival.data(), ((start + nonNegative(j)) & slots) * I(Int(L)) + lane);
      const I got = pending & atLeast(jmax, I(Int(o))) & atLeast(j, zero) & atLeast(j - best, I(Int(1))) &
                    atLeast(a, zero) & atLeast(k, a);
      best = (got & j) | (best & ~got);
      best_at = (got & k) | (best_at & ~got);
      pending = (pending & ~got);
    }
    best.store_unaligned(newest);
    best_at.store_unaligned(newest_at);
    return ((start + nonNegative(best)) & slots) * I(Int(L)) + lane;
  }

  // All ones where a >= b, else 0 (link.h's mask form).
  static I atLeast(const I& a, const I& b) { return aurora_control::atLeastMask<Int>(a, b); }
  static I nonNegative(const I& x) { return x & atLeast(x, I(Int(0))); }
};

// Lane by lane over each lane's own ModelLink (where the vectorized links
// do not apply: a geometric jitter): the history index (1-based) of the state
// lane l's controller receives at its step k[l] ...
template <class I, class Link, int L>
I modelLinksUplink(std::vector<Link>& links, const long (&k)[L]) {
  alignas(64) typename I::value_type at[L];
  for (int l = 0; l < L; ++l) at[l] = static_cast<typename I::value_type>(links[l].uplinkIndex(k[l]) + 1);
  return I::load_aligned(at);
}

// ... and the commands U (Inputs of them) each lane sent at k[l] become
// the ones its drone applies.
template <int Inputs, class B, class Link, int L>
void modelLinksDownlink(std::vector<Link>& links, const long (&k)[L], B U[Inputs]) {
  using T = typename B::value_type;
  alignas(64) T sent[Inputs][L];
  for (int i = 0; i < Inputs; ++i) U[i].store_aligned(sent[i]);
  for (int l = 0; l < L; ++l) {
    T lane[Inputs];
    for (int i = 0; i < Inputs; ++i) lane[i] = sent[i][l];
    links[l].downlink(k[l], lane, lane);
    for (int i = 0; i < Inputs; ++i) sent[i][l] = lane[i];
  }
  for (int i = 0; i < Inputs; ++i) U[i] = B::load_aligned(sent[i]);
}

// Both directions and the commands in flight on every lane (ModelLink), in
// the engine's batches: B of T, I of Int; commands of `Inputs` values;
// rings of `window` slots (the history's capacity).
template <typename T, class Arch, int Inputs = 4>
class LaneLinks {
 public:
  using B = xsimd::batch<T, Arch>;
  using Int = xsimd::as_integer_t<T>;
  using I = xsimd::batch<Int, Arch>;
  static constexpr int L = static_cast<int>(B::size);

  LaneLinks(long window, long timeout_steps)
      : timeout_(static_cast<Int>(timeout_steps)), up_(window), down_(window), mask_(window - 1),
        commands_(static_cast<size_t>(window) * Inputs * L) {
    for (int l = 0; l < L; ++l) lane_[l] = static_cast<Int>(l);
  }

  // Lane l's run over `link` (its combination's: combinationLink), its
  // draws keyed by `key`.
  void start(int l, const aurora_control::LinkParams& link, uint64_t key) {
    up_.start(l, link.uplink, link.uplink.delay);
    down_.start(l, link.downlink, link.downlink.delay);
    // The draws' key layout (link.h, drawBlock): the key and the
    // combination's counter words are the same at every step.
    const aurora_control::DrawBlock b = aurora_control::drawBlock(link.seed, key, 0);
    for (int w = 0; w < 2; ++w) key_[w][l] = b.key[w];
    for (int w = 2; w < 4; ++w) ctr_[w][l] = b.ctr[w];
  }

  // Each lane's history index (1-based) of the state its controller
  // receives at its step k (count - 1): the newest arrived, the current one
  // while none has. Sends its packet k at global slot `slot`; draws the
  // step's Philox blocks for both directions.
  I uplink(const I& count, const I& start, long slot) {
    alignas(64) Int k[L];
    (count - I(Int(1))).store_aligned(k);
    for (int l = 0; l < L; ++l) {  // the step's counter words (link.h, DrawBlock)
      const uint64_t step = uint64_t(int64_t(k[l]));
      ctr_[0][l] = aurora_control::DrawBlock::stepLow(step), ctr_[1][l] = aurora_control::DrawBlock::stepHigh(step);
    }
    LanePhilox<L, Arch>::blocks(ctr_, key_, words_);
    up_.send(k, slot, words_[0], words_[1]);
    up_.receive(I::load_aligned(k), start, I::load_unaligned(lane_));
    const I newest = I::load_unaligned(up_.newest);
    const I arrived = LaneChannel<Int, Arch>::atLeast(newest, I(Int(0)));
    return ((newest + I(Int(1))) & arrived) | (count & ~arrived);
  }

  // The commands U sent at step k become the ones each drone applies: the
  // newest arrived, or hover (0) while none has or when the newest arrived
  // timeout steps ago or more.
  void downlink(const I& count, const I& start, long slot, B U[Inputs]) {
    alignas(64) Int k[L];
    (count - I(Int(1))).store_aligned(k);
    T* sent = &commands_[static_cast<size_t>(slot & mask_) * Inputs * L];
    for (int i = 0; i < Inputs; ++i) U[i].store_unaligned(sent + i * L);
    down_.send(k, slot, words_[2], words_[3]);
    const I kb = I::load_aligned(k), lane = I::load_unaligned(lane_);
    const I at = down_.receive(kb, start, lane);  // slot L + lane of each lane's newest command
    const I newest = I::load_unaligned(down_.newest), since = kb - I::load_unaligned(down_.newest_at);
    // Hover (all ones): the drivers' watchdog, the one-run link's rule (hoverMask).
    const I hover = aurora_control::hoverMask<Int>(newest, since, I(timeout_));
    const B hover_bits = xsimd::bitwise_cast<B>(hover);
    const I base = (at - lane) * I(Int(Inputs)) + lane;  // [slot][i][lane]
    for (int i = 0; i < Inputs; ++i) {
      U[i] = gatherLanes<B>(commands_.data(), base + I(Int(i * L))) & ~hover_bits;
    }
  }

 private:
  Int timeout_;
  Int lane_[L];  // 0, 1, ..., L - 1 (no batch members: this object is not over-aligned)
  LaneChannel<Int, Arch> up_, down_;
  long mask_;  // window - 1
  uint64_t key_[2][L], ctr_[4][L];  // each lane's Philox key and counter (32-bit values)
  uint64_t words_[4][L];
  std::vector<T, xsimd::aligned_allocator<T, 64>> commands_;  // [slot][i][lane]
};

}  // namespace aurora_sweep
