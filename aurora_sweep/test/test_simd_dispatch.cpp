// The cpu backend's instruction sets, chosen at run time: every build this
// CPU runs gives the scalar backend's results (flags and step counts equal,
// metrics to the libm differences), in double and float; the environment
// override picks a build or is refused before any output is written.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <sys/wait.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>

#include "aurora_sweep/backends.h"
#include "aurora_sweep/sweep_file.h"
#include "sweep_test_support.h"

using namespace aurora_sweep;

namespace {

using test::relClose;
using test::runOn;

using test::expectAgreement;

}  // namespace

TEST(SimdDispatch, BuildsAreListedWidestFirstWithTheFallbackLast) {
  const std::vector<CpuIsa> isas = cpuBatchIsas();
  ASSERT_GE(isas.size(), 1u);
  EXPECT_EQ(isas.back().key, "none");
  EXPECT_TRUE(isas.back().supported);
  // The builds CMake made (an x86-64 build makes all three, so a binary made
  // here runs on any x86-64 CPU), widest first.
  std::vector<std::string> expected;
#ifdef AURORA_SWEEP_ISA_NATIVE
  expected.push_back("native");
#endif
#ifdef AURORA_SWEEP_ISA_AVX512
  expected.push_back("avx512");
#endif
#ifdef AURORA_SWEEP_ISA_AVX2
  expected.push_back("avx2");
#endif
#ifdef AURORA_SWEEP_ISA_SSE4_2
  expected.push_back("sse4_2");
#endif
  expected.push_back("none");
  ASSERT_EQ(isas.size(), expected.size());
  for (size_t i = 0; i < expected.size(); ++i) EXPECT_EQ(isas[i].key, expected[i]);
#if defined(__x86_64__)
  if (expected.size() > 1 && expected[0] != "native") EXPECT_EQ(expected.size(), 4u);
#endif
  std::string supported;
  for (const CpuIsa& isa : isas) supported += isa.supported ? isa.key + " " : "";
  std::printf("builds this CPU runs: %s\n", supported.c_str());
}

TEST(SimdDispatch, EveryBuildThisCpuRunsAgreesWithTheScalarLoop) {
  int forced = 0;
  for (const CpuIsa& isa : cpuBatchIsas()) {
    if (!isa.supported) {
      std::printf("%s: not run (this CPU lacks it)\n", isa.key.c_str());
      continue;
    }
    SCOPED_TRACE(isa.key + " (" + isa.name + ")");
    SweepSpec spec = loadSweepFile(test::dataDir() + "/small_grid.yaml", test::configDir());
    expectAgreement(isa.key, spec, 1e-9);
    spec.precision = Precision::kFloat;
    // float: the flags and step counts still agree on this grid; metrics to float rounding
    expectAgreement(isa.key, spec, 2e-3);
    ++forced;
  }
  EXPECT_GE(forced, 1);  // the fallback always runs
#if defined(__x86_64__)
  // With SIMD builds (xsimd 8; Ubuntu 20.04's xsimd 7 has none), an SSE4.2
  // CPU runs at least the sse4_2 one besides the fallback.
  if (cpuBatchIsas().size() > 1 && __builtin_cpu_supports("sse4.2")) EXPECT_GE(forced, 2);
#endif
}

TEST(SimdDispatch, AnUnknownOrUnsupportedBuildIsRefused) {
  const SweepSpec spec = loadSweepFile(test::dataDir() + "/small_grid.yaml", test::configDir());
  std::vector<SimResult> out;
  Progress progress{0};
  try {
    runCpuBatchOn("avx1024", spec, 1, out, progress);
    FAIL() << "avx1024 accepted";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("is not one of the builds: "), std::string::npos) << e.what();
  }
  for (const CpuIsa& isa : cpuBatchIsas()) {
    if (isa.supported) continue;
    EXPECT_THROW(runCpuBatchOn(isa.key, spec, 1, out, progress), std::runtime_error) << isa.key;
  }
}

#ifdef AURORA_SWEEP_BIN
namespace {
int runSweepWith(const std::string& env, const std::string& args, std::string& output) {
  FILE* p = popen((env + " " + std::string(AURORA_SWEEP_BIN) + " " + args + " 2>&1").c_str(), "r");
  char buf[512];
  output.clear();
  while (fgets(buf, sizeof buf, p)) output += buf;
  const int status = pclose(p);
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

std::string readFile(const std::string& path) {
  std::stringstream ss;
  ss << std::ifstream(path).rdbuf();
  return ss.str();
}
}  // namespace

TEST(SimdDispatch, TheEnvironmentPicksTheBuild) {
  for (const CpuIsa& isa : cpuBatchIsas()) {
    if (!isa.supported) continue;
    const std::string out = ::testing::TempDir() + "/simd_env_" + isa.key;
    std::string log;
    ASSERT_EQ(runSweepWith("AURORA_SWEEP_SIMD=" + isa.key,
                           "--config " + test::dataDir() + "/small_grid.yaml --config-dir " + test::configDir() +
                               " --out " + out + " --backend cpu --no-plots --quiet --overwrite",
                           log),
              0)
        << log;
    EXPECT_NE(readFile(out + "/summary.json").find("(" + isa.key + ", chosen at run time)"),
              std::string::npos)
        << readFile(out + "/summary.json");
  }
  const std::string refused = ::testing::TempDir() + "/simd_env_refused";
  std::string log;
  EXPECT_EQ(runSweepWith("AURORA_SWEEP_SIMD=avx1024",
                         "--config " + test::dataDir() + "/small_grid.yaml --config-dir " + test::configDir() +
                             " --out " + refused + " --backend cpu --no-plots --quiet",
                         log),
            2)
      << log;
  EXPECT_NE(log.find("AURORA_SWEEP_SIMD=avx1024 is not one of the builds"), std::string::npos) << log;
  struct stat st;
  EXPECT_NE(stat(refused.c_str(), &st), 0) << "the refused run left " << refused << " behind";
}
#endif
