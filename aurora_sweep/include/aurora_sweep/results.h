// Writing a sweep's results: one CSV row per combination and a JSON summary.
#pragma once

#include <string>
#include <vector>

#include "aurora_sweep/simulation.h"
#include "aurora_sweep/sweep_spec.h"

namespace aurora_sweep {

struct RunInfo {
  std::string backend;      // scalar | cpu | cuda
  std::string device;       // CPU arch or GPU name
  int threads = 1;
  int lanes = 1;            // simulations per instruction stream (SIMD lanes)
  double wall_time_s = 0;   // whole run, transfers included
  double kernel_time_s = -1;  // CUDA kernel only (-1: not applicable)
  std::string note;         // how `auto` chose, etc.
};

// Per check: passed (held through a complete run), failed, or not reached
// (the run stopped early at another check's failure while this one held).
struct Counts {
  long combinations = 0;
  long feasible = 0;
  long passed[4] = {0, 0, 0, 0};
  long failed[4] = {0, 0, 0, 0};
  long not_reached[4] = {0, 0, 0, 0};
  long long steps = 0;
};

// `iterations`: the steps of a complete run (studyIterationCount).
Counts countResults(const std::vector<SimResult>& results, long iterations);

// Throws std::runtime_error naming the file when it cannot be written.
void writeResultsCsv(const std::string& path, const SweepSpec& spec,
                     const std::vector<SimResult>& results);
void writeSummaryJson(const std::string& path, const SweepSpec& spec, const RunInfo& info,
                      const Counts& counts);

}  // namespace aurora_sweep
