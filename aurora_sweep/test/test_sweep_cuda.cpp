// The cuda backend against the cpu backend, where a GPU exists (built only
// with nvcc). Without a usable device the tests skip, saying why; with
// AURORA_REQUIRE_CUDA=1 (on a GPU machine) a missing device fails them.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cmath>
#include <cstdlib>
#include <algorithm>
#include <fstream>

#include "aurora_sweep/backends.h"
#include "aurora_sweep/cuda_backend.h"
#include "aurora_sweep/sweep_file.h"
#include "sweep_test_support.h"

using namespace aurora_sweep;

namespace {

bool skipWithoutDevice() {
  const CudaDevice dev = probeCudaDevice();
  if (dev.usable) {
    std::fprintf(stderr, "CUDA device: %s\n", dev.name.c_str());
    return false;
  }
  const char* require = std::getenv("AURORA_REQUIRE_CUDA");
  if (require && std::string(require) == "1") {
    ADD_FAILURE() << "AURORA_REQUIRE_CUDA=1 but no usable CUDA device: " << dev.error;
  } else {
    std::fprintf(stderr, "[  SKIPPED ] no usable CUDA device: %s\n", dev.error.c_str());
  }
  return true;
}

SweepSpec thesisGrid(Precision p) {
  SweepSpec spec = loadSweepFile(std::string(AURORA_CONFIG_DIR) + "/sweeps/positioning_delay.yaml",
                                 AURORA_CONFIG_DIR);
  spec.precision = p;
  return spec;
}

}  // namespace

// A skip, or a failure under AURORA_REQUIRE_CUDA=1.
#define SKIP_WITHOUT_DEVICE()                                   \
  do {                                                          \
    if (skipWithoutDevice()) {                                  \
      if (!HasFailure()) GTEST_SKIP() << "no usable CUDA device"; \
      return;                                                   \
    }                                                           \
  } while (0)

TEST(CudaBackend, DoubleMatchesCpuOnTheThesisGrid) {
  SKIP_WITHOUT_DEVICE();
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
  SKIP_WITHOUT_DEVICE();
  std::vector<SimResult> gpu_float, cpu_double;
  Progress progress{0};
  runCuda(thesisGrid(Precision::kFloat), 0, gpu_float);
  runCpuBatch(thesisGrid(Precision::kDouble), 4, cpu_double, progress);
  long agree = 0;
  for (size_t i = 0; i < gpu_float.size(); ++i) {
    agree += feasible(gpu_float[i]) == feasible(cpu_double[i]);
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
    feasible += aurora_sweep::feasible(cpu[i]);
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
    agree += feasible(gpu_float[i]) == feasible(cpu_double[i]);
  }
  return double(agree) / double(gpu_float.size());
}

}  // namespace

TEST(CudaBackend, StudiesMatchCpuInDouble) {
  SKIP_WITHOUT_DEVICE();
  expectCudaMatchesCpu(test::study13(4096), "underactuated_13 (4096 samples)");
  expectCudaMatchesCpu(test::robustness(4096), "robustness");
}

TEST(CudaBackend, StudiesFloatFlagsTrackDouble) {
  SKIP_WITHOUT_DEVICE();
  const double ua = floatFlagShare(test::study13(4096, Precision::kFloat), test::study13(4096));
  const double rob = floatFlagShare(test::robustness(4096, Precision::kFloat), test::robustness(4096));
  std::fprintf(stderr, "cuda float vs cpu double: underactuated_13 %.4f %%, robustness %.4f %%\n", 100 * ua, 100 * rob);
  EXPECT_GE(ua, 0.995);
  EXPECT_GE(rob, 0.995);
}

// The full 13-parameter study on the GPU: kernel and total time (the thesis:
// 10.39 s on a T4), printed for the closing note.
TEST(CudaBackend, TheFullThirteenParameterStudy) {
  SKIP_WITHOUT_DEVICE();
  for (Precision p : {Precision::kFloat, Precision::kDouble}) {
    std::vector<SimResult> out;
    const CudaRun run = runCuda(test::study13(65536, p), 0, out);
    long feasible = 0;
    for (const SimResult& r : out) feasible += aurora_sweep::feasible(r);
    std::fprintf(stderr, "cuda underactuated_13 %s: kernel %.4f s, total %.4f s, block %d, %ld feasible\n",
                 precisionName(p), run.kernel_s, run.total_s, run.block_size, feasible);
    EXPECT_EQ(out.size(), 65536u);
  }
}

namespace {

// Every field of every result: flags and steps equal, the final position
// to float rounding, the metrics to 1e-9 relative (libm differences).
long fieldDifferences(const std::vector<SimResult>& gpu, const std::vector<SimResult>& cpu) {
  long diff = 0;
  for (size_t i = 0; i < gpu.size() && i < cpu.size(); ++i) {
    const SimResult &a = gpu[i], &b = cpu[i];
    bool same = a.ok == b.ok && a.steps == b.steps;
    for (int k = 0; k < 3; ++k) same = same && std::fabs(a.final_pos[k] - b.final_pos[k]) <= 1e-5f * (1 + std::fabs(b.final_pos[k]));
    if (b.ok & 1) {
      same = same && test::relClose(a.iae, b.iae, 1e-9) && test::relClose(a.itae, b.itae, 1e-9) &&
             test::relClose(a.iasc, b.iasc, 1e-9);
    }
    diff += !same;
  }
  return diff + static_cast<long>(gpu.size() != cpu.size());
}

// The chunks of `spec` in launches of `chunk` combinations, concatenated.
std::vector<SimResult> cudaInChunks(SweepSpec spec, long chunk) {
  std::vector<SimResult> all, part;
  const long total = spec.size();
  for (long first = 0; first < total; first += chunk) {
    spec.range_begin = first;
    spec.range_end = std::min(total, first + chunk);
    runCuda(spec, 0, part);
    all.insert(all.end(), part.begin(), part.end());
  }
  return all;
}

}  // namespace

// Several chunks of an odd size (offsets into the grid and into a design's
// rows, a last short chunk) against the cpu backend, every field.
TEST(CudaBackend, ChunksOfAnOddSizeMatchCpuInEveryField) {
  SKIP_WITHOUT_DEVICE();
  const SweepSpec grid = thesisGrid(Precision::kDouble);
  EXPECT_EQ(fieldDifferences(cudaInChunks(grid, 4099), test::runOn("cpu", grid, 4)), 0);
  const SweepSpec design = test::study13(4096);
  EXPECT_EQ(fieldDifferences(cudaInChunks(design, 1001), test::runOn("cpu", design, 4)), 0);
}

// Offsets above 2^32 (a 10^13 grid), against the scalar loop.
TEST(CudaBackend, OffsetsAboveTwoToTheThirtyTwo) {
  SKIP_WITHOUT_DEVICE();
  SweepSpec spec = loadSweepFile(test::writeTemp("huge_cuda.yaml",
      "sweep:\n  parameters:\n    kp: {from: 0.1, to: 1, count: 100000}\n    kd: {from: 0.1, to: 1, count: 100000}\n"
      "    delay: {values: [0, 3, 9]}\n"), AURORA_CONFIG_DIR);
  spec.range_begin = (1L << 32) + 3;
  spec.range_end = spec.range_begin + 4099;
  std::vector<SimResult> gpu;
  runCuda(spec, 0, gpu);
  EXPECT_EQ(fieldDifferences(gpu, test::runOn("scalar", spec)), 0);
}

// The 512-sample history tier of both laws (delays 64 to 511).
TEST(CudaBackend, TheLongHistoryTierOfBothLaws) {
  SKIP_WITHOUT_DEVICE();
  for (const char* law : {"pd_saturated", "underactuated"}) {
    const std::string gains = std::string(law) == "pd_saturated" ? "    kp: {from: 0.2, to: 1.0, count: 8}\n    kd: 0.85\n"
                                                                 : "    k1_x: {from: 0.2, to: 1.0, count: 8}\n";
    const SweepSpec spec = loadSweepFile(test::writeTemp(std::string("tier512_") + law + ".yaml",
        std::string("sweep:\n  controller: ") + law + "\n  early_stop: false\n  parameters:\n" + gains +
        "    delay: {values: [0, 64, 200, 511]}\n"), AURORA_CONFIG_DIR);
    std::vector<SimResult> gpu;
    runCuda(spec, 0, gpu);
    EXPECT_EQ(fieldDifferences(gpu, test::runOn("cpu", spec, 4)), 0) << law;
  }
}

// Over links (a kernel of its own): a link file, link values varied, a
// points design with repeats in chunks of an odd size, both laws and both
// history tiers, against the cpu backend (its SIMD lanes, each with its own
// link) and the scalar loop.
TEST(CudaBackend, LinkSweepsMatchCpu) {
  SKIP_WITHOUT_DEVICE();
  const std::string grid = test::readText(std::string(AURORA_SWEEP_TEST_DIR) + "/data/small_grid.yaml");
  const SweepSpec congested = loadSweepFile(test::writeTemp("cuda_congested.yaml", grid + "  link: links/wifi_congested.yaml\n"),
                                            AURORA_CONFIG_DIR);
  std::vector<SimResult> gpu;
  runCuda(congested, 0, gpu);
  EXPECT_EQ(fieldDifferences(gpu, test::runOn("scalar", congested)), 0);
  for (const char* law : {"pd_saturated", "underactuated"}) {
    const std::string gains = std::string(law) == "pd_saturated" ? "    kp: 0.5\n    kd: 0.85\n" : "";
    for (const char* delays : {"[0, 6, 12]", "[0, 100, 400]"}) {
      const SweepSpec spec = loadSweepFile(test::writeTemp(std::string("cuda_link_") + law + ".yaml",
          std::string("sweep:\n  controller: ") + law + "\n  repeats: 3\n  early_stop: false\n  parameters:\n" + gains +
          "    delay: {values: " + delays + "}\n    uplink_jitter: {values: [0, 5]}\n    uplink_loss: {values: [0, 0.3]}\n"
          "    downlink_delay: 2\n    downlink_loss: 0.1\n    downlink_burst: 4\n"), AURORA_CONFIG_DIR);
      EXPECT_EQ(fieldDifferences(cudaInChunks(spec, 7), test::runOn("cpu", spec, 4)), 0) << law << " " << delays;
    }
  }
}

// Formation sweeps, one formation per thread (docs/formation.md, "Formation
// sweeps"): both laws, double and float, ideal and over lossy links with
// repeats, in launches of 5, against the scalar loop (the same code), no
// further from it than the CPU's SIMD lanes (expectNoFurtherThanLanes: on
// an H200 one run of line_lemniscate_ik beyond 1e-9 in double, where the
// lanes reach 4.5e-10 over lossy links). Delays up to 15 samples: beyond,
// the flights swing so hard that last-bit differences grow into other
// outcomes.
TEST(CudaBackend, FormationSweepsMatchTheScalarLoop) {
  SKIP_WITHOUT_DEVICE();
  const std::string grid = "  parameters:\n    delay_1: {values: [0, 9, 15]}\n    delay_2: {values: [0, 15]}\n"
                           "    formation_k1_rho: {values: [0.75, 1.5]}\n";
  const std::string lossy = grid + "    uplink_jitter: 2\n    uplink_loss: 0.1\n    downlink_loss: 0.05\n  repeats: 3\n";
  const std::string own = grid + "    uplink_loss_2: 0.3\n    downlink_jitter_1: 2\n  repeats: 2\n";  // per drone
  for (const char* file : {"line_lemniscate", "line_lemniscate_ik"}) {
    for (const std::string& body : {grid, lossy, own}) {
      SweepSpec spec = loadSweepFile(test::writeTemp(std::string("cuda_formation_") + file + ".yaml",
          std::string("sweep:\n  early_stop: false\n  formation: formations/") + file + ".yaml\n" + body), AURORA_CONFIG_DIR);
      SCOPED_TRACE(std::string(file) + ": " + body);
      test::expectNoFurtherThanLanes(test::runOn("scalar", spec), cudaInChunks(spec, 5), test::runOn("cpu", spec), 0.0);
      spec.precision = Precision::kFloat;
      const std::vector<SimResult> gpu = cudaInChunks(spec, 5), cpu = test::runOn("scalar", spec);
      const test::RunDifferences d = test::runDifferences(cpu, gpu), l = test::runDifferences(cpu, test::runOn("cpu", spec));
      EXPECT_LE(d.flags, 2 * l.flags) << "float: device " << d.text() << "; CPU lanes " << l.text();
    }
  }
}

// The Bebop 2's and the Pioneer's delay studies (each law's own kernel) on
// the GPU against the scalar loop, in double: the checks of all but 0.1 %
// of the runs equal (the device's tanh, sin and cos differ from libm's in
// the last bits, and a run on the edge of a check may go either way), or
// no more than twice as many as the CPU's SIMD lanes' (the Bebop at 5 Hz:
// expectNoFurtherThanLanes).
TEST(CudaBackend, TheOtherVehiclesStudiesMatchTheScalarLoop) {
  SKIP_WITHOUT_DEVICE();
  for (const char* study : {"bebop2_delay", "bebop2_delay_5hz", "pioneer_delay"}) {
    SCOPED_TRACE(study);
    const SweepSpec spec = loadSweepFile(std::string(AURORA_CONFIG_DIR) + "/sweeps/" + study + ".yaml", AURORA_CONFIG_DIR);
    std::vector<SimResult> gpu;
    runCuda(spec, 0, gpu);
    test::expectNoFurtherThanLanes(test::runOn("scalar", spec), gpu, test::runOn("cpu", spec), 1e-3);
  }
}

// Launch limits are known before the run: a block too large for the
// kernel's registers is refused with the largest accepted.
TEST(CudaBackend, LaunchProblemsAreKnownBeforeTheRun) {
  SKIP_WITHOUT_DEVICE();
  SweepSpec spec = test::study13(64);
  EXPECT_EQ(cudaLaunchProblem(spec, 0), "");
  const std::string msg = cudaLaunchProblem(spec, 1024);
  EXPECT_NE(msg.find("threads per block"), std::string::npos) << "1024 threads of the underactuated double kernel: " << msg;
  EXPECT_GT(cudaResidentThreads(spec, 0), 0);
}

// The program's own path: sweep --backend cuda (chunked, resumable) gives
// the cpu backend's feasible set.
TEST(CudaBackend, TheSweepProgramOnTheCudaBackend) {
  SKIP_WITHOUT_DEVICE();
  const std::string dir = ::testing::TempDir();
  const std::string base = std::string(AURORA_SWEEP_BIN) + " --config " + AURORA_CONFIG_DIR +
                           "/sweeps/positioning_delay.yaml --no-plots --quiet --overwrite --chunk-size 5001 ";
  for (const char* b : {"cuda", "cpu"}) {
    const int status = std::system((base + "--backend " + b + " --out " + dir + "/prog_" + b + " > /dev/null").c_str());
    ASSERT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << b;
  }
  // The flags and steps of every row (the columns ok1 ... feasible, then steps).
  auto flags = [](const std::string& row) {
    std::vector<std::string> cells;
    size_t from = 0;
    for (size_t comma; (comma = row.find(',', from)) != std::string::npos; from = comma + 1) {
      cells.push_back(row.substr(from, comma - from));
    }
    cells.push_back(row.substr(from));
    return cells;
  };
  std::ifstream cuda_csv(dir + "/prog_cuda/results.csv"), cpu_csv(dir + "/prog_cpu/results.csv");
  std::string a, b;
  std::getline(cuda_csv, a), std::getline(cpu_csv, b);
  const std::vector<std::string> header = flags(b);
  ASSERT_EQ(flags(a), header);
  const size_t ok1 = std::find(header.begin(), header.end(), "ok1") - header.begin();
  const size_t steps = std::find(header.begin(), header.end(), "steps") - header.begin();
  ASSERT_LT(steps, header.size());
  long rows = 0, differ = 0;
  while (std::getline(cuda_csv, a) && std::getline(cpu_csv, b)) {
    ++rows;
    const auto x = flags(a), y = flags(b);
    for (size_t c = ok1; c <= steps; ++c) differ += c < ok1 + 5 || c == steps ? x[c] != y[c] : 0;
  }
  EXPECT_EQ(rows, 65536);
  EXPECT_EQ(differ, 0);
}

// Issue 35: the predictor's kernels fly the AR.Drone's laws (their per-thread
// entry is tested on the host: SweepPredictor.*); another vehicle's law with
// a predictor is refused before any device is asked, naming it (on every
// machine with the CUDA build).
TEST(CudaBackend, PredictingKernelsAreThoseOfTheLawsThatDeclareThem) {
  const std::string c = AURORA_CONFIG_DIR;
  for (const char* study : {"positioning_delay_predictor", "positioning_delay_wifi_congested_predictor",
                            "predictor_robustness"}) {
    EXPECT_EQ(cudaDelayProblem(loadSweepFile(c + "/sweeps/" + study + ".yaml", c)), "") << study;
  }
  const SweepSpec bebop = loadSweepFile(test::writeTemp("cuda_bebop_predictor.yaml",
      "sweep:\n  controller: bebop2_compensator\n  task: tasks/bebop2_waypoints.yaml\n"
      "  parameters:\n    delay: {values: [0, 3]}\n  predictor: {form: smith}\n"), c);
  ASSERT_TRUE(bebop.predicting());
  EXPECT_NE(cudaDelayProblem(bebop).find("has CUDA kernels for the laws pd_saturated, underactuated only, not "
                                         "bebop2_compensator: use --backend cpu"),
            std::string::npos) << cudaDelayProblem(bebop);
}

// The predictor on the GPU against the scalar loop: both forms, both laws,
// ideal and over the congested link, in double (the checks of all but
// 0.1 % of the runs equal: the device's trigonometry differs in the last
// bits) and float (flags track double as the plain kernels' do).
TEST(CudaBackend, PredictorSweepsMatchTheScalarLoop) {
  SKIP_WITHOUT_DEVICE();
  const std::pair<const char*, const char*> laws[] = {
      {"pd_saturated", "    kp: {from: 0.1, to: 0.75, count: 4}\n    kd: {from: 0.2, to: 1.0, count: 3}\n"},
      {"underactuated", "    k1_x: {values: [0.3, 0.5, 1.0]}\n    k2_x: {values: [1.0, 2.0]}\n"}};
  for (const auto& law : laws) {
    for (const char* form : {"resimulate", "smith"}) {
      for (const char* link : {"", "  link: links/wifi_congested.yaml\n"}) {
        SCOPED_TRACE(std::string(law.first) + " " + form + " " + link);
        SweepSpec spec = loadSweepFile(test::writeTemp("cuda_predictor.yaml",
            std::string("sweep:\n  controller: ") + law.first + "\n  task: tasks/positioning.yaml\n"
            "  parameters:\n" + law.second + "    delay: {from: 0, to: 40, count: 6}\n  predictor: {form: " + form +
            "}\n" + link), AURORA_CONFIG_DIR);
        std::vector<SimResult> gpu;
        runCuda(spec, 0, gpu);
        test::expectRunsAgree(test::runOn("scalar", spec), gpu, 1e-3);
      }
    }
  }
}

// AuRoRA's triangle and UAV-UGV line have their kernels (their per-thread
// entry is tested on the host: AuRoRAsFormationSweep.*): accepted before the
// run, as the two-drone line's.
TEST(CudaBackend, AuRoRAsFormationsHaveKernels) {
  const std::string c = AURORA_CONFIG_DIR;
  for (const char* study : {"triangle_delay", "line_pioneer_delay", "formation_delay"}) {
    EXPECT_EQ(cudaDelayProblem(loadSweepFile(c + "/sweeps/" + study + ".yaml", c)), "") << study;
  }
}

// The triangle's three drones and the UAV-UGV line's Pioneer and drone on
// the GPU against the scalar loop: each robot its own delay, ideal and over
// lossy links with repeats, in launches of 5; double (the checks of all but
// 0.1 % of the runs equal) and float (flags), no further from it than the
// CPU's SIMD lanes (float triangles: the lanes 2 of 12 runs with other
// flags, an H200 1).
TEST(CudaBackend, AuRoRAsFormationSweepsMatchTheScalarLoop) {
  SKIP_WITHOUT_DEVICE();
  const std::string triangle = "  parameters:\n    delay_1: {values: [0, 6]}\n    delay_2: {values: [0, 9]}\n"
                               "    delay_3: {values: [0, 3, 12]}\n";
  const std::string line = "  parameters:\n    delay_1: {values: [0, 5, 10]}\n    delay_2: {values: [0, 10, 20]}\n"
                           "    kc1_1: {values: [0.2, 0.35]}\n";
  const std::string lossy = "    uplink_jitter: 2\n    uplink_loss: 0.1\n    downlink_loss: 0.05\n  repeats: 2\n";
  // triangle_ardrones_predictor: its drones on their controller file's predictor (issue 51).
  for (const auto& file_body : {std::make_pair("triangle_ardrones", triangle), std::make_pair("line_pioneer_ardrone", line),
                                std::make_pair("triangle_ardrones_predictor", triangle)}) {
    for (const std::string& extra : {std::string(), lossy}) {
      SCOPED_TRACE(std::string(file_body.first) + (extra.empty() ? " ideal" : " lossy"));
      SweepSpec spec = loadSweepFile(test::writeTemp(std::string("cuda_shape_") + file_body.first + ".yaml",
          std::string("sweep:\n  early_stop: false\n  formation: formations/") + file_body.first + ".yaml\n" +
          file_body.second + extra), AURORA_CONFIG_DIR);
      test::expectNoFurtherThanLanes(test::runOn("scalar", spec), cudaInChunks(spec, 5), test::runOn("cpu", spec), 1e-3);
      spec.precision = Precision::kFloat;
      const std::vector<SimResult> gpu = cudaInChunks(spec, 5), cpu = test::runOn("scalar", spec);
      const test::RunDifferences d = test::runDifferences(cpu, gpu), l = test::runDifferences(cpu, test::runOn("cpu", spec));
      EXPECT_LE(double(d.flags), std::max(double(cpu.size()) / 50, 2.0 * double(l.flags)))
          << "float: device " << d.text() << "; CPU lanes " << l.text();
    }
  }
}
