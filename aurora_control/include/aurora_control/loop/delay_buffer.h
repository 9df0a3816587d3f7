// Delayed feedback (docs/delay-and-study.md, "Delayed feedback"): the loop keeps the
// history H(1) = X0, H(k+1) = X after k steps; at iteration k (1-based) with a
// delay of d samples the controller receives H(k - d) if k > d, otherwise the
// current state H(k).
#pragma once

#include "aurora_common/host_device.h"
#include "aurora_common/scalar_math.h"

namespace aurora_control {

// 1-based index into the history of the sample the controller receives at
// iteration k with delay d. The one place the rule is written; the ring
// buffer below (node, replay, runners, CUDA threads) and the SIMD engine
// (on integer batches, one k and d per lane: select() is xsimd's there)
// all call it.
template <typename Index>
AURORA_HD inline Index delayedHistoryIndex(const Index& k, const Index& d) {
  using aurora_common::select;
  return select(k > d, k - d, k);
}

// Fixed-capacity ring of the most recent samples (no allocation after
// construction, so it runs inside a GPU thread). A delay d needs
// Capacity >= d + 1.
template <typename Sample, int Capacity>
class DelayBuffer {
 public:
  static constexpr int kCapacity = Capacity;

  AURORA_HD DelayBuffer() : count_(0) {}

  AURORA_HD void clear() { count_ = 0; }

  // Appends H(count + 1).
  AURORA_HD void push(const Sample& s) {
    ring_[count_ % Capacity] = s;
    ++count_;
  }

  // Number of samples pushed since the last clear (k at the current iteration).
  AURORA_HD long size() const { return count_; }

  AURORA_HD static constexpr bool supportsDelay(long d) { return d >= 0 && d + 1 <= Capacity; }

  // The sample the controller receives with a delay of d samples; requires
  // size() >= 1 and supportsDelay(d).
  AURORA_HD const Sample& delayed(long d) const {
    const long index = delayedHistoryIndex<long>(count_, d);  // 1-based
    return ring_[(index - 1) % Capacity];
  }

  // The sample pushed as H(index + 1) (0-based: the state of step index);
  // requires size() - Capacity <= index < size().
  AURORA_HD const Sample& at(long index) const { return ring_[index % Capacity]; }

  // Delay actually in force for the newest sample: d once d samples of
  // history exist, 0 before (the spec's "otherwise the current state").
  AURORA_HD long delayInForce(long d) const { return count_ > d ? d : 0; }

  // Further samples needed before a delay of d is in force (0 once it is):
  // the same rule, counted forward. Raising d live beyond the history kept
  // makes this positive again, and the delay in force drops to 0 until then.
  AURORA_HD long pendingUntilInForce(long d) const { return count_ > d ? 0 : d + 1 - count_; }

 private:
  Sample ring_[Capacity];
  long count_;
};

}  // namespace aurora_control
