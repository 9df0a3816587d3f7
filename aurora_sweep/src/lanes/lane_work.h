// The skeleton every lane engine of the `cpu` backend shares (BatchWorker in
// batch_engine.h, FormationBatch in formation_lanes.h): the grid's
// combinations handed out to the threads (LaneWork), and each thread's L
// lanes, each running one combination at a time (LaneSlots). A lane whose
// run ended (its last iteration, or a failed check with early stop) gives
// its result and takes the next combination at once (refill), so that
// early stops keep paying. Included by batch_engine.h only.
#pragma once

#include <algorithm>
#include <atomic>
#include <vector>

#include "aurora_sweep/backends.h"

namespace aurora_sweep {

namespace {

// Work is handed out in chunks of consecutive indices (neighbouring
// combinations run for similar lengths).
constexpr long kChunk = 64;

// What every lane engine's thread shares with the others: the range
// [first, total) of the grid's combinations, handed out in chunks of
// consecutive indices from `next`, and each run's result, stored at its
// index and counted in `progress`. One per thread (its chunk is its own).
class LaneWork {
 public:
  LaneWork(const GridView& grid, long first, long total, std::vector<SimResult>& out, std::atomic<long>& next,
           Progress& progress)
      : grid_(grid), first_(first), total_(total), out_(out), next_(next), progress_(progress) {}

  // The next combination this thread runs (false: none is left), left for
  // take() (a formation batch takes only those of its law).
  bool peek(long& index) {
    if (chunk_next_ >= total_) return false;  // once out of work, no further trip to `next`
    if (chunk_next_ >= chunk_end_) {
      chunk_next_ = next_.fetch_add(kChunk, std::memory_order_relaxed);
      chunk_end_ = std::min(chunk_next_ + kChunk, total_);
      if (chunk_next_ >= total_) return false;
    }
    index = chunk_next_;
    return true;
  }
  bool take(long& index) {
    if (!peek(index)) return false;
    ++chunk_next_;
    return true;
  }
  Combination decode(long index) const { return grid_.decode(index); }
  long first() const { return first_; }  // a lane without work reruns it, its result dropped
  void record(long index, const SimResult& result) {
    out_[index - first_] = result;
    progress_.fetch_add(1, std::memory_order_relaxed);
  }

 private:
  const GridView grid_;
  const long first_, total_;
  std::vector<SimResult>& out_;
  std::atomic<long>& next_;
  Progress& progress_;
  long chunk_next_ = 0, chunk_end_ = 0;
};

// Which combination each of L lanes runs, whether its result counts, and
// the turn of a lane whose run ended: its result is recorded, the lane is
// free, and a refill gives it the next combination the engine allows or,
// with none, a spare run whose result is dropped (the lanes of a batch run
// on together until none counts).
template <int L>
class LaneSlots {
 public:
  explicit LaneSlots(LaneWork& work) : work_(work) { clear(); }

  // Every lane free, none counting (a new batch).
  void clear() {
    for (int l = 0; l < L; ++l) free_[l] = true, counts_[l] = false, index_[l] = work_.first();
  }

  bool anyCounts() const {
    for (int l = 0; l < L; ++l) {
      if (counts_[l]) return true;
    }
    return false;
  }

  // The lanes whose run ended at this step are free: one whose result
  // counts when it stopped (stopped[l]: a failed check with early stop, or
  // its last step: last[l]) and gives it, result(l); a spare one only past
  // its last step (an early stop would restart it every few steps).
  template <class Result>
  void end(const bool* stopped, const bool* last, Result&& result) {
    for (int l = 0; l < L; ++l) {
      if (free_[l] || !(last[l] || (counts_[l] && stopped[l]))) continue;
      if (counts_[l]) work_.record(index_[l], result(l));
      free_[l] = true, counts_[l] = false;
    }
  }

  // Each free lane starts the next combination take(index) gives,
  // start(l, index, true), or with none left `spare`, start(l, spare, false).
  template <class Take, class Start>
  void refill(Take&& take, long spare, Start&& start) {
    for (int l = 0; l < L; ++l) {
      if (!free_[l]) continue;
      long index = spare;
      const bool have = take(index);
      index_[l] = have ? index : spare;
      counts_[l] = have, free_[l] = false;
      start(l, index_[l], have);
    }
  }

 private:
  LaneWork& work_;
  bool free_[L];    // its run ended (or none started): a refill starts one
  bool counts_[L];  // its run's result is recorded when it ends
  long index_[L];   // its run's combination
};

}  // namespace

}  // namespace aurora_sweep
