// What a sweep will cost, said before any work: the combinations, the time
// at a rate measured on this machine and backend (a short calibration run
// of the first combinations), and the bytes it writes (chunk files and
// results side by side during the merge), against the free space where
// they go. A sweep that cannot fit on the disk is refused unless asked.
#pragma once

#include <cstdint>
#include <string>

#include "aurora_sweep/sweep_spec.h"
#include "../chunks/chunk_runner.h"

namespace aurora_sweep {

struct SweepPlan {
  long combinations = 0;       // runs: combinations x repeats
  long repeats = 1;            // the spec's (runs are counted as runs when above 1)
  long chunks = 0;             // of the chunk size planned
  long calibrated = 0;         // combinations run to measure the rate
  double rate = 0;             // simulations per second measured
  double seconds = 0;          // estimated compute time
  uint64_t chunk_bytes = 0;    // DIR/progress/ (removed at the end)
  uint64_t results_bytes = 0;  // results.csv / .h5, estimated from a measured row
  uint64_t free_bytes = 0;     // on the file system of `out`
  std::string volume;          // the existing folder whose file system was asked

  uint64_t neededBytes() const { return chunk_bytes + results_bytes; }
  bool fits() const { return neededBytes() <= free_bytes; }
};

// `format`: csv, hdf5, both or none (outputFormat()); `feasible_only`: --rows
// feasible (the results bytes are then an upper bound).
SweepPlan planSweep(const SweepSpec& spec, const BackendChoice& choice, const std::string& out,
                    const std::string& format, long chunk_size);

// "1,000,000 combinations in 16 chunks: about 2 min at 8300 sims/s (measured on
// the first 4,096), writes about 106 MB (chunk files 48 MB, results 58 MB);
// 53 GB free on /work"
std::string planText(const SweepPlan& plan);

// "1 combination", "2 combinations" (item counts in messages).
std::string counted(long n, const std::string& singular, const std::string& plural);

// n simulations of a spec of `repeats`: "80 combinations", or with repeats
// "30 runs" (each combination flies `repeats` runs).
std::string runCount(long n, long repeats);

}  // namespace aurora_sweep
