// What the sweep's gtests share: temporary sweep files, loading one and
// catching its refusal, running a spec on a backend, the relative metric
// comparison, and the shipped studies (config/sweeps/) cut to fewer samples.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <fstream>
#include <string>
#include <vector>

#include "aurora_sweep/backends.h"
#include "aurora_sweep/sweep_file.h"

namespace aurora_sweep {
namespace test {

inline const std::string& configDir() {
  static const std::string dir = AURORA_CONFIG_DIR;
  return dir;
}

// The sweep's test data (aurora_sweep/test/data: reference results).
inline const std::string& dataDir() {
  static const std::string dir = std::string(AURORA_SWEEP_TEST_DIR) + "/data";
  return dir;
}

// How many of two runs' results differ in any byte, and by how many their
// counts differ (0: bit-identical).
inline long differing(const std::vector<SimResult>& a, const std::vector<SimResult>& b) {
  long n = 0;
  for (size_t i = 0; i < a.size() && i < b.size(); ++i) n += std::memcmp(&a[i], &b[i], sizeof(SimResult)) != 0;
  return n + static_cast<long>(a.size() > b.size() ? a.size() - b.size() : b.size() - a.size());
}

inline std::string writeTemp(const std::string& name, const std::string& text) {
  const std::string path = ::testing::TempDir() + "/" + name;
  std::ofstream(path) << text;
  return path;
}

inline std::string readText(const std::string& path) {
  std::ifstream in(path);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

// The message of loading sweep file text `yaml`; empty if it loaded.
inline std::string refusal(const std::string& yaml) {
  static int n = 0;
  try {
    loadSweepFile(writeTemp("bad_sweep_" + std::to_string(n++) + ".yaml", yaml), configDir());
  } catch (const ConfigError& e) {
    return e.what();
  }
  return "";
}

// `spec` on backend `key`: "scalar", "cpu" (the build chosen at run time) or
// one of the cpu backend's builds (cpuBatchIsas) on `threads` threads.
inline std::vector<SimResult> runOn(const std::string& key, const SweepSpec& spec, int threads = 2) {
  std::vector<SimResult> out;
  Progress progress{0};
  if (key == "scalar") runScalar(spec, out, progress);
  else if (key == "cpu") runCpuBatch(spec, threads, out, progress);
  else runCpuBatchOn(key, spec, threads, out, progress);
  EXPECT_EQ(progress.load(), spec.rangeSize()) << key;
  return out;
}

// `view`'s axes: parameter params[a] over axes[a] (axis 0 varies fastest;
// the values stay in `axes`), one run per combination; `fixed` is the
// caller's.
inline void setAxes(GridView& view, const int* params, const std::vector<std::vector<double>>& axes) {
  view.n_axes = static_cast<int>(axes.size());
  for (int a = 0; a < view.n_axes; ++a) {
    view.param[a] = params[a];
    view.count[a] = static_cast<long>(axes[a].size());
    view.values[a] = axes[a].data();
  }
  view.points = nullptr, view.n_points = 0, view.points_first = 0, view.point_cols = 0;
  view.repeats = 1;
}

// A launch of `n` runs in blocks of `block` threads, on the host: thread(b,
// t, out) for every (block, thread), as the kernel's threads would run; the
// records they wrote.
template <class Thread>
std::vector<SimResult> launchOnHost(long n, int block, Thread&& thread) {
  std::vector<SimResult> out(static_cast<size_t>(n));
  for (long b = 0; b < (n + block - 1) / block; ++b) {
    for (int t = 0; t < block; ++t) thread(unsigned(b), unsigned(block), unsigned(t), out.data());
  }
  return out;
}

// The build the cpu backend picks on this CPU (the first supported one).
inline std::string widestIsa() {
  for (const CpuIsa& isa : cpuBatchIsas()) {
    if (isa.supported) return isa.key;
  }
  return "none";
}

inline bool relClose(double a, double b, double rel) {
  return a == b || std::fabs(a - b) <= rel * std::max(std::fabs(a), std::fabs(b));
}

// SIMD records against the scalar loop's: flags and step counts equal,
// metrics to `rel` (xsimd's sin and cos differ from libm's in the last
// bits), over at least `min_compared` runs that did not diverge.
inline void expectRecordsAgree(const std::string& key, const std::vector<SimResult>& scalar,
                               const std::vector<SimResult>& simd, double rel, int min_compared) {
  ASSERT_EQ(simd.size(), scalar.size());
  int compared = 0;
  for (size_t i = 0; i < scalar.size(); ++i) {
    EXPECT_EQ(scalar[i].ok, simd[i].ok) << key << " combination " << i;
    EXPECT_EQ(scalar[i].steps, simd[i].steps) << key << " combination " << i;
    if (!(scalar[i].ok & 1)) continue;  // diverged: the metrics are meaningless
    ++compared;
    EXPECT_PRED3(relClose, scalar[i].iae, simd[i].iae, rel) << key << " " << i;
    EXPECT_PRED3(relClose, scalar[i].itae, simd[i].itae, rel) << key << " " << i;
    EXPECT_PRED3(relClose, scalar[i].iasc, simd[i].iasc, rel) << key << " " << i;
    // A formation's ground_command: a float, so to its last bits at least.
    EXPECT_PRED3(relClose, double(scalar[i].extra), double(simd[i].extra), std::max(rel, 1e-6)) << key << " " << i;
  }
  EXPECT_GE(compared, min_compared) << key;
}

// Another backend's runs (SIMD lanes, a GPU) against the scalar loop's, for
// laws whose runs may oscillate against a clamp for their whole length (the
// Bebop's and the Pioneer's): the check flags and step counts of all but
// `flag_share` of the runs equal (0: all); the metrics to 1e-9 relative for
// nine runs in ten at least (xsimd's and the device's tanh, sin and cos
// differ from libm's in the last bits) and to 1e-2 for every run whose flags
// agree (such a run amplifies those bits over its 60 s).
inline void expectRunsAgree(const std::vector<SimResult>& scalar, const std::vector<SimResult>& other,
                            double flag_share) {
  ASSERT_EQ(scalar.size(), other.size());
  long loose = 0, flags = 0;
  for (size_t i = 0; i < scalar.size(); ++i) {
    if (scalar[i].ok != other[i].ok || scalar[i].steps != other[i].steps) {
      ++flags;
      continue;
    }
    bool close = true;
    for (auto m : {&SimResult::iae, &SimResult::itae, &SimResult::iasc}) {
      EXPECT_PRED3(relClose, scalar[i].*m, other[i].*m, 1e-2) << i;
      close = close && relClose(scalar[i].*m, other[i].*m, 1e-9);
    }
    loose += !close;
  }
  EXPECT_LE(double(flags), flag_share * double(scalar.size())) << flags << " runs whose checks or steps differ";
  EXPECT_LE(loose * 10, static_cast<long>(scalar.size())) << loose << " runs beyond 1e-9";
}

// How far another backend's runs are from the scalar loop's: the runs whose
// check flags or steps differ; among the others, the runs whose metrics
// (IAE, ITAE, IASC; a formation's IAEs) differ beyond 1e-9 and 1e-2
// relative, and the largest relative difference (with its run).
struct RunDifferences {
  long runs = 0, flags = 0, beyond_1e9 = 0, beyond_1e2 = 0, worst_run = -1;
  double worst = 0;
  std::string text() const {
    return std::to_string(runs) + " runs: " + std::to_string(flags) + " with other flags or steps, " +
           std::to_string(beyond_1e9) + " beyond 1e-9, " + std::to_string(beyond_1e2) +
           " beyond 1e-2, largest relative difference " + std::to_string(worst) + " (run " + std::to_string(worst_run) + ")";
  }
};

inline double relDifference(double a, double b) {
  if (a == b) return 0.0;
  const double scale = std::max(std::fabs(a), std::fabs(b));
  return scale > 0 ? std::fabs(a - b) / scale : 0.0;
}

inline RunDifferences runDifferences(const std::vector<SimResult>& scalar, const std::vector<SimResult>& other) {
  RunDifferences d;
  d.runs = static_cast<long>(std::min(scalar.size(), other.size()));
  d.flags = static_cast<long>(std::max(scalar.size(), other.size())) - d.runs;
  for (long i = 0; i < d.runs; ++i) {
    const SimResult &a = scalar[static_cast<size_t>(i)], &b = other[static_cast<size_t>(i)];
    if (a.ok != b.ok || a.steps != b.steps) {
      ++d.flags;
      continue;
    }
    double rel = 0.0;
    for (auto m : {&SimResult::iae, &SimResult::itae, &SimResult::iasc}) rel = std::max(rel, relDifference(a.*m, b.*m));
    d.beyond_1e9 += rel > 1e-9, d.beyond_1e2 += rel > 1e-2;
    if (rel > d.worst) d.worst = rel, d.worst_run = i;
  }
  return d;
}

// A GPU's runs against the scalar loop, measured against the CPU's own SIMD
// lanes on the same spec: both compute tanh, sin and cos otherwise than
// libm in the last bits (xsimd, the device's math library), and a run on
// the edge of a check, or one that swings for its whole length (the Bebop
// at 5 Hz under long delays, float triangles), turns those bits into other
// outcomes. Measured (bebop2_delay_5hz, 12,288 runs): the lanes 27 runs
// with other flags and 274 beyond 1e-2, an H200 26 and 281. So the device
// may be as far as the lanes, twice over (small counts), and at most
// `flag_share` of the runs (and none beyond 1e-2, nine in ten within 1e-9)
// where the lanes agree: a defect of the device's code (a wrong index, a
// lost parameter) moves far more runs than that.
inline void expectNoFurtherThanLanes(const std::vector<SimResult>& scalar, const std::vector<SimResult>& device,
                                     const std::vector<SimResult>& lanes, double flag_share) {
  const RunDifferences d = runDifferences(scalar, device), l = runDifferences(scalar, lanes);
  const std::string said = "device: " + d.text() + "; CPU lanes: " + l.text();
  EXPECT_LE(double(d.flags), std::max(flag_share * double(d.runs), 2.0 * double(l.flags))) << said;
  EXPECT_LE(d.beyond_1e2, 2 * l.beyond_1e2) << said;
  EXPECT_LE(d.beyond_1e9, std::max(d.runs / 10, 2 * l.beyond_1e9)) << said;
  EXPECT_LE(d.worst, std::max(1e-9, 10.0 * l.worst)) << said;
}

// One SIMD build against the scalar loop on the same spec.
inline void expectAgreement(const std::string& key, const SweepSpec& spec, double rel, int min_compared = 20) {
  expectRecordsAgree(key, runOn("scalar", spec), runOn(key, spec), rel, min_compared);
}

// config/sweeps/NAME.yaml with `samples_line` replaced by `samples` (relative
// names resolve in config/).
inline SweepSpec shippedStudy(const std::string& name, const std::string& samples_line, long samples,
                              Precision precision) {
  std::string text = readText(configDir() + "/sweeps/" + name + ".yaml");
  const size_t at = text.find(samples_line);
  EXPECT_NE(at, std::string::npos) << name;
  if (at != std::string::npos) text.replace(at, samples_line.size(), "samples: " + std::to_string(samples));
  SweepSpec spec = loadSweepFile(writeTemp(name + "_small.yaml", text), configDir());
  spec.precision = precision;
  return spec;
}

inline SweepSpec study13(long samples, Precision p = Precision::kDouble) {
  return shippedStudy("underactuated_13", "samples: 65536", samples, p);
}
inline SweepSpec robustness(long samples, Precision p = Precision::kDouble) {
  return shippedStudy("robustness", "samples: 4096", samples, p);
}

}  // namespace test
}  // namespace aurora_sweep
