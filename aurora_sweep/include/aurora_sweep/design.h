// Sampling designs for studies where a full grid is impossible (13
// parameters at 4 values each is 67 million runs): random, Latin hypercube
// and Sobol samples of the parameters' ranges (docs/delay-and-study.md,
// "Sampling designs"). The samples are made once on the host from the seed
// and the sample's index, never from the clock, and become the sweep's
// points: every backend, thread and run sees the same sample i.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace aurora_sweep {

enum class Design { kGrid, kRandom, kLatinHypercube, kSobol };

// "grid", "random", "latin_hypercube", "sobol"; false for another name.
bool designFromName(const std::string& name, Design& design);
const char* designName(Design design);

// One varied parameter's range and how a unit sample u in [0, 1) maps onto it.
struct SampledRange {
  double from = 0, to = 0;
  bool log = false;      // from * (to / from)^u (from > 0)
  bool integer = false;  // whole values from..to, each equally likely (delays)
  double at(double u) const;
};

// `samples` rows of `dims` unit coordinates in [0, 1), row-major.
// random: Boost.Random mt19937_64 seeded from (seed, row). latin_hypercube:
// each dimension's N bins permuted (seeded from (seed, dimension)), one
// sample in each bin, placed in it at random. sobol: Boost.Random's Sobol
// sequence, the first `seed` points skipped.
std::vector<double> unitSamples(Design design, long samples, int dims, uint64_t seed);

}  // namespace aurora_sweep
