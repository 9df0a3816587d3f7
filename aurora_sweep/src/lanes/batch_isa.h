// Entry points of the per-instruction-set builds of the SIMD engine
// (batch_isa.cpp, one shared library each). Only these symbols leave a
// library (batch_isa.map); cpu_dispatch.cpp calls the one the CPU runs.
#pragma once

#include <vector>

#include "aurora_sweep/backends.h"

// The libraries are compiled with hidden visibility (direct calls inside, no
// interposition): the entry points say they are exported.
#define AURORA_SWEEP_ISA_API __attribute__((visibility("default")))
#define AURORA_SWEEP_DECLARE_ISA(ns)                                                  \
  namespace aurora_sweep {                                                            \
  namespace isa_##ns {                                                                \
  AURORA_SWEEP_ISA_API void run(const SweepSpec& spec, int threads,                   \
                                std::vector<SimResult>& out, Progress& p);            \
  AURORA_SWEEP_ISA_API int lanes(Precision precision);                                \
  AURORA_SWEEP_ISA_API const char* name();                                            \
  }                                                                                   \
  }

AURORA_SWEEP_DECLARE_ISA(sse4_2)
AURORA_SWEEP_DECLARE_ISA(avx2)
AURORA_SWEEP_DECLARE_ISA(avx512)
AURORA_SWEEP_DECLARE_ISA(native)

namespace aurora_sweep {
// threaded_backend.cpp: the scalar body on all cores, no SIMD lanes (the
// fallback where no engine build runs, or AURORA_SWEEP_SIMD=none).
void runThreadedScalar(const SweepSpec& spec, int threads, std::vector<SimResult>& out,
                       Progress& progress);
}  // namespace aurora_sweep
