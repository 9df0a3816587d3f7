// Sampling designs: Latin hypercube bins, reproducible random and Sobol
// samples, design sweep files (ranges, log scale, whole delays), refusals,
// and the backends agreeing on a design.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <set>
#include <string>

#include "aurora_sweep/backends.h"
#include "aurora_sweep/design.h"
#include "aurora_sweep/sweep_file.h"
#include "sweep_test_support.h"

using namespace aurora_sweep;

namespace {

using test::refusal;
using test::runOn;

std::string writeSweep(const std::string& name, const std::string& yaml) {
  return test::writeTemp(name + ".yaml", yaml);
}

const char* kSobolSweep =
    "sweep:\n"
    "  design: sobol\n"
    "  samples: 512\n"
    "  seed: 3\n"
    "  early_stop: false\n"
    "  parameters:\n"
    "    kp: {from: 0.05, to: 0.75, scale: log}\n"
    "    kd: {from: 0.0, to: 1.0}\n"
    "    delay: {from: 0, to: 40}\n";

}  // namespace

TEST(Design, LatinHypercubePutsOneSampleInEachBin) {
  const long n = 97;
  const int dims = 4;
  const std::vector<double> u = unitSamples(Design::kLatinHypercube, n, dims, 11);
  for (int j = 0; j < dims; ++j) {
    std::set<long> bins;
    for (long i = 0; i < n; ++i) {
      const double v = u[i * dims + j];
      ASSERT_GE(v, 0.0);
      ASSERT_LT(v, 1.0);
      bins.insert(static_cast<long>(std::floor(v * n)));
    }
    EXPECT_EQ(bins.size(), static_cast<size_t>(n)) << "dimension " << j;
  }
}

TEST(Design, SamplesDependOnSeedAndIndexOnly) {
  for (Design d : {Design::kRandom, Design::kLatinHypercube, Design::kSobol}) {
    const std::vector<double> a = unitSamples(d, 200, 3, 5), b = unitSamples(d, 200, 3, 5);
    EXPECT_EQ(a, b) << designName(d);
    EXPECT_NE(a, unitSamples(d, 200, 3, 6)) << designName(d);
    for (double v : a) {
      ASSERT_GE(v, 0.0);
      ASSERT_LT(v, 1.0);
    }
  }
  // random: sample i does not depend on how many are drawn
  const std::vector<double> few = unitSamples(Design::kRandom, 10, 3, 5);
  const std::vector<double> many = unitSamples(Design::kRandom, 200, 3, 5);
  EXPECT_TRUE(std::equal(few.begin(), few.end(), many.begin()));
  // Sobol with a seed skips that many points of the same sequence
  const std::vector<double> s0 = unitSamples(Design::kSobol, 8, 2, 0), s3 = unitSamples(Design::kSobol, 5, 2, 3);
  EXPECT_TRUE(std::equal(s3.begin(), s3.end(), s0.begin() + 6));
}

TEST(Design, SweepFileSamplesTheRanges) {
  const SweepSpec spec = loadSweepFile(writeSweep("sobol", kSobolSweep), test::configDir());
  EXPECT_EQ(spec.size(), 512);
  EXPECT_EQ(spec.design, "sobol");
  const GridView g = spec.view();
  std::set<long> delays;
  for (long i = 0; i < spec.size(); ++i) {
    const Combination c = g.decode(i);
    EXPECT_GE(c.v[kParamKp], 0.05);
    EXPECT_LE(c.v[kParamKp], 0.75);
    EXPECT_GE(c.v[kParamKd], 0.0);
    EXPECT_LE(c.v[kParamKd], 1.0);
    EXPECT_GE(c.delay(), 0);
    EXPECT_LE(c.delay(), 40);
    delays.insert(c.delay());
  }
  EXPECT_EQ(delays.size(), 41u);  // every whole delay of the range is drawn
  EXPECT_LE(spec.max_delay, 40);
  // log scale: half the samples below the geometric mean of the range
  long below = 0;
  for (long i = 0; i < spec.size(); ++i) below += g.decode(i).v[kParamKp] < std::sqrt(0.05 * 0.75);
  EXPECT_NEAR(double(below) / spec.size(), 0.5, 0.03);
}

TEST(Design, ScalarAndCpuAgreeOnADesign) {
  const SweepSpec spec = loadSweepFile(writeSweep("sobol_backends", kSobolSweep), test::configDir());
  const std::vector<SimResult> scalar = runOn("scalar", spec), cpu = runOn("cpu", spec);
  int feasible = 0;
  for (long i = 0; i < spec.size(); ++i) {
    EXPECT_EQ(scalar[i].ok, cpu[i].ok) << i;
    EXPECT_EQ(scalar[i].steps, cpu[i].steps) << i;
    feasible += aurora_sweep::feasible(scalar[i]);
  }
  EXPECT_GT(feasible, 20);
  EXPECT_LT(feasible, spec.size() - 20);
}

TEST(Design, MistakesAreNamed) {
  EXPECT_NE(refusal("sweep:\n  design: halton\n  samples: 4\n  parameters: {kp: 0.5, kd: 0.5, delay: 0}\n")
                .find("'sweep.design' = 'halton' is unknown: accepted grid, random, latin_hypercube, sobol"),
            std::string::npos);
  EXPECT_NE(refusal("sweep:\n  design: sobol\n  parameters: {kp: {from: 0, to: 1}, kd: 0.5, delay: 0}\n")
                .find("'sweep.samples' is missing"), std::string::npos);
  EXPECT_NE(refusal("sweep:\n  design: random\n  samples: 8\n"
                    "  parameters: {kp: {from: 0, to: 1, count: 4}, kd: 0.5, delay: 0}\n")
                .find("a random design samples ranges"), std::string::npos);
  EXPECT_NE(refusal("sweep:\n  design: sobol\n  samples: 8\n  order: [kp]\n"
                    "  parameters: {kp: {from: 0, to: 1}, kd: 0.5, delay: 0}\n")
                .find("'sweep.order' is for grids"), std::string::npos);
  EXPECT_NE(refusal("sweep:\n  design: sobol\n  samples: 8\n"
                    "  parameters: {kp: 0.5, kd: 0.5, delay: {from: 1, to: 9, scale: log}}\n")
                .find("= log: delay takes whole samples"), std::string::npos);
  EXPECT_NE(refusal("sweep:\n  samples: 8\n  parameters: {kp: 0.5, kd: 0.5, delay: 0}\n")
                .find("'sweep.samples' is for sampling designs"), std::string::npos);
  EXPECT_NE(refusal("sweep:\n  design: sobol\n  samples: 8\n"
                    "  parameters: {kp: {from: 0, to: 20}, kd: 0.5, delay: 0}\n")
                .find("'sweep.parameters.kp.to' = 20 is outside the accepted range [0, 10]"), std::string::npos);
}
