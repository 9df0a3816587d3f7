// The CUDA kernel's per-thread entry (kernel_entry.h) run on the host for
// every (block, thread) of a launch: the indexing of the kernel is tested in
// CI without a GPU. Results are compared byte for byte with the scalar
// backend (SimResult has no undefined bytes).
#include <gtest/gtest.h>

#include <cstring>
#include <string>
#include <vector>

#include "aurora_sweep/backends.h"
#include "aurora_sweep/kernel_entry.h"
#include "aurora_sweep/sweep_file.h"
#include "sweep_test_support.h"

using namespace aurora_sweep;
using aurora_control::LawType;

namespace {

// Every thread of a launch of blocks of `block` threads over [first, first + n),
// as the GPU would run them; `grid` may hold only the chunk's rows of a design.
template <LawType Law, int Capacity>
std::vector<SimResult> launchOnHost(const SweepSpec& spec, const GridView& grid, long first, long n, int block) {
  const auto setup = makeSetup<aurora_sim::Ardrone2, double>(spec);
  std::vector<SimResult> out(static_cast<size_t>(n) + block);  // room a bad index would write into
  std::memset(out.data(), 0xAB, out.size() * sizeof(SimResult));
  const long blocks = blocksFor(n, block);
  for (long b = 0; b < blocks; ++b) {
    for (int t = 0; t < block; ++t) {
      sweepThread<aurora_control::ArdroneLaw<Law>, double, Capacity>(setup, grid, first, n, out.data(), static_cast<unsigned>(b),
                                         static_cast<unsigned>(block), static_cast<unsigned>(t));
    }
  }
  for (size_t i = static_cast<size_t>(n); i < out.size(); ++i) {
    const unsigned char* bytes = reinterpret_cast<const unsigned char*>(&out[i]);
    for (size_t k = 0; k < sizeof(SimResult); ++k) EXPECT_EQ(bytes[k], 0xAB) << "a thread wrote past n at " << i;
  }
  out.resize(static_cast<size_t>(n));
  return out;
}

std::vector<SimResult> scalarRange(SweepSpec spec, long first, long n) {
  spec.range_begin = first;
  spec.range_end = first + n;
  std::vector<SimResult> out;
  Progress progress{0};
  runScalar(spec, out, progress);
  return out;
}

void expectSameBytes(const std::vector<SimResult>& a, const std::vector<SimResult>& b) {
  ASSERT_EQ(a.size(), b.size());
  for (size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(std::memcmp(&a[i], &b[i], sizeof(SimResult)), 0) << "combination " << i;
  }
}

}  // namespace

// An odd count from an offset, with a last partial block.
TEST(KernelEntry, EveryThreadOfALaunchWithAnOffset) {
  const SweepSpec spec = loadSweepFile(test::dataDir() + "/small_grid.yaml", test::configDir());
  const long first = 7, n = 37;
  aurora_control::withHistoryCapacity(spec.max_delay, [&](auto capacity) {
    const auto gpu = launchOnHost<LawType::kPdSaturated, decltype(capacity)::value>(spec, spec.view(), first, n, 8);
    expectSameBytes(gpu, scalarRange(spec, first, n));
  });
}

// A design's rows: the device holds only the chunk's rows (points_first).
TEST(KernelEntry, AChunkOfADesignFromItsOwnRowsOnly) {
  const SweepSpec spec = test::study13(256);
  const long first = 101, n = 53;
  GridView chunk = spec.view();
  const size_t cols = static_cast<size_t>(chunk.point_cols);
  const std::vector<double> rows(spec.points.begin() + first * cols, spec.points.begin() + (first + n) * cols);
  chunk.points = rows.data();
  chunk.points_first = first;
  aurora_control::withHistoryCapacity(spec.max_delay, [&](auto capacity) {
    const auto gpu = launchOnHost<LawType::kUnderactuated, decltype(capacity)::value>(spec, chunk, first, n, 32);
    expectSameBytes(gpu, scalarRange(spec, first, n));
  });
}

// Indices above 2^32 (a 10^13 grid): 64-bit arithmetic from block to index.
TEST(KernelEntry, OffsetsAboveTwoToTheThirtyTwo) {
  const SweepSpec spec = loadSweepFile(test::writeTemp("huge_entry.yaml",
      "sweep:\n  parameters:\n    kp: {from: 0.1, to: 1, count: 100000}\n    kd: {from: 0.1, to: 1, count: 100000}\n"
      "    delay: {values: [0, 3, 9]}\n"), test::configDir());
  const long first = (1L << 32) + 3, n = 5;
  aurora_control::withHistoryCapacity(spec.max_delay, [&](auto capacity) {
    const auto gpu = launchOnHost<LawType::kPdSaturated, decltype(capacity)::value>(spec, spec.view(), first, n, 4);
    expectSameBytes(gpu, scalarRange(spec, first, n));
  });
  const Combination c = spec.view().decode(first + 4);
  EXPECT_EQ(c.v[kParamKp], spec.axes[0].values[(first + 4) % 100000]);
  EXPECT_EQ(c.v[kParamKd], spec.axes[1].values[((first + 4) / 100000) % 100000]);
}

// Every byte of a result is defined (the padding is a zeroed field): two
// runs give identical chunk bytes.
TEST(KernelEntry, ResultsHaveNoUndefinedBytes) {
  const SweepSpec spec = loadSweepFile(test::dataDir() + "/small_grid.yaml", test::configDir());
  const auto a = scalarRange(spec, 0, spec.size());
  const auto b = test::runOn("cpu", spec);
  for (const SimResult& r : a) {
    for (unsigned char z : r.zero) EXPECT_EQ(z, 0);
  }
  for (const SimResult& r : b) {
    for (unsigned char z : r.zero) EXPECT_EQ(z, 0);
  }
}
