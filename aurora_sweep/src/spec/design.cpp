#include "aurora_sweep/design.h"

#include <boost/random/mersenne_twister.hpp>
#include <boost/random/seed_seq.hpp>
#include <boost/random/sobol.hpp>
#include <boost/random/uniform_01.hpp>
#include <boost/random/uniform_int_distribution.hpp>
#include <cmath>
#include <numeric>

namespace aurora_sweep {

namespace {

// A generator for one (seed, stream) pair: the same numbers on every run.
boost::random::mt19937_64 generatorFor(uint64_t seed, uint64_t stream) {
  boost::random::seed_seq seq{static_cast<uint32_t>(seed), static_cast<uint32_t>(seed >> 32),
                              static_cast<uint32_t>(stream), static_cast<uint32_t>(stream >> 32)};
  return boost::random::mt19937_64(seq);
}

void randomSamples(std::vector<double>& u, long n, int dims, uint64_t seed) {
  boost::random::uniform_01<double> unit;
  for (long i = 0; i < n; ++i) {
    boost::random::mt19937_64 gen = generatorFor(seed, static_cast<uint64_t>(i));
    for (int j = 0; j < dims; ++j) u[i * dims + j] = unit(gen);
  }
}

void latinHypercube(std::vector<double>& u, long n, int dims, uint64_t seed) {
  boost::random::uniform_01<double> unit;
  std::vector<long> bin(static_cast<size_t>(n));
  for (int j = 0; j < dims; ++j) {
    // Fisher-Yates with Boost's uniform integers: the same permutation on
    // every platform (std::shuffle's is the library's own choice).
    boost::random::mt19937_64 gen = generatorFor(seed, ~static_cast<uint64_t>(j));
    std::iota(bin.begin(), bin.end(), 0L);
    for (long k = n - 1; k > 0; --k) {
      const long m = boost::random::uniform_int_distribution<long>(0, k)(gen);
      std::swap(bin[k], bin[m]);
    }
    for (long i = 0; i < n; ++i) u[i * dims + j] = (double(bin[i]) + unit(gen)) / double(n);
  }
}

void sobolSamples(std::vector<double>& u, long n, int dims, uint64_t seed) {
  boost::random::sobol engine(static_cast<std::size_t>(dims));
  engine.discard(seed * static_cast<uint64_t>(dims));
  const double scale = std::ldexp(1.0, -64);  // 64-bit lattice values to [0, 1)
  for (long k = 0; k < n * dims; ++k) u[k] = double(engine()) * scale;
}

}  // namespace

bool designFromName(const std::string& name, Design& design) {
  for (Design d : {Design::kGrid, Design::kRandom, Design::kLatinHypercube, Design::kSobol}) {
    if (name == designName(d)) {
      design = d;
      return true;
    }
  }
  return false;
}

const char* designName(Design design) {
  switch (design) {
    case Design::kRandom: return "random";
    case Design::kLatinHypercube: return "latin_hypercube";
    case Design::kSobol: return "sobol";
    default: return "grid";
  }
}

double SampledRange::at(double u) const {
  if (integer) {
    const double v = std::floor(from + u * (to - from + 1.0));
    return v > to ? to : v;
  }
  const double v = log ? from * std::pow(to / from, u) : from + u * (to - from);
  return v > to ? to : v;  // rounding at u near 1 stays inside the range
}

std::vector<double> unitSamples(Design design, long samples, int dims, uint64_t seed) {
  std::vector<double> u(static_cast<size_t>(samples) * static_cast<size_t>(dims));
  if (design == Design::kRandom) randomSamples(u, samples, dims, seed);
  if (design == Design::kLatinHypercube) latinHypercube(u, samples, dims, seed);
  if (design == Design::kSobol) sobolSamples(u, samples, dims, seed);
  return u;
}

}  // namespace aurora_sweep
