// One instruction set's build of the SIMD engine. CMakeLists compiles this
// file once per set, each time with AURORA_ISA (the entry namespace),
// AURORA_ISA_ARCH (the xsimd architecture) and that set's compiler flags,
// into a shared library that exports only the entry points below.
#include "batch_engine.h"
#include "batch_isa.h"

#define AURORA_CONCAT2(a, b) a##b
#define AURORA_CONCAT(a, b) AURORA_CONCAT2(a, b)

namespace aurora_sweep {
namespace AURORA_CONCAT(isa_, AURORA_ISA) {

void run(const SweepSpec& spec, int threads, std::vector<SimResult>& out, Progress& p) {
  runBatchArch<AURORA_ISA_ARCH>(spec, threads, out, p);
}

int lanes(Precision precision) { return batchLanes<AURORA_ISA_ARCH>(precision); }

const char* name() { return AURORA_ISA_ARCH::name(); }

}  // namespace isa_
}  // namespace aurora_sweep
