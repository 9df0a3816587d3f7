// The cuda backend against the cpu backend, where a GPU exists (built only
// with nvcc). Without a usable device the tests skip, saying why.
#include <gtest/gtest.h>

#include <cmath>

#include "aurora_sweep/backends.h"
#include "aurora_sweep/cuda_backend.h"
#include "aurora_sweep/sweep_file.h"
#include "sweep_test_support.h"

using namespace aurora_sweep;

namespace {

bool skipWithoutDevice() {
  const CudaDevice dev = probeCudaDevice();
  if (!dev.usable) {
    std::fprintf(stderr, "[  SKIPPED ] no usable CUDA device: %s\n", dev.error.c_str());
    return true;
  }
  std::fprintf(stderr, "CUDA device: %s\n", dev.name.c_str());
  return false;
}

SweepSpec thesisGrid(Precision p) {
  SweepSpec spec = loadSweepFile(std::string(AURORA_CONFIG_DIR) + "/sweeps/positioning_delay.yaml",
                                 AURORA_CONFIG_DIR);
  spec.precision = p;
  return spec;
}

}  // namespace

TEST(CudaBackend, DoubleMatchesCpuOnTheThesisGrid) {
  if (skipWithoutDevice()) GTEST_SKIP() << "no usable CUDA device";
  const SweepSpec spec = thesisGrid(Precision::kDouble);
  std::vector<SimResult> gpu, cpu;
  Progress progress{0};
  const CudaRun run = runCuda(spec, 0, gpu);
  runCpuBatch(spec, 4, cpu, progress);
  ASSERT_EQ(gpu.size(), cpu.size());
  long flag_diff = 0, metric_diff = 0;
  for (size_t i = 0; i < gpu.size(); ++i) {
    flag_diff += gpu[i].ok != cpu[i].ok;
    if ((cpu[i].ok & 1) && gpu[i].ok == cpu[i].ok) {
      const double a[3] = {gpu[i].iae, gpu[i].itae, gpu[i].iasc};
      const double b[3] = {cpu[i].iae, cpu[i].itae, cpu[i].iasc};
      for (int k = 0; k < 3; ++k) {
        if (std::fabs(a[k] - b[k]) > 1e-9 * std::fabs(b[k])) ++metric_diff;
      }
    }
  }
  std::fprintf(stderr, "cuda double: kernel %.4f s, total %.4f s, block %d; flag differences %ld, "
               "metric differences %ld\n", run.kernel_s, run.total_s, run.block_size, flag_diff, metric_diff);
  EXPECT_EQ(flag_diff, 0);
  EXPECT_EQ(metric_diff, 0);
}

TEST(CudaBackend, FloatFeasibleFlagsAgreeWithDouble) {
  if (skipWithoutDevice()) GTEST_SKIP() << "no usable CUDA device";
  std::vector<SimResult> gpu_float, cpu_double;
  Progress progress{0};
  runCuda(thesisGrid(Precision::kFloat), 0, gpu_float);
  runCpuBatch(thesisGrid(Precision::kDouble), 4, cpu_double, progress);
  long agree = 0;
  for (size_t i = 0; i < gpu_float.size(); ++i) {
    agree += ((gpu_float[i].ok >> 4) & 1) == ((cpu_double[i].ok >> 4) & 1);
  }
  const double share = double(agree) / gpu_float.size();
  std::fprintf(stderr, "cuda float vs cpu double: feasible flags agree on %.4f %%\n", 100 * share);
  EXPECT_GE(share, 0.995);
}

namespace {

// CUDA against the cpu backend on one spec: double identical flags and
// metrics to 1e-9 relative.
void expectCudaMatchesCpu(const SweepSpec& spec, const char* what) {
  std::vector<SimResult> gpu, cpu;
  Progress progress{0};
  const CudaRun run = runCuda(spec, 0, gpu);
  runCpuBatch(spec, 4, cpu, progress);
  ASSERT_EQ(gpu.size(), cpu.size());
  long flag_diff = 0, metric_diff = 0, feasible = 0;
  for (size_t i = 0; i < gpu.size(); ++i) {
    flag_diff += gpu[i].ok != cpu[i].ok || gpu[i].steps != cpu[i].steps;
    feasible += (cpu[i].ok >> 4) & 1;
    if (!(cpu[i].ok & 1) || gpu[i].ok != cpu[i].ok) continue;
    const double a[3] = {gpu[i].iae, gpu[i].itae, gpu[i].iasc};
    const double b[3] = {cpu[i].iae, cpu[i].itae, cpu[i].iasc};
    for (int k = 0; k < 3; ++k) metric_diff += std::fabs(a[k] - b[k]) > 1e-9 * std::fabs(b[k]);
  }
  std::fprintf(stderr, "cuda %s (%zu runs, %ld feasible): kernel %.4f s, total %.4f s, block %d; flag "
               "differences %ld, metric differences %ld\n", what, gpu.size(), feasible, run.kernel_s,
               run.total_s, run.block_size, flag_diff, metric_diff);
  EXPECT_GT(feasible, 0);
  EXPECT_EQ(flag_diff, 0);
  EXPECT_EQ(metric_diff, 0);
}

double floatFlagShare(const SweepSpec& float_spec, const SweepSpec& double_spec) {
  std::vector<SimResult> gpu_float, cpu_double;
  Progress progress{0};
  runCuda(float_spec, 0, gpu_float);
  runCpuBatch(double_spec, 4, cpu_double, progress);
  long agree = 0;
  for (size_t i = 0; i < gpu_float.size(); ++i) {
    agree += ((gpu_float[i].ok >> 4) & 1) == ((cpu_double[i].ok >> 4) & 1);
  }
  return double(agree) / double(gpu_float.size());
}

}  // namespace

TEST(CudaBackend, StudiesMatchCpuInDouble) {
  if (skipWithoutDevice()) GTEST_SKIP() << "no usable CUDA device";
  expectCudaMatchesCpu(test::study13(4096), "underactuated_13 (4096 samples)");
  expectCudaMatchesCpu(test::robustness(4096), "robustness");
}

TEST(CudaBackend, StudiesFloatFlagsTrackDouble) {
  if (skipWithoutDevice()) GTEST_SKIP() << "no usable CUDA device";
  const double ua = floatFlagShare(test::study13(4096, Precision::kFloat), test::study13(4096));
  const double rob = floatFlagShare(test::robustness(4096, Precision::kFloat), test::robustness(4096));
  std::fprintf(stderr, "cuda float vs cpu double: underactuated_13 %.4f %%, robustness %.4f %%\n", 100 * ua, 100 * rob);
  EXPECT_GE(ua, 0.995);
  EXPECT_GE(rob, 0.995);
}

// The full 13-parameter study on the GPU: kernel and total time (the thesis:
// 10.39 s on a T4), printed for the closing note.
TEST(CudaBackend, TheFullThirteenParameterStudy) {
  if (skipWithoutDevice()) GTEST_SKIP() << "no usable CUDA device";
  for (Precision p : {Precision::kFloat, Precision::kDouble}) {
    std::vector<SimResult> out;
    const CudaRun run = runCuda(test::study13(65536, p), 0, out);
    long feasible = 0;
    for (const SimResult& r : out) feasible += (r.ok >> 4) & 1;
    std::fprintf(stderr, "cuda underactuated_13 %s: kernel %.4f s, total %.4f s, block %d, %ld feasible\n",
                 precisionName(p), run.kernel_s, run.total_s, run.block_size, feasible);
    EXPECT_EQ(out.size(), 65536u);
  }
}
