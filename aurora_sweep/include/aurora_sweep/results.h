// Writing a sweep's results: one CSV row per combination and a JSON summary.
#pragma once

#include <memory>
#include <nlohmann/json.hpp>
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
  // Simulated by this run (a resumed run computes only the missing chunks);
  // -1: all of them. The rates in summary.json are over these.
  long computed_combinations = -1;
  long long computed_steps = -1;
};

// Per check: passed (held through a complete run), failed, or not reached
// (the run stopped early at another check's failure while this one held).
// A sweep of one robot has four checks, a formation sweep five.
struct Counts {
  static constexpr int kMostChecks = aurora_control::kFormationChecks;
  explicit Counts(int check_count = 4) : checks(check_count) {}
  int checks;
  long combinations = 0;
  long feasible = 0;
  long passed[kMostChecks] = {};
  long failed[kMostChecks] = {};
  long not_reached[kMostChecks] = {};
  long long steps = 0;
};
inline int checkCount(bool formation) { return formation ? aurora_control::kFormationChecks : aurora_control::kPositioningChecks; }

// `iterations`: the steps of a complete run (studyIterationCount).
Counts countResults(const std::vector<SimResult>& results, long iterations, int checks = 4);
// Adds one chunk's results to running counts.
void addCounts(Counts& c, const std::vector<SimResult>& results, long iterations);

// Results written chunk by chunk, in index order, so that no second copy of
// all results is held in memory. Throw std::runtime_error naming the file.
class ResultsWriter {
 public:
  virtual ~ResultsWriter() = default;
  // Results of combinations first, first + 1, ...
  virtual void append(long first, const std::vector<SimResult>& results) = 0;
  virtual void close() = 0;
  virtual long rows() const = 0;  // rows written
};

// `feasible_only`: only the rows of feasible combinations.
std::unique_ptr<ResultsWriter> openCsvWriter(const std::string& path, const SweepSpec& spec,
                                             bool feasible_only);
// HDF5 (h5py reads it): one column per field, chunked. Only where libhdf5 was
// found at build time (hdf5Available()).
bool hdf5Available();
std::unique_ptr<ResultsWriter> openHdf5Writer(const std::string& path, const SweepSpec& spec,
                                              bool feasible_only);

// For grids varying two of the law's gains and the delay (one run each:
// kp, kd and delay for the PD law): per gain pair, is feasibility monotone
// in the delay (feasible up to some delay, infeasible beyond)? A pair that
// fails, then holds again at a longer delay is counted (summary.json).
class DelayMonotony {
 public:
  explicit DelayMonotony(const SweepSpec& spec);
  bool applies() const { return applies_; }
  void add(long first, const std::vector<SimResult>& results);
  long pairs() const { return static_cast<long>(feasible_.size() / delays_.size()); }
  long nonMonotonePairs() const;
  const int* gains() const { return gain_; }  // the two gains' ParamIds, in the grid's order

 private:
  bool applies_ = false;
  GridView grid_;
  int gain_[2] = {kParamKp, kParamKd};
  std::vector<double> values_[2], delays_;
  std::vector<unsigned char> feasible_;  // [pair][delay]
};

// With repeats (sweep.repeats N > 1): per combination, in how many of its N
// runs (link seeds) it was feasible; its share is that over N. One draw of
// a link is one sample, not an answer (docs/links.md, "Links in a sweep").
class FeasibleShare {
 public:
  explicit FeasibleShare(const SweepSpec& spec);
  bool applies() const { return repeats_ > 1; }
  void add(long first, const std::vector<SimResult>& results);
  // summary.json's "feasible_share": repeats, combinations, how many were
  // feasible in 0, 1, ..., N runs, the mean share.
  nlohmann::json summary() const;
  // feasible_share.csv: one row per combination (its parameters, the
  // feasible runs, the share). Throws std::runtime_error naming the file.
  void writeCsv(const std::string& path, const SweepSpec& spec) const;

 private:
  long repeats_;
  std::vector<unsigned int> feasible_runs_;  // per combination
};

// Whole-vector convenience (tests, small sweeps).
void writeResultsCsv(const std::string& path, const SweepSpec& spec,
                     const std::vector<SimResult>& results);

// `extra`: further members (resume, ranks, outputs) added to summary.json.
void writeSummaryJson(const std::string& path, const SweepSpec& spec, const RunInfo& info,
                      const Counts& counts, const nlohmann::json& extra = nlohmann::json::object());

}  // namespace aurora_sweep
